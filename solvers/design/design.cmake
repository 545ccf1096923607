# Fixture design (solvers/design): the search, and its MPI distribution when MPI is found (optional:
# -DCONTACTCERT_MPI=OFF, or no MPI installed, builds the serial distributor only).
target_sources(contactcert_solvers PRIVATE design/candidates.cpp design/problem.cpp design/symmetry.cpp
  design/evaluate.cpp design/ranking.cpp design/checkpoint.cpp design/distribute_serial.cpp
  design/goal_certificate.cpp design/goal_certificate_check.cpp)
option(CONTACTCERT_MPI "Build the MPI distribution of contactcert design (if MPI is found)" ON)
if(CONTACTCERT_MPI)
  find_package(MPI COMPONENTS CXX QUIET)
endif()
if(CONTACTCERT_MPI AND MPI_CXX_FOUND)
  message(STATUS "contactcert design: MPI distribution enabled (${MPI_CXX_LIBRARY_VERSION_STRING})")
  target_sources(contactcert_solvers PRIVATE design/distribute_mpi.cpp)
  target_link_libraries(contactcert_solvers PRIVATE MPI::MPI_CXX)
  target_compile_definitions(contactcert_solvers PRIVATE CONTACTCERT_HAVE_MPI)
  set(CONTACTCERT_HAVE_MPI ON CACHE INTERNAL "MPI found for contactcert design")
else()
  message(STATUS "contactcert design: serial only (MPI not found or CONTACTCERT_MPI=OFF)")
  set(CONTACTCERT_HAVE_MPI OFF CACHE INTERNAL "MPI found for contactcert design")
endif()
