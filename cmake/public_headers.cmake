# The C++ surface that `cmake --install` ships (docs/cpp.md). A public header is API: a consumer includes it as
# <contactcert/PATH>. A detail header is what public headers need but a consumer should not call: it is installed
# as <contactcert/detail/PATH>. Every other header is internal and not installed. The sets are closed: a public or
# detail header includes only public or detail headers, every detail header is reached from a public one, and
# contactcert.h includes every public header (checked by cmake/header_surface.cmake: ctest public_header_surface).
set(CONTACTCERT_PUBLIC_HEADERS
    contactcert.h
    # numbers, input, errors, budgets
    exact/number.h exact/rational_text.h exact/json_input.h exact/input_error.h exact/arith.h exact/deadline.h
    # scenes (SPEC section 3)
    geometry/workpiece.h geometry/contact_frame.h geometry/planar_scene.h geometry/scene_json.h
    # cones (SPEC section 4)
    geometry/span_cone.h geometry/face_cone.h geometry/nnc_cone.h geometry/double_description.h
    geometry/canonical.h geometry/set_ops.h geometry/cone_json.h
    # wrench cones (sections 2.3 and 5)
    solvers/wrench_cone/mode.h solvers/wrench_cone/wrench_cone.h solvers/wrench_cone/line_of_force.h
    solvers/wrench_cone/cone_certificate.h
    # stability (sections 7-8) and insertion (sections 8-9)
    solvers/stability/strong_stability.h solvers/stability/stable_region.h solvers/stability/strong_cones.h
    solvers/stability/margin.h solvers/stability/finger_push.h solvers/stability/contact_modes.h
    solvers/stability/world_forces.h solvers/stability/stability_certificate.h solvers/insertion/insertion.h
    # the quasistatic problem (Pang-Trinkle-Lo)
    solvers/ucp/problem.h solvers/ucp/solve.h solvers/ucp/generate.h solvers/ucp/certificate.h
    # the independent checkers of the certificates
    checker/stability_check.h checker/modes_check.h checker/cone_check.h checker/ucp_check.h)
set(CONTACTCERT_DETAIL_HEADERS
    exact/lp_problem.h exact/double_description.h
    exact/strict_feasibility.h exact/integer_system.h exact/int_matrix.h exact/fraction_free.h exact/float_ring.h
    exact/rational_vector.h
    geometry/projection.h geometry/sphere_arrangement.h
    solvers/wrench_cone/cone_form.h solvers/wrench_cone/contact_model.h
    solvers/stability/mode_tree.h solvers/stability/motion_system.h solvers/stability/reused_certificates.h
    solvers/ucp/integer_rows.h solvers/ucp/phases.h solvers/ucp/face_lp.h solvers/ucp/bilinear.h solvers/ucp/search.h
    solvers/ucp/float_check.h solvers/ucp/recovery.h
    geometry/number_names.h solvers/number_names.h checker/mode_letters.h)
