# Spatial contact (issue 34): modes of one body from rest in R^6 (its checker is checker/spatial_modes_check.h).
target_sources(contactcert_solvers PRIVATE spatial/spatial_modes.cpp spatial/spatial_modes_certificate.cpp)
# Its strong stability under a wrench (checker/spatial_stability_check.h).
target_sources(contactcert_solvers PRIVATE spatial/spatial_stability.cpp spatial/spatial_stability_certificate.cpp
                                           spatial/spatial_certificate_lines.cpp)
# The wrench cone of a spatial mode (6-D, both forms).
target_sources(contactcert_solvers PRIVATE spatial/spatial_cone.cpp)
# Its certificate (checker/spatial_cone_check.h).
target_sources(contactcert_solvers PRIVATE spatial/spatial_cone_certificate.cpp)
