# `cmake --install BUILD --prefix P`: the libraries and their headers as the CMake package contactcert
# (find_package(contactcert) gives contactcert::contactcert; docs/cpp.md), the CLI and the bundled scenes.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(CONTACTCERT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/contactcert)

install(TARGETS contactcert_lib contactcert_checker contactcert_solvers contactcert_geometry contactcert_exact
        EXPORT contactcertTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
# The public headers as <contactcert/PATH>, what they need as <contactcert/detail/PATH>, nothing else
# (cmake/public_headers.cmake); their includes rewritten to those names, so PREFIX/include is the one exported
# include directory (cmake/header_surface.cmake, docs/cpp.md).
if(IS_ABSOLUTE ${CMAKE_INSTALL_INCLUDEDIR})
  set(contactcert_includedir ${CMAKE_INSTALL_INCLUDEDIR})
else()
  set(contactcert_includedir "\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_INCLUDEDIR}")
endif()
install(CODE "cmake_policy(PUSH)
cmake_policy(VERSION 3.20)
include(\"${PROJECT_SOURCE_DIR}/cmake/header_surface.cmake\")
contactcert_install_headers(\"${PROJECT_SOURCE_DIR}\" \"${contactcert_includedir}\" contactcert_headers)
list(APPEND CMAKE_INSTALL_MANIFEST_FILES \${contactcert_headers})
cmake_policy(POP)")
install(EXPORT contactcertTargets NAMESPACE contactcert:: DESTINATION ${CONTACTCERT_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/contactcertConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/contactcertConfig.cmake INSTALL_DESTINATION ${CONTACTCERT_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/contactcertConfigVersion.cmake VERSION ${PROJECT_VERSION}
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/contactcertConfig.cmake ${PROJECT_BINARY_DIR}/contactcertConfigVersion.cmake
        DESTINATION ${CONTACTCERT_CMAKE_DIR})

install(TARGETS contactcert RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(TARGET contactcert_mpi)  # design's MPI distribution, loaded under mpirun
  install(TARGETS contactcert_mpi LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/contactcert)
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/contactcert/scenes)
