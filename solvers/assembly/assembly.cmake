# Several bodies (issue 31): the assembly's rigid-body model, stability from rest (its independent checker is
# checker/assembly_check.h), and Pang-Trinkle-Lo's quasistatic problem for N bodies.
target_sources(contactcert_solvers PRIVATE assembly/assembly_system.cpp assembly/assembly_stability.cpp
                                           assembly/assembly_certificate_memory.cpp assembly/assembly_ucp.cpp
                                           assembly/assembly_certificate.cpp assembly/assembly_modes.cpp)
