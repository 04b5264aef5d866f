# Fails when a library file is longer than 400 lines: a file that long holds more than
# one concept, and each concept wants a file of its own, named after it. Checked in the
# libraries' code, clipper/, hsr/, shadowgen/ and cli/, headers and sources alike;
# tests, benchmarks and examples are not libraries and may hold long tables of cases.
#
#   cmake -DSOURCE_DIR=<repository root> -P file_lengths.cmake

set(max_lines 400)

# Files over the limit that are yet to be split. Nothing else may pass the limit, and a
# file listed here that has come under it fails too, so that the list only shrinks.
set(waiting_to_split)

file(GLOB_RECURSE files RELATIVE ${SOURCE_DIR}
  ${SOURCE_DIR}/clipper/*.h ${SOURCE_DIR}/clipper/*.cpp
  ${SOURCE_DIR}/hsr/*.h ${SOURCE_DIR}/hsr/*.cpp
  ${SOURCE_DIR}/shadowgen/*.h ${SOURCE_DIR}/shadowgen/*.cpp
  ${SOURCE_DIR}/cli/*.h ${SOURCE_DIR}/cli/*.cpp)

set(violations "")
foreach(file IN LISTS files)
  file(READ ${SOURCE_DIR}/${file} text)
  string(REGEX REPLACE "[^\n]" "" newlines "${text}")
  string(LENGTH "${newlines}" lines)
  list(FIND waiting_to_split ${file} waiting)
  if(lines GREATER max_lines AND waiting EQUAL -1)
    list(APPEND violations "${file}: ${lines} lines, over ${max_lines}")
  elseif(NOT lines GREATER max_lines AND NOT waiting EQUAL -1)
    list(APPEND violations
         "${file}: ${lines} lines, under ${max_lines}: take it off the list of files waiting to be split")
  endif()
endforeach()

list(LENGTH files count)
if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "library files over ${max_lines} lines (split each by concept):\n  ${text}")
endif()
message(STATUS "${count} files checked: none over ${max_lines} lines but those waiting to be split")
