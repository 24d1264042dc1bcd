# What `cmake --install` puts under the prefix, the CMake package find_package(eomgen) reads, and the Debian
# package `cpack -G DEB` makes of the same files.
#   bin/eomgen, bin/eomgen-sim                    the generator and the simulator of the shipped models
#   include/eomgen/*.hpp                          the header-only runtime (eomgen run compiles against it)
#   lib/cmake/eomgen/                             eomgenConfig(Version).cmake, eomgenTargets.cmake, eomgen.cmake
#   share/doc/eomgen/, share/eomgen/{models,examples}/
include(CMakePackageConfigHelpers)
set(EOMGEN_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/eomgen")

install(TARGETS eomgen eomgen_runtime EXPORT eomgenTargets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(TARGET eomgen-sim)
  install(TARGETS eomgen-sim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(DIRECTORY runtime/eomgen DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp" PATTERN "*.cuh")
install(EXPORT eomgenTargets NAMESPACE eomgen:: DESTINATION ${EOMGEN_CMAKE_DIR})
configure_package_config_file(cmake/eomgenConfig.cmake.in "${CMAKE_CURRENT_BINARY_DIR}/eomgenConfig.cmake"
                              INSTALL_DESTINATION ${EOMGEN_CMAKE_DIR})
write_basic_package_version_file("${CMAKE_CURRENT_BINARY_DIR}/eomgenConfigVersion.cmake"
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/eomgenConfig.cmake" "${CMAKE_CURRENT_BINARY_DIR}/eomgenConfigVersion.cmake"
              cmake/eomgen.cmake
        DESTINATION ${EOMGEN_CMAKE_DIR})
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY models/ DESTINATION ${CMAKE_INSTALL_DATADIR}/eomgen/models FILES_MATCHING PATTERN "*.toml")
install(FILES examples/bead_on_hoop.toml examples/double_pendulum.toml examples/door_closing.cpp
              examples/door_sweep.cpp examples/python_tour.ipynb DESTINATION ${CMAKE_INSTALL_DATADIR}/eomgen/examples)

# cpack -G DEB (from the build directory): eomgen_<version>_<arch>.deb, installing under /usr. The shared
# libraries it needs (GiNaC, CLN, fmt, ...) come from dpkg-shlibdeps; Eigen and a C++ compiler because
# generated models, and `eomgen run`, compile against the installed runtime.
set(CPACK_PACKAGE_NAME eomgen)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "eomgen")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Lagrangian mechanics to equations of motion and fast C++")
string(CONCAT CPACK_PACKAGE_DESCRIPTION
       "eomgen derives Euler-Lagrange equations from a model file (coordinates, parameters, T and V or rigid "
       "bodies, constraints, forces) with GiNaC, prints them for people, emits CSE'd C++ that depends only on "
       "Eigen and a header-only runtime, integrates it, and checks hand derivations equation by equation.")
set(EOMGEN_DEB_MAINTAINER "eomgen developers <maintainer@eomgen.invalid>" CACHE STRING
    "The Debian package's Maintainer field (the default's .invalid says no address has been set)")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${EOMGEN_DEB_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libeigen3-dev (>= 3.4), g++")
# import eomgen (python/, where the build has it) needs NumPy: recommended, which apt installs by default, so that
# `python3 -c 'import eomgen'` works after `apt-get install ./eomgen_*.deb`; Solution.plot needs matplotlib.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3, python3-numpy")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "python3-matplotlib")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
include(CPack)
