#include "solvers/ucp/certificate.h"

#include <nlohmann/json.hpp>

#include "exact/rational_text.h"
#include "solvers/ucp/integer_rows.h"

namespace contactcert::solvers::ucp {

namespace {
using Index = Eigen::Index;
using json = nlohmann::ordered_json;

/// Z^T u for Z's sparse rows, X's rows (build_X: row r of X.A is row r of Z, n = 2nc entries, then its v_t block
/// negated): the combination of P's left null vectors.
Vec<Q> z_transpose_times(const SparseRows& Z, Index n, const Vec<Q>& u) {
  Vec<Q> w = Vec<Q>::Zero(n);
  for (Index r = 0; r < Z.rows(); ++r) {
    const Q& ur = u(r);
    if (sgn(ur) == 0) continue;
    for (Index t = Z.begin(r); t < Z.end(r) && Z.col(t) < n; ++t) w(Z.col(t)) += ur * Q(Z.value(t));
  }
  return w;
}

}  // namespace

json integers_json(const std::vector<exact::Z>& v) {
  json a = json::array();
  for (const auto& z : v) a.push_back(z.get_str());
  return a;
}

json rationals_json(const Vec<Q>& v) {
  json a = json::array();
  for (Index i = 0; i < v.size(); ++i) a.push_back(exact::to_string(v(i)));
  return a;
}

json certificate_header(const std::string& kind, int format, const UcpProblem& problem,
                        const std::string& assembly_text) {
  json p = to_json(problem);
  json j;
  j["kind"] = kind;
  j["format"] = format;
  j["problem_sha256"] = exact::canonical_sha256(p);
  j["problem"] = std::move(p);
  if (!assembly_text.empty()) j["assembly"] = assembly_text;
  return j;
}

std::vector<exact::Z> written_farkas(const UcpProblem& problem, bool x_side, const Vec<Q>& u) {
  if (!problem.quasistatic) return exact::primitive(u);
  // build_Y scales row r of [C | -d] by y_factor[r] > 0; a Farkas vector u of the scaled rows is (y_factor[r] u_r)
  // for C.
  if (x_side) return exact::primitive(z_transpose_times(problem.rows().X.A, problem.quasistatic->P.rows(), u));
  const Vec<Q> y_scale = Eigen::Map<const Vec<Q>>(problem.rows().y_factor.data(), problem.rows().Y.rows());
  return exact::primitive(Vec<Q>(y_scale.cwiseProduct(u)));
}

std::string jammed_certificate(const UcpProblem& problem, const SearchResult<Q>& result,
                               const std::string& assembly_text) {
  json j = certificate_header("ucp_jammed", 2, problem, assembly_text);
  j["reason"] = result.reason;
  json nodes = json::array();
  for (const SearchNode<Q>& node : result.tree) {
    json n;
    if (!node.is_leaf()) {
      n["branch"] = node.branch;
      n["x_zero"] = node.child_x_zero;
      n["y_zero"] = node.child_y_zero;
    } else {
      n["empty"] = node.side == Side::kX ? "X" : "Y";
      n["farkas"] = integers_json(written_farkas(problem, node.side == Side::kX, node.farkas));
    }
    nodes.push_back(n);
  }
  j["nodes"] = nodes;
  return exact::json_text(j) + "\n";
}

std::string solvable_certificate(const UcpProblem& problem, const Vec<Q>& x, const Vec<Q>& y,
                                 const std::string& assembly_text) {
  json j = certificate_header("ucp_solvable", 2, problem, assembly_text);
  j["x"] = rationals_json(x);
  j["y"] = rationals_json(y);
  return exact::json_text(j, 1) + "\n";
}

bool is_ucp_certificate_kind(const std::string& kind) { return kind == "ucp_jammed" || kind == "ucp_solvable"; }

}  // namespace contactcert::solvers::ucp
