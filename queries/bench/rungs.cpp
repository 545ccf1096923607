#include "queries/bench/rungs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "solvers/scene_ladder.h"
#include "solvers/ucp/solve.h"

namespace contactcert::bench {

namespace {

using exact::Arith;
using exact::Mat;

/// v in the rung's number type (MPFR: at the working precision of the run, see run_rung).
template <class T>
Vec<T> from_q(const Vec<Q>& v) {
  return v.unaryExpr([](const Q& q) { return solvers::from_exact<T>(q); });
}

/// A number of the rung as a rational: exactly (every double and MPFR float is one), an interval by its midpoint.
Q as_rational(const Q& x) { return x; }
Q as_rational(double x) { return Q(x); }
Q as_rational(const exact::Mpfr& x) { return exact::to_rational(x); }
Q as_rational(const exact::Interval& x) { return exact::to_rational(x); }

template <class T>
Vec<Q> to_q(const Vec<T>& v) {
  return v.unaryExpr([](const T& x) { return as_rational(x); });
}

/// `contactcert ucp`'s default method: the bilinear algorithm, then the complete search (arith picks the path);
/// the problem read from its text and X and Y built first, as a user's run does.
template <class T>
Answer answer(const UcpQuestion& q, const Rung& rung) {
  solvers::ucp::UcpOptions o;
  o.arith = rung.arith;
  o.float_rung = rung.number;
  const solvers::ucp::UcpProblem problem = solvers::ucp::read_ucp_problem(exact::JsonInput::parse(q.text, "bench"));
  const solvers::ucp::UcpReport r = solvers::ucp::solve_ucp(problem, o);
  Answer a;
  a.verdict = solvers::ucp::status_name(r.status);
  if (r.status != solvers::ucp::UcpStatus::kSolvable) return a;
  if constexpr (std::is_same_v<T, Q>)
    a.x = r.x->to_q(), a.y = r.y->to_q();
  else if (r.x_float.size() > 0)  // MPFR, intervals: the pair as the rung computed it, not rounded to double
    a.x = r.x_float, a.y = r.y_float;
  else
    a.x = to_q(r.x_approx), a.y = to_q(r.y_approx);
  return a;
}

template <class T>
Answer answer(const StabilityQuestion& q, const Rung& rung) {
  const auto r = solvers::strong_stability<T>(q.scene, from_q<T>(q.wrench), {rung.arith});
  Answer a;
  a.verdict = solvers::verdict_name(r.verdict);
  if (r.has_resting) a.forces = to_q(r.resting_forces);
  return a;
}

/// Rows of M scaled to unit length (in double), appended to G.
template <class T>
void append_unit_rows(const Mat<T>& M, double sign, std::vector<Vec<double>>& G) {
  for (Eigen::Index r = 0; r < M.rows(); ++r) {
    Vec<double> v(M.cols());
    for (Eigen::Index c = 0; c < M.cols(); ++c) v(c) = sign * exact::NumberTraits<T>::to_double(M(r, c));
    if (v.norm() > 0) G.push_back(v / v.norm());
  }
}

/// The paper's route (F = K^F P, eq. 18). The cone layer has no float-proposal path yet, so the verified rung
/// computes the cone in rationals, as `contactcert cone --arith verified` does; the float rungs compute it
/// unchecked in their number type.
template <class T>
Answer answer(const ConeQuestion& q, const Rung&) {
  const auto c = solvers::wrench_cone<T>(q.scene, q.mode, solvers::Route::kPaper);
  Answer a;
  a.verdict = c.status == solvers::ConeStatus::kEmpty ? "empty" : "non_empty";
  if (c.status == solvers::ConeStatus::kEmpty) return a;
  std::vector<Vec<double>> G;
  append_unit_rows(c.cone.closure.rays, 1, G);
  append_unit_rows(c.cone.closure.lines, 1, G);
  append_unit_rows(c.cone.closure.lines, -1, G);
  a.generators = Mat<double>(static_cast<Eigen::Index>(G.size()), 3);
  for (std::size_t i = 0; i < G.size(); ++i) a.generators.row(static_cast<Eigen::Index>(i)) = G[i].transpose();
  return a;
}

double max_abs(const Vec<Q>& v) {
  Q m = 0;
  for (Eigen::Index i = 0; i < v.size(); ++i) m = std::max(m, Q(abs(v(i))));
  return m.get_d();
}

/// Largest violation of x in {x >= 0 : A x = b}, residual relative to max(1, |b|).
double violation(const solvers::ucp::StandardPolyhedron<Q>& P, const Vec<Q>& x) {
  if (x.size() != P.A.cols()) return std::numeric_limits<double>::infinity();
  double v = max_abs(Vec<Q>(P.A * x - P.b)) / std::max(1.0, max_abs(P.b));
  for (Eigen::Index j = 0; j < x.size(); ++j) v = std::max(v, -x(j).get_d());
  return v;
}

void measure_point(const UcpQuestion& q, const Answer& a, const Answer&, Errors& e) {
  if (a.x.size() == 0) return;
  e.violation = std::max(violation(q.problem.ucp().X, a.x), violation(q.problem.ucp().Y, a.y));
  e.xTy = std::abs(a.x.dot(a.y).get_d());
}

/// Resting forces in the frames of solvers::jacobian (those of MotionSystem::forces): J c + g = 0 (relative to
/// max(1, |g|)) and |c_t| <= mu_s c_n, c_n >= 0 (eq. 6 at rest, Table 2 'n').
void measure_point(const StabilityQuestion& q, const Answer& a, const Answer&, Errors& e) {
  if (a.forces.size() == 0) return;
  const geometry::PlanarScene scene = solvers::touching_scene(q.scene);
  const auto k = static_cast<Eigen::Index>(scene.fixels.size());
  if (a.forces.size() != 2 * k) {
    e.violation = std::numeric_limits<double>::infinity();
    return;
  }
  e.violation = max_abs(Vec<Q>(solvers::jacobian(scene) * a.forces + q.wrench)) / std::max(1.0, max_abs(q.wrench));
  for (Eigen::Index i = 0; i < k; ++i) {
    const Q& cn = a.forces(i);
    const Q over = abs(a.forces(k + i)) - scene.fixels[static_cast<std::size_t>(i)].mu_s * cn;
    e.violation = std::max({e.violation, -cn.get_d(), over.get_d()});
  }
}

/// Hausdorff distance between two sets of unit vectors (rows).
double hausdorff(const Mat<double>& A, const Mat<double>& B) {
  const auto directed = [](const Mat<double>& P, const Mat<double>& R) {
    double d = 0;
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
      double best = std::numeric_limits<double>::infinity();
      for (Eigen::Index j = 0; j < R.rows(); ++j) best = std::min(best, (P.row(i) - R.row(j)).norm());
      d = std::max(d, best);
    }
    return d;
  };
  return std::max(directed(A, B), directed(B, A));
}

void measure_point(const ConeQuestion&, const Answer& a, const Answer& x, Errors& e) {
  const bool a_empty = a.generators.rows() == 0, x_empty = x.generators.rows() == 0;
  e.generator_distance = a_empty && x_empty ? 0.0 : (a_empty || x_empty ? 2.0 : hausdorff(a.generators, x.generators));
}

bool decided(const std::string& verdict) { return verdict != "unknown" && verdict != "failed"; }

}  // namespace

const std::vector<Rung>& default_rungs() {
  static const std::vector<Rung> rungs = {
      {"float", Arith::kFloat, 53, {}},
      {"verified", Arith::kVerified, 0, {}},
      {"adaptive", Arith::kAdaptive, 0, {}},  // the precision ladder, checked exactly (docs/precision.md)
      {"exact", Arith::kExact, 0, {}}};
  return rungs;
}

const std::vector<Rung>& all_rungs() {
  using K = exact::Rung::Kind;
  static const std::vector<Rung> rungs = {{"float", Arith::kFloat, 53, {}},
                                          {"interval", Arith::kFloat, 53, {K::kInterval, 0}},
                                          {"mpfr113", Arith::kFloat, 113, {K::kMpfr, 113}},
                                          {"mpfr256", Arith::kFloat, 256, {K::kMpfr, 256}},
                                          {"mpfr1024", Arith::kFloat, 1024, {K::kMpfr, 1024}},
                                          {"verified", Arith::kVerified, 0, {}},
                                          {"adaptive", Arith::kAdaptive, 0, {}},
                                          {"exact", Arith::kExact, 0, {}}};
  return rungs;
}

std::vector<Rung> parse_rungs(const std::string& list) {
  std::vector<bool> chosen(all_rungs().size(), false);
  std::size_t begin = 0;
  while (begin <= list.size()) {
    const std::size_t end = std::min(list.find(',', begin), list.size());
    const std::string name = list.substr(begin, end - begin);
    const auto it = std::find_if(all_rungs().begin(), all_rungs().end(), [&](const Rung& r) { return r.name == name; });
    if (it == all_rungs().end()) throw std::invalid_argument("unknown rung \"" + name + "\"");
    chosen[static_cast<std::size_t>(it - all_rungs().begin())] = true;
    begin = end + 1;
  }
  chosen.back() = true;  // exact: the reference
  std::vector<Rung> out;
  for (std::size_t k = 0; k < chosen.size(); ++k)
    if (chosen[k]) out.push_back(all_rungs()[k]);
  return out;
}

Answer run_rung(const Question& question, const Rung& rung) {
  try {
    // Float rungs run unchecked in their number type (MPFR: the scene converted and every operation rounded
    // at the rung's bits); the checked rungs answer in rationals.
    using K = exact::Rung::Kind;
    return std::visit(
        [&](const auto& q) {
          switch (rung.arith == Arith::kFloat ? rung.number.kind : K::kExact) {
            case K::kInterval:
              return answer<exact::Interval>(q, rung);
            case K::kMpfr: {
              const exact::MpfrPrecision precision(rung.number.bits);
              return answer<exact::Mpfr>(q, rung);
            }
            case K::kDouble:
              return answer<double>(q, rung);
            case K::kExact:
              break;
          }
          return answer<Q>(q, rung);
        },
        question);
  } catch (const exact::UncertainSign&) {  // an interval run that could not prove a sign: undecided
    Answer a;
    a.verdict = "unknown";
    a.failure = "an interval sign is uncertain";
    return a;
  } catch (const std::exception& ex) {
    Answer a;
    a.verdict = "failed";
    a.failure = ex.what();
    return a;
  }
}

Errors measure(const Question& question, const Answer& answer, const Answer& exact_answer) {
  Errors e;
  e.undecided = !decided(answer.verdict) && decided(exact_answer.verdict);
  e.wrong_verdict = decided(answer.verdict) && decided(exact_answer.verdict) && answer.verdict != exact_answer.verdict;
  if (decided(answer.verdict)) std::visit([&](const auto& q) { measure_point(q, answer, exact_answer, e); }, question);
  return e;
}

double worst_error(const Errors& e) {
  if (e.wrong_verdict || e.undecided) return 1;
  double w = 0;
  for (double v : {e.violation, e.xTy, e.generator_distance}) {
    if (std::isinf(v)) return 1;
    if (!std::isnan(v)) w = std::max(w, v);
  }
  return w;
}

}  // namespace contactcert::bench
