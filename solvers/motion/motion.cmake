# Quasistatic time-stepping of one body (issue 32): exact rigid motion, contacts found from geometry, the UCP of
# every step with its certificate, uniqueness of the motion, the float run compared with the exact one.
target_sources(contactcert_solvers PRIVATE motion/motion_scene.cpp motion/first_root.cpp motion/contacts.cpp
                                           motion/step_problem.cpp motion/uniqueness.cpp motion/uniqueness_certificate.cpp
                                           motion/keep_contacts.cpp motion/simulate.cpp motion/compare.cpp)
