# The Debian package: `cpack -G DEB` in a build folder gives shadowgen_<version>_<arch>.deb
# with the command, the library, the headers, the CMake package and shadowgen.pc under
# /usr. Its Depends come from dpkg-shlibdeps (dpkg-dev) on the command's shared libraries,
# plus the -dev packages a program linking libshadowgen.a needs.
# The Python module, where built (python/), installs with COMPONENT python: one package
# holds every component, and then depends on the Python it was built for and NumPy.
# cpack packs what the build made, as `cmake --install` does, without building the whole
# tree (tests and benchmarks included) first: the install's files must be built before.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON CACHE BOOL "install and cpack do not build all first")
set(CPACK_PACKAGE_NAME shadowgen)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "shadowgen")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "exact polygon shadows (Atherton, Weiler and Greenberg 1978): command and C++ library")
string(CONCAT CPACK_PACKAGE_DESCRIPTION
    "shadowgen computes the lit regions of every face of a scene under every light, in the "
    "scene's own coordinates, and writes the shadowed database, area reports, OBJ, glTF and "
    "SVG output. The package holds the shadowgen command, the C++ library (headers, static "
    "library, CMake package and pkg-config file) and, where built, the Python module.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
set(CPACK_DEB_COMPONENT_INSTALL OFF)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "shadowgen maintainers <shadowgen@localhost>")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "libproj-dev, libopenmesh-dev, libembree-dev, libtinygltf-dev, libpng-dev, libtbb-dev, zlib1g-dev")
if(TARGET shadowgen_python)
  string(APPEND CPACK_DEBIAN_PACKAGE_DEPENDS ", ${SHADOWGEN_PYTHON_DEPENDS}")
endif()
include(CPack)
