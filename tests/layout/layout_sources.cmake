# The C++ files the layout checks read: every folder's code, its tests, the benchmarks,
# the examples and the Python bindings, relative to SOURCE_DIR, in `sources`.

file(GLOB_RECURSE sources RELATIVE ${SOURCE_DIR}
  ${SOURCE_DIR}/clipper/*.h ${SOURCE_DIR}/clipper/*.cpp
  ${SOURCE_DIR}/hsr/*.h ${SOURCE_DIR}/hsr/*.cpp
  ${SOURCE_DIR}/shadowgen/*.h ${SOURCE_DIR}/shadowgen/*.cpp
  ${SOURCE_DIR}/cli/*.h ${SOURCE_DIR}/cli/*.cpp
  ${SOURCE_DIR}/bench/*.h ${SOURCE_DIR}/bench/*.cpp
  ${SOURCE_DIR}/examples/*.h ${SOURCE_DIR}/examples/*.cpp
  ${SOURCE_DIR}/python/*.h ${SOURCE_DIR}/python/*.cpp
  ${SOURCE_DIR}/tests/*.h ${SOURCE_DIR}/tests/*.cpp)
