// Certificates of the UCP verdicts (their independent checker, `contactcert check`: checker/ucp_check.h).
//
// A certificate is one JSON object with a top-level "kind" (other kinds, e.g. a stability certificate, can be
// added beside these): "ucp_jammed" or "ucp_solvable". Both embed the problem (SPEC section 2 form, exact
// strings) under "problem", so the file is self-contained.
//
// "ucp_jammed": "nodes" is a flat array (node 0 is the root, which fixes nothing). An internal node is
// {"branch": i, "x_zero": a, "y_zero": b}: child a adds x_i = 0, child b adds y_i = 0; every complementary
// pair satisfies one of the two, so the leaves cover all cases. A path splits each pair at most once (a second
// split would repeat a face) and each node is reached once. A leaf is {"empty": "X" | "Y", "farkas":
// [integers with gcd 1]} proving that the leaf's face of X or Y is empty:
//   - generic UCP, or side Y: u over the rows of A (Y: of C) with u^T A_j >= 0 for every column j not fixed
//     to 0 on that side and u^T b < 0 (Y: u^T d > 0, since C y = -d);
//   - quasistatic side X: w in R^{2nc} with w^T P = 0 (so w = Z^T u for the Z of section 2), (w_n, w_t, -w_t)_j
//     >= 0 for every free column j of (v_n, v_t^+, v_t^-), and w^T J_alpha theta_dot_alpha > 0.
// "ucp_solvable": "x" and "y" (exact strings) with x in X, y in Y, x^T y = 0.
#pragma once

#include <string>

#include "exact/json_input.h"
#include "solvers/ucp/search.h"

namespace contactcert::solvers::ucp {

/// The "ucp_jammed" certificate of a jammed search result (T = Q) as JSON text; with `assembly_text`, the problem
/// is that assembly's (`assembly --ucp`) and its text is embedded under "assembly" (the checker derives the
/// problem from it).
std::string jammed_certificate(const UcpProblem& problem, const SearchResult<Q>& result,
                               const std::string& assembly_text = "");
/// The "ucp_solvable" certificate of a complementary pair as JSON text (`assembly_text` as above).
std::string solvable_certificate(const UcpProblem& problem, const Vec<Q>& x, const Vec<Q>& y,
                                 const std::string& assembly_text = "");

/// The head of a certificate of a UCP problem: "kind", "format", "problem_sha256", "problem" and, given,
/// "assembly" (the certificates above, and motion_uniqueness: solvers/motion/uniqueness_certificate.h).
nlohmann::ordered_json certificate_header(const std::string& kind, int format, const UcpProblem& problem,
                                          const std::string& assembly_text);
/// A Farkas vector u of the face LP over X's (x_side) or Y's rows as a certificate states it: a quasistatic problem's
/// X side as w = Z^T u (independent of the choice of Z), its Y side over the rows of [C | -d] (build_Y's rows
/// unscaled); primitive integers.
std::vector<exact::Z> written_farkas(const UcpProblem& problem, bool x_side, const Vec<Q>& u);
/// Integers as JSON strings.
nlohmann::ordered_json integers_json(const std::vector<exact::Z>& v);
/// Exact numbers as JSON strings.
nlohmann::ordered_json rationals_json(const Vec<Q>& v);

/// True if `kind` names a UCP certificate.
bool is_ucp_certificate_kind(const std::string& kind);

}  // namespace contactcert::solvers::ucp
