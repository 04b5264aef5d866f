# Fails when a file includes a header from another folder's detail/.
#
# Libraries cannot do it at all (the source tree is not on their include path, see
# shadowgen_library in the top-level CMakeLists.txt); this check covers what sees the
# whole tree: the benchmarks, the examples, and the tests, where a folder's tests may
# include that folder's detail/ and nothing else's (tests/clipper and tests/fuzz test
# clipper/, tests/shadowgen/scene tests shadowgen/scene/, and so on).
#
#   cmake -DSOURCE_DIR=<repository root> -P detail_includes.cmake

include(${CMAKE_CURRENT_LIST_DIR}/layout_sources.cmake)

# The folder whose detail/ a file may include.
function(owner_of file out)
  if(file MATCHES "^tests/fuzz/")
    set(owner clipper)
  elseif(file MATCHES "^tests/(shadowgen/[a-z_]+)/")
    set(owner ${CMAKE_MATCH_1})
  elseif(file MATCHES "^tests/([a-z_]+)/")
    set(owner ${CMAKE_MATCH_1})
  elseif(file MATCHES "^(shadowgen/[a-z_]+)/")
    set(owner ${CMAKE_MATCH_1})
  elseif(file MATCHES "^([a-z_]+)/")
    set(owner ${CMAKE_MATCH_1})
  endif()
  set(${out} ${owner} PARENT_SCOPE)
endfunction()

set(violations "")
foreach(file IN LISTS sources)
  owner_of(${file} owner)
  file(STRINGS ${SOURCE_DIR}/${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]*)\".*" "\\1" header "${line}")
    if(header MATCHES "\\.\\./")
      list(APPEND violations "${file}: includes '${header}' by a relative path upwards")
    elseif(header MATCHES "^(.*)/detail/" AND NOT CMAKE_MATCH_1 STREQUAL owner)
      list(APPEND violations "${file}: includes '${header}', private to ${CMAKE_MATCH_1}/")
    endif()
  endforeach()
endforeach()

list(LENGTH sources count)
if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "includes of another folder's detail/:\n  ${text}")
endif()
message(STATUS "${count} files checked: no include of another folder's detail/")
