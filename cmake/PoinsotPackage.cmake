# The Debian package, made from a build folder by `cpack -G DEB` (scripts/test-install.sh shows the steps):
# everything `cmake --install` puts in place, under /usr: the tool, its man pages and bash completion, the
# library, headers and CMake package files, the Python module in the interpreter's dist-packages, and the
# examples in /usr/share/doc/poinsot/examples. Depends is computed by dpkg-shlibdeps from the binaries, plus
# the interpreter the module was built for and NumPy, which no binary links.
include(GNUInstallDirs)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples
        PATTERN CMakeLists.txt EXCLUDE PATTERN __pycache__ EXCLUDE)

set(POINSOT_PACKAGE_MAINTAINER "poinsot developers" CACHE STRING "Maintainer field of the Debian package")
set(CPACK_PACKAGE_NAME poinsot)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
    "A C++20 library, the command-line tool poinsot and a Python module for the rotation of rigid bodies: \
inertia from geometry and meshes, Euler's equations integrated exactly or with structure-preserving methods, \
the Lagrange multipliers of the rotation-matrix formulation, coupled bodies with joints.")
set(CPACK_PACKAGE_CONTACT "${POINSOT_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # poinsot_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
if(POINSOT_PYTHON_VERSION)  # set by python/CMakeLists.txt: the module is built for this interpreter only
  string(REPLACE "." ";" _py ${POINSOT_PYTHON_VERSION})
  list(GET _py 0 _py_major)
  list(GET _py 1 _py_minor)
  math(EXPR _py_next "${_py_minor} + 1")
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3 (>= ${POINSOT_PYTHON_VERSION}), python3 (<< ${_py_major}.${_py_next}), python3-numpy")
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3-matplotlib")  # poinsot run --plot, poinsot.plot
endif()
# To build C++ programs against the installed library (find_package(poinsot)): its dependencies' headers.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS
    "cmake, g++, libeigen3-dev, libfmt-dev, libassimp-dev, libtomlplusplus-dev, libboost-math-dev")
include(CPack)
