# The window's include rule (docs/architecture.md, "Which folder may include which"), checked on
# the sources: cmake -DUI_DIR=<source>/ui -P IncludeRule.cmake fails naming every include that
# breaks it.
#
#   model                  includes no other folder of ui/
#   delegate               model
#   frame                  model, delegate: never the window, never a feature
#   main (the window)      model, delegate, frame: never a feature
#   a feature folder       model, delegate, frame: never the window, never another feature
#
# One file is the exception: ui/main/WindowFeatures.cpp, the list of the features, includes each.
# An include "X/Y.h" names a folder of ui/ only where ui/X/Y.h exists: "scope/ScopeRecording.h"
# in ui/scope is core's.
cmake_minimum_required(VERSION 3.16)
if(NOT UI_DIR OR NOT IS_DIRECTORY "${UI_DIR}")
    message(FATAL_ERROR "UI_DIR must name the ui/ folder of the sources")
endif()

set(features files edit monitor transfer compare scope plant journal)
set(allowed_model model)
set(allowed_delegate model delegate)
set(allowed_frame model delegate frame)
set(allowed_main model delegate frame main)
foreach(feature IN LISTS features)
    set(allowed_${feature} model delegate frame ${feature})
endforeach()
set(exceptions main/WindowFeatures.cpp)

set(folders model delegate frame main ${features})
set(violations "")
set(checked 0)
foreach(folder IN LISTS folders)
    file(GLOB_RECURSE sources RELATIVE "${UI_DIR}" "${UI_DIR}/${folder}/*.h"
        "${UI_DIR}/${folder}/*.cpp")
    foreach(source IN LISTS sources)
        if(source IN_LIST exceptions)
            continue()
        endif()
        math(EXPR checked "${checked} + 1")
        file(STRINGS "${UI_DIR}/${source}" includes
            REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<][^\">]+/[^\">]+[\">]")
        foreach(line IN LISTS includes)
            string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[\"<]([^\">]+)[\">].*$" "\\1"
                included "${line}")
            string(REGEX MATCH "^[^/]+" target "${included}")
            if(NOT EXISTS "${UI_DIR}/${included}" OR NOT target IN_LIST folders)
                continue()
            endif()
            if(NOT target IN_LIST allowed_${folder})
                list(JOIN allowed_${folder} ", " may)
                list(APPEND violations
                    "ui/${source} includes ${included} (${folder} may include ${may})")
            endif()
        endforeach()
    endforeach()
endforeach()

# Every folder of ui/ is in the rule: a new one is given its place in it, not left unchecked.
file(GLOB entries RELATIVE "${UI_DIR}" "${UI_DIR}/*")
foreach(entry IN LISTS entries)
    if(IS_DIRECTORY "${UI_DIR}/${entry}" AND NOT entry IN_LIST folders)
        list(APPEND violations "ui/${entry}/ has no place in the include rule")
    endif()
endforeach()

if(checked EQUAL 0)
    message(FATAL_ERROR "no sources found under ${UI_DIR}")
endif()
if(violations)
    list(JOIN violations "\n  " text)
    message(FATAL_ERROR "The include rule is broken:\n  ${text}")
endif()
message(STATUS "${checked} files of ui/ keep the include rule")
