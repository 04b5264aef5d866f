# Fails when a folder's private names are not in a namespace of its own: each folder's
# detail/ declares shadowgen::<folder>::detail (shadowgen::scene::detail for
# shadowgen/scene/, shadowgen::clipper::detail for clipper/), never the shared
# shadowgen::detail nor another folder's. Checked in the folders' code and their tests
# (tests/shadowgen/scene may open shadowgen::scene::detail to test it, and no other).
#
#   cmake -DSOURCE_DIR=<repository root> -P detail_namespaces.cmake

include(${CMAKE_CURRENT_LIST_DIR}/layout_sources.cmake)

# The folder whose detail namespace a file may open: shadowgen/<room>/ and its tests
# (tests/shadowgen/<room>/) the room's, clipper/, hsr/ and cli/ (and their tests) theirs.
function(owner_of file out)
  set(owner "")
  if(file MATCHES "^(tests/)?shadowgen/([a-z_]+)/")
    set(owner ${CMAKE_MATCH_2})
  elseif(file MATCHES "^tests/fuzz/")
    set(owner clipper)
  elseif(file MATCHES "^(tests/)?(clipper|hsr|cli)/")
    set(owner ${CMAKE_MATCH_2})
  endif()
  set(${out} "${owner}" PARENT_SCOPE)
endfunction()

set(violations "")
foreach(file IN LISTS sources)
  owner_of(${file} owner)
  file(STRINGS ${SOURCE_DIR}/${file} lines REGEX "^[ \t]*namespace[ \t]+[a-z_:]*detail")
  foreach(line IN LISTS lines)
    string(STRIP "${line}" line)
    if(line MATCHES "^namespace[ \t]+shadowgen::detail([^a-z_]|$)")
      list(APPEND violations
           "${file}: '${line}': the shared shadowgen::detail, not shadowgen::${owner}::detail")
    elseif(line MATCHES "^namespace[ \t]+(shadowgen::)?([a-z_]+)::detail"
           AND NOT CMAKE_MATCH_2 STREQUAL owner)
      list(APPEND violations "${file}: '${line}': ${CMAKE_MATCH_2}'s detail, in ${owner}'s file")
    endif()
  endforeach()
endforeach()

list(LENGTH sources count)
if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "detail namespaces not the folder's own:\n  ${text}")
endif()
message(STATUS "${count} files checked: every detail namespace is its folder's own")
