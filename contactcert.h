// contactcert's public C++ API in one include: <contactcert/contactcert.h> (docs/cpp.md). Scenes, cones, wrench
// cones, stability, insertion, the quasistatic problem, and the certificates with their independent checkers.
// The list of public headers is cmake/public_headers.cmake; this file includes exactly those.
#pragma once

// Numbers (Q), exact text and JSON input, typed errors, budgets.
#include "exact/arith.h"
#include "exact/deadline.h"
#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/number.h"
#include "exact/rational_text.h"

// Scenes (SPEC section 3).
#include "geometry/contact_frame.h"
#include "geometry/planar_scene.h"
#include "geometry/scene_json.h"
#include "geometry/workpiece.h"

// Cones in span, face and not-necessarily-closed form (SPEC section 4).
#include "geometry/canonical.h"
#include "geometry/cone_json.h"
#include "geometry/double_description.h"
#include "geometry/face_cone.h"
#include "geometry/nnc_cone.h"
#include "geometry/set_ops.h"
#include "geometry/span_cone.h"

// Wrench cones of augmented contact modes (wrench cone paper, sections 2.3 and 5) and their certificates.
#include "solvers/wrench_cone/cone_certificate.h"
#include "solvers/wrench_cone/line_of_force.h"
#include "solvers/wrench_cone/mode.h"
#include "solvers/wrench_cone/wrench_cone.h"

// Stability (sections 7-8), insertion (sections 8-9), their certificates.
#include "solvers/insertion/insertion.h"
#include "solvers/stability/contact_modes.h"
#include "solvers/stability/finger_push.h"
#include "solvers/stability/margin.h"
#include "solvers/stability/stability_certificate.h"
#include "solvers/stability/stable_region.h"
#include "solvers/stability/strong_cones.h"
#include "solvers/stability/strong_stability.h"
#include "solvers/stability/world_forces.h"

// The quasistatic problem of Pang, Trinkle and Lo: solving, generating, certificates and their checker.
#include "solvers/ucp/certificate.h"
#include "solvers/ucp/generate.h"
#include "solvers/ucp/problem.h"
#include "solvers/ucp/solve.h"

// The independent checkers of those certificates (`contactcert check`): the checker's own frames and rows.
#include "checker/cone_check.h"
#include "checker/modes_check.h"
#include "checker/stability_check.h"
#include "checker/ucp_check.h"
