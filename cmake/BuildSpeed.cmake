# What keeps a build quick on a small machine. None of it changes what is built or how it
# behaves; a fresh clone's first build and every build after it both gain.

# A compiler cache turns a second build of the same sources (another build directory, a fresh
# clone, a rebuild after switching branches) into look-ups. Precompiled headers differ between
# builds only in their time stamps and in macros the build keeps equal, which ccache must be
# told it may overlook, or it would compile everything that uses one.
find_program(DRIVEDESK_CCACHE ccache)
if(DRIVEDESK_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
    set(CMAKE_CXX_COMPILER_LAUNCHER "${CMAKE_COMMAND}" -E env
        CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
        "${DRIVEDESK_CCACHE}")
endif()

# Linking some ninety programs against static libraries is a good part of a build; GNU ld is
# the slowest linker there is. lld where it is installed, else gold (part of binutils).
include(CheckLinkerFlag)
foreach(linker lld gold)
    check_linker_flag(CXX "-fuse-ld=${linker}" DRIVEDESK_LINKER_${linker})
    if(DRIVEDESK_LINKER_${linker})
        add_link_options("-fuse-ld=${linker}")
        break()
    endif()
endforeach()

# A unity build compiles a library's files eight to a translation unit: Qt's headers, the
# templates they instantiate and the optimiser's set-up are paid once for eight files. A fresh
# tree builds in about two thirds of the time (docs/performance.md); a change to one file
# compiles its seven neighbours too, so the trees that are built again and again keep it off.
# Names in anonymous namespaces must not meet in one unit: give such helpers their file's
# words. tools/setup.sh and tools/test.sh turn it on; every other tree compiles file by file,
# which keeps each file's own includes honest.
option(DRIVEDESK_UNITY_BUILD "Compile eight source files to a translation unit" OFF)
if(DRIVEDESK_UNITY_BUILD)
    set(CMAKE_UNITY_BUILD ON)
    set(CMAKE_UNITY_BUILD_BATCH_SIZE 8)
endif()

# Line tables are what stack traces, sanitizer reports and profiles need. Full debug info costs
# a quarter of every compile and triples what the linker reads; ask for it when a debugger
# should see local variables.
option(DRIVEDESK_FULL_DEBUG_INFO "Full debug information (-g) instead of line tables (-g1)" OFF)
if(NOT DRIVEDESK_FULL_DEBUG_INFO AND CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    add_compile_options("$<$<CONFIG:Debug,RelWithDebInfo>:-g1>")
endif()

# Precompiled Qt headers: parsing Qt is most of what compiling one of our files costs. Four sets
# (core's libraries, the Widgets library, widget-free tests, Widgets tests), each compiled once
# in a library of its own that every target of its kind reuses.
set(DRIVEDESK_PCH_CORE <QByteArray> <QCoreApplication> <QFuture> <QHash> <QList> <QObject>
    <QString> <QStringList> <QTimer>)
set(DRIVEDESK_PCH_WIDGETS ${DRIVEDESK_PCH_CORE} <QAction> <QApplication> <QBoxLayout>
    <QComboBox> <QDialog> <QDialogButtonBox> <QFutureWatcher> <QHeaderView> <QLabel>
    <QLineEdit> <QMenu> <QPushButton> <QSettings> <QToolBar> <QTreeView> <QUndoStack>
    <QWidget>)
set(DRIVEDESK_PCH_TEST <QSignalSpy> <QTemporaryDir> <QTest>)

# A library that compiles nothing but one set of precompiled headers, for others to reuse.
# It links what gives the reusing targets their Qt macros (QtTest's headers test them).
function(drivedesk_pch_donor name)
    cmake_parse_arguments(D "" "" "LIBS;HEADERS" ${ARGN})
    add_library(${name} OBJECT "${PROJECT_SOURCE_DIR}/cmake/PchDonor.cpp")
    target_link_libraries(${name} PRIVATE ${D_LIBS})
    target_precompile_headers(${name} PRIVATE ${D_HEADERS})
endfunction()

# Every static library below `dir` reuses the donor's headers.
function(drivedesk_reuse_pch dir donor)
    get_property(targets DIRECTORY "${dir}" PROPERTY BUILDSYSTEM_TARGETS)
    foreach(target IN LISTS targets)
        get_target_property(type ${target} TYPE)
        if(type STREQUAL "STATIC_LIBRARY")
            target_precompile_headers(${target} REUSE_FROM ${donor})
        endif()
    endforeach()
    get_property(subdirectories DIRECTORY "${dir}" PROPERTY SUBDIRECTORIES)
    foreach(subdirectory IN LISTS subdirectories)
        drivedesk_reuse_pch("${subdirectory}" ${donor})
    endforeach()
endfunction()
