# Fixture design (solvers/design): the search, and its MPI distribution when MPI is found (optional:
# -DCONTACTCERT_MPI=OFF, or no MPI installed, builds the serial distributor only).
target_sources(contactcert_solvers PRIVATE design/candidates.cpp design/problem.cpp design/symmetry.cpp
  design/evaluate.cpp design/ranking.cpp design/checkpoint.cpp design/distribute_serial.cpp
  design/goal_certificate.cpp)
option(CONTACTCERT_MPI "Build the MPI distribution of contactcert design (if MPI is found)" ON)
if(CONTACTCERT_MPI)
  find_package(MPI COMPONENTS CXX QUIET)
endif()
if(CONTACTCERT_MPI AND MPI_CXX_FOUND)
  message(STATUS "contactcert design: MPI distribution enabled (${MPI_CXX_LIBRARY_VERSION_STRING})")
  # A module that make_distributor loads under mpirun only (MPI's libraries linked into the program cost every
  # command ~10 ms of start-up), built beside the executable and installed in LIBDIR/contactcert.
  add_library(contactcert_mpi MODULE design/distribute_mpi.cpp)
  target_include_directories(contactcert_mpi PRIVATE ${PROJECT_SOURCE_DIR})
  target_link_libraries(contactcert_mpi PRIVATE MPI::MPI_CXX)
  set_target_properties(contactcert_mpi PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/cli)
  set_source_files_properties(design/distribute_serial.cpp PROPERTIES COMPILE_DEFINITIONS
    "CONTACTCERT_HAVE_MPI;CONTACTCERT_MPI_MODULE=\"${CMAKE_INSTALL_LIBDIR}/contactcert/libcontactcert_mpi.so\"")
  target_link_libraries(contactcert_solvers PRIVATE ${CMAKE_DL_LIBS})
  set(CONTACTCERT_HAVE_MPI ON CACHE INTERNAL "MPI found for contactcert design")
else()
  message(STATUS "contactcert design: serial only (MPI not found or CONTACTCERT_MPI=OFF)")
  set(CONTACTCERT_HAVE_MPI OFF CACHE INTERNAL "MPI found for contactcert design")
endif()
