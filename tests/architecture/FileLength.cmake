# Small files with one purpose: no source of the product (core/, ui/, app/) is longer than
# MAX_LINES lines. cmake -DSOURCE_DIR=<source> -DMAX_LINES=400 -P FileLength.cmake fails naming
# every file over it; a file that grows past it is split where it has two purposes.
cmake_minimum_required(VERSION 3.16)
if(NOT SOURCE_DIR OR NOT MAX_LINES)
    message(FATAL_ERROR "SOURCE_DIR and MAX_LINES must be given")
endif()

set(long "")
set(checked 0)
foreach(folder core ui app)
    file(GLOB_RECURSE sources RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/${folder}/*.h"
        "${SOURCE_DIR}/${folder}/*.cpp")
    foreach(source IN LISTS sources)
        math(EXPR checked "${checked} + 1")
        # Every line, empty ones too (file(STRINGS) would skip them).
        file(READ "${SOURCE_DIR}/${source}" text)
        string(REGEX MATCHALL "\n" newlines "${text}")
        list(LENGTH newlines lines)
        if(lines GREATER MAX_LINES)
            list(APPEND long "${source}: ${lines} lines")
        endif()
    endforeach()
endforeach()

if(checked EQUAL 0)
    message(FATAL_ERROR "no sources found under ${SOURCE_DIR}")
endif()
if(long)
    list(JOIN long "\n  " text)
    message(FATAL_ERROR "Longer than ${MAX_LINES} lines:\n  ${text}")
endif()
message(STATUS "${checked} files of the product, none over ${MAX_LINES} lines")
