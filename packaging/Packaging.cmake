# What a system install holds besides the programs, desktop entry and icons (app/, resources/):
# the man pages, the AppStream metadata, bash completion, the documents the man pages point to,
# and the Debian package CPack makes of it all (tools/package.sh).
include(GNUInstallDirs)

set(DRIVEDESK_MAINTAINER "The DriveDesk developers <drivedesk@users.noreply.github.com>")
set(drivedesk_packaging_dir ${PROJECT_BINARY_DIR}/packaging)
# The package's name, not the project's: CMAKE_INSTALL_DOCDIR would say share/doc/DriveDesk.
set(drivedesk_doc_dir ${CMAKE_INSTALL_DATADIR}/doc/drivedesk)

# The release the metadata and the changelog name is the project's version.
configure_file(${CMAKE_CURRENT_LIST_DIR}/io.github.drivedesk.DriveDesk.metainfo.xml.in
               ${drivedesk_packaging_dir}/io.github.drivedesk.DriveDesk.metainfo.xml @ONLY)
configure_file(${CMAKE_CURRENT_LIST_DIR}/changelog.in ${drivedesk_packaging_dir}/changelog @ONLY)
install(FILES ${drivedesk_packaging_dir}/io.github.drivedesk.DriveDesk.metainfo.xml
        DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)

# Debian wants man pages and changelogs compressed, reproducibly (-n: no name or time).
# Compressed at install time: the build itself makes nothing for packaging.
set(drivedesk_gzipped)
foreach(page drivedesk drivedesk-cli drivedesk-sim)
    list(APPEND drivedesk_gzipped
        "${CMAKE_CURRENT_LIST_DIR}/man/${page}.1" "${drivedesk_packaging_dir}/${page}.1.gz")
endforeach()
list(APPEND drivedesk_gzipped
    "${drivedesk_packaging_dir}/changelog" "${drivedesk_packaging_dir}/changelog.gz")
install(CODE "
    set(files \"${drivedesk_gzipped}\")
    while(files)
        list(POP_FRONT files source target)
        execute_process(COMMAND gzip -9nc \${source} OUTPUT_FILE \${target}
                        COMMAND_ERROR_IS_FATAL ANY)
    endwhile()
")
foreach(page drivedesk drivedesk-cli drivedesk-sim)
    install(FILES ${drivedesk_packaging_dir}/${page}.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
endforeach()

foreach(program drivedesk drivedesk-cli drivedesk-sim)
    install(FILES ${CMAKE_CURRENT_LIST_DIR}/completion/${program}
            DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)
endforeach()
install(FILES ${drivedesk_packaging_dir}/changelog.gz ${CMAKE_CURRENT_LIST_DIR}/copyright
              ${PROJECT_SOURCE_DIR}/docs/parameter-file.md ${PROJECT_SOURCE_DIR}/docs/plant.md
              ${PROJECT_SOURCE_DIR}/docs/simulated-drive.md ${PROJECT_SOURCE_DIR}/docs/journal.md
        DESTINATION ${drivedesk_doc_dir})

# The Debian package: drivedesk_<version>_amd64.deb.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME drivedesk)
set(CPACK_PACKAGE_VENDOR "The DriveDesk developers")
set(CPACK_PACKAGE_CONTACT "${DRIVEDESK_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION electronics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE https://github.com/drivedesk/drivedesk)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_DEBIAN_COMPRESSION_TYPE xz)
# After the summary line (CPACK_PACKAGE_DESCRIPTION_SUMMARY), which CPack puts first.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "\
DriveDesk configures KEB frequency inverters over a serial line or a
serial-to-Ethernet gateway, in KEB's protocols HSP5 and DIN66019II (with the
legacy DIN66019). It reads the drive's parameter groups and every parameter
with its limits, default, unit, scaling and plaintexts, and its values in
every set; edits them in place, backs the drive up to a parameter file and
downloads one to it, compares drives and files, and records the drive's
scope channels.

The package holds the window (drivedesk), the command line (drivedesk-cli)
and a simulated drive to try it all without hardware (drivedesk-sim).")
# The libraries the programs link come from dpkg-shlibdeps (Qt's, and libfftw3-double3 for the
# scope's spectrum; tools/package.sh checks they are there). What it cannot see: Qt loads its
# platform plugins (xcb) and its SQLite driver (the journal) at run time, and its own
# translations for the German texts; and `plant backup --commit`, `plant history` and `--at`
# run the git program.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins, libqt6sql6-sqlite, git")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "qt6-translations-l10n")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "bash-completion")
# The package is made from the build the tests ran in: `cpack` must not build everything first
# (its preinstall step would otherwise depend on `all`). tools/package.sh builds the programs.
# `make install` then installs what is built, as `cmake --install` always does.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)
include(CPack)
