#include "solvers/ucp/problem.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <utility>

#include "exact/rational_text.h"
#include "solvers/ucp/integer_rows.h"
#include "solvers/ucp/scene_builder.h"

namespace contactcert::solvers::ucp {

using exact::InputError;
using exact::JsonInput;

namespace {

using Index = Eigen::Index;

QuasistaticProblem read_quasistatic(const JsonInput& in) {
  in.expect_keys({"kind", "nc", "nq", "ntheta", "P", "Jn", "Jt", "theta_dot", "alpha", "d", "mu", "source", "note"});
  QuasistaticProblem p;
  p.nc = static_cast<int>(in.at("nc").integer(1, 100000));
  p.nq = static_cast<int>(in.at("nq").integer(1, 100000));
  p.ntheta = static_cast<int>(in.at("ntheta").integer(0, 100000));
  const auto nc = static_cast<std::size_t>(p.nc), ntheta = static_cast<std::size_t>(p.ntheta);
  // alpha: 0-based joints with given velocity; default all joints.
  std::vector<bool> in_alpha(ntheta, false);
  if (auto a = in.find("alpha")) {
    for (const JsonInput& e : a->elements()) {
      const long j = e.integer(0, static_cast<long>(p.ntheta) - 1);
      if (in_alpha[static_cast<std::size_t>(j)]) e.fail("joint " + std::to_string(j) + " is listed twice in alpha");
      in_alpha[static_cast<std::size_t>(j)] = true;
    }
  } else {
    std::fill(in_alpha.begin(), in_alpha.end(), true);
  }
  for (int j = 0; j < p.ntheta; ++j) (in_alpha[static_cast<std::size_t>(j)] ? p.alpha : p.abar).push_back(j);
  const std::size_t m = static_cast<std::size_t>(p.nq) + p.abar.size();
  p.Jn = in.at("Jn").rational_matrix(nc, ntheta);
  p.Jt = in.at("Jt").rational_matrix(nc, ntheta);
  p.P = in.at("P").rational_matrix(2 * nc, m);
  // theta_dot: entries outside alpha are ignored and may be null.
  JsonInput td = in.at("theta_dot");
  if (td.size() != ntheta)
    td.fail("expected an array of " + std::to_string(ntheta) + " entries (ntheta), found " + std::to_string(td.size()));
  p.theta_dot = Vec<Q>::Zero(p.ntheta);
  for (int j : p.alpha) p.theta_dot(j) = td.at(static_cast<std::size_t>(j)).rational();
  for (int j : p.abar)
    if (!td.at(static_cast<std::size_t>(j)).is_null()) (void)td.at(static_cast<std::size_t>(j)).rational();
  p.d = in.at("d").rational_vector(nc + m);
  p.mu = in.at("mu").rational_vector(nc);
  for (std::size_t i = 0; i < nc; ++i)
    if (sgn(p.mu(static_cast<Index>(i))) < 0) in.at("mu").at(i).fail("expected a friction coefficient >= 0");
  for (std::size_t i = 0; i < nc; ++i)
    if (sgn(p.d(static_cast<Index>(i))) != 0)
      in.at("d").at(i).fail("expected 0: the first nc entries of d are the zero block of the friction rows");
  validate(p, in.file());
  return p;
}

StandardPolyhedron<Q> read_polyhedron(const JsonInput& in, std::size_t n) {
  in.expect_keys({"A", "b"});
  StandardPolyhedron<Q> P;
  JsonInput A = in.at("A");
  P.A = A.rational_matrix(A.size(), n);
  P.b = in.at("b").rational_vector(A.size());
  return P;
}

nlohmann::ordered_json to_json(const Mat<Q>& A) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (Index i = 0; i < A.rows(); ++i) {
    nlohmann::ordered_json r = nlohmann::ordered_json::array();
    for (Index j = 0; j < A.cols(); ++j) r.push_back(exact::to_string(A(i, j)));
    rows.push_back(std::move(r));
  }
  return rows;
}

nlohmann::ordered_json to_json(const Vec<Q>& v) {
  nlohmann::ordered_json r = nlohmann::ordered_json::array();
  for (Index i = 0; i < v.size(); ++i) r.push_back(exact::to_string(v(i)));
  return r;
}

}  // namespace

Mat<Q> QuasistaticProblem::Wn() const { return P.block(0, 0, nc, nq).transpose(); }
Mat<Q> QuasistaticProblem::Wt() const { return P.block(nc, 0, nc, nq).transpose(); }
Vec<Q> QuasistaticProblem::g_obj() const { return d.segment(nc, nq); }

Vec<Q> QuasistaticProblem::J_alpha_theta_alpha() const {
  // Sparse in J: only its non-zero entries in columns with a non-zero given velocity contribute.
  Vec<Q> h = Vec<Q>::Zero(2 * nc);
  for (int j : alpha) {
    if (sgn(theta_dot(j)) == 0) continue;
    for (Index i = 0; i < nc; ++i) {
      if (sgn(Jn(i, j)) != 0) h(i) += Jn(i, j) * theta_dot(j);
      if (sgn(Jt(i, j)) != 0) h(nc + i) += Jt(i, j) * theta_dot(j);
    }
  }
  return h;
}

void validate(const QuasistaticProblem& p, const std::string& file) {
  auto fail = [&](const std::string& path, const std::string& what) { throw InputError(file, path, what); };
  const Index m = p.nq + static_cast<Index>(p.abar.size());
  if (p.P.rows() != 2 * p.nc || p.P.cols() != m) fail("$.P", "expected a 2nc x (nq + |abar|) matrix");
  if (p.Jn.rows() != p.nc || p.Jn.cols() != p.ntheta) fail("$.Jn", "expected an nc x ntheta matrix");
  if (p.Jt.rows() != p.nc || p.Jt.cols() != p.ntheta) fail("$.Jt", "expected an nc x ntheta matrix");
  if (p.mu.size() != p.nc) fail("$.mu", "expected nc entries");
  if (p.d.size() != p.nc + m) fail("$.d", "expected nc + nq + |abar| entries");
  for (std::size_t k = 0; k < p.abar.size(); ++k) {
    const Index col = p.nq + static_cast<Index>(k);
    if (p.P.col(col).head(p.nc) != p.Jn.col(p.abar[k]) || p.P.col(col).tail(p.nc) != p.Jt.col(p.abar[k]))
      fail("$.P", "column " + std::to_string(col) + " (J_abar) must equal column " + std::to_string(p.abar[k]) +
                      " of [Jn; Jt] (joint " + std::to_string(p.abar[k]) + " is not in alpha)");
  }
  for (Index i = 0; i < p.nc; ++i)
    if (sgn(p.mu(i)) < 0) fail("$.mu[" + std::to_string(i) + "]", "expected a friction coefficient >= 0");
}

UcpProblem read_ucp_problem(const JsonInput& in, UcpPhases* phases, geometry::FrameRule frames) {
  double parse = 0, build = 0;
  UcpProblem out;
  {
    const PhaseTimer t(parse);
    const std::string kind = in.at("kind").string();
    if (kind == "quasistatic") {
      out.quasistatic = read_quasistatic(in);
    } else if (kind == "quasistatic_scene") {
      out.quasistatic = build_quasistatic_scene(in, frames);
    } else if (kind == "ucp") {
      in.expect_keys({"kind", "n", "X", "Y", "source", "note"});
      const auto n = static_cast<std::size_t>(in.at("n").integer(1, 100000));
      UcpInstance<Q> u;
      u.X = read_polyhedron(in.at("X"), n);
      u.Y = read_polyhedron(in.at("Y"), n);
      out.set(std::move(u));
    } else {
      in.at("kind").fail("expected \"quasistatic\", \"quasistatic_scene\" or \"ucp\", found " +
                         exact::quoted_excerpt(kind));
    }
    if (auto s = in.find("source")) out.source = s->string();
  }
  if (out.quasistatic) {
    const PhaseTimer t(build);
    out.set(build_ucp(*out.quasistatic));
  }
  if (phases) phases->parse += parse, phases->build += build;
  return out;
}

UcpProblem load_ucp_problem(const std::string& path, UcpPhases* phases) {
  double parse = 0;
  std::optional<JsonInput> in;
  {
    const PhaseTimer t(parse);
    in = JsonInput::load(path);
  }
  if (phases) phases->parse += parse;
  return read_ucp_problem(*in, phases);
}

IntegerPolyhedron build_X(const QuasistaticProblem& p) {
  // Section 2: Z a = 0 iff a = P b for some b. X.A = Z B with B x = [v_n; v_t^+ - v_t^-] for x = (v_n, v_t^+,
  // v_t^-): B only selects and negates columns, so row r of X.A is row r of Z with its v_t block repeated negated.
  // X.b = -Z h with h = J_alpha theta_alpha = hn / L (integers over one denominator): -(Z_r . hn) / L.
  const Index nc = p.nc;
  const SparseRows Z = left_null_rows(p.P);
  IntegerPolyhedron X{SparseRows(3 * nc), std::vector<exact::Z>(static_cast<std::size_t>(Z.rows()), exact::Z(1)),
                      Vec<Q>(Z.rows())};
  const Vec<Q> h = p.J_alpha_theta_alpha();
  std::vector<exact::Z> hn(static_cast<std::size_t>(h.size()));
  const exact::Z L = exact::ring::to_common_denominator<exact::Z>(
      h.size(), [&](Index i) -> const Q& { return h(i); }, hn.data());
  exact::Z dot;
  for (Index r = 0; r < Z.rows(); ++r) {
    X.A.add_row();
    dot = 0;
    for (Index t = Z.begin(r); t < Z.end(r); ++t) {
      const exact::Z& hc = hn[static_cast<std::size_t>(Z.col(t))];
      if (sgn(hc) != 0) mpz_submul(dot.get_mpz_t(), Z.value(t).get_mpz_t(), hc.get_mpz_t());
      X.A.push(Z.col(t), Z.value(t));
    }
    for (Index t = Z.begin(r); t < Z.end(r); ++t)
      if (Z.col(t) >= nc) X.A.push(Z.col(t) + nc, -Z.value(t));
    exact::ring::to_rational(dot, L, X.b(r));
  }
  return X;
}

IntegerPolyhedron build_Y(const QuasistaticProblem& p, std::vector<Q>* factor) {
  // The rows of [C | -d], sparse: C's friction rows [2U | -I | -I] (row i: 2 mu_i, -1, -1) and the rows
  // [Wn - Wt U | Wt | 0] over the columns k of P = [W^T  J_abar] (Wn^T, Wt^T stacked), (J_abar)^T likewise: column i of
  // Wn - Wt U is Wn_i - mu_i Wt_i (U = diag(mu)), no product with U. Each row is scaled to primitive integers.
  const Index nc = p.nc, nq = p.nq, na = static_cast<Index>(p.abar.size()), m = nc + nq + na;
  IntegerPolyhedron Y{SparseRows(3 * nc), std::vector<exact::Z>(static_cast<std::size_t>(m), exact::Z(1)), Vec<Q>(m)};
  if (factor) factor->resize(static_cast<std::size_t>(m));
  std::vector<Q> entries;
  std::vector<Index> cols;
  std::vector<const Q*> row;
  const Q minus_one(-1);
  for (Index r = 0; r < m; ++r) {
    entries.clear();
    entries.reserve(static_cast<std::size_t>(2 * nc + 1));
    if (r < nc) {
      cols = {r, nc + r, 2 * nc + r};
      entries = {2 * p.mu(r), minus_one, minus_one};
    } else {
      cols.clear();
      const Index k = r - nc;
      for (Index i = 0; i < nc; ++i) {  // column i: n - mu_i t
        const Q& n = p.P(i, k);
        const Q& t = p.P(nc + i, k);
        if (sgn(t) == 0 && sgn(n) == 0) continue;
        cols.push_back(i);
        entries.push_back(sgn(t) == 0 ? n : Q(n - t * p.mu(i)));
      }
      for (Index i = 0; i < nc; ++i)  // column nc + i: t
        if (sgn(p.P(nc + i, k)) != 0) {
          cols.push_back(nc + i);
          entries.push_back(p.P(nc + i, k));
        }
    }
    entries.push_back(-p.d(r));
    row.clear();
    for (const Q& e : entries) row.push_back(&e);
    std::vector<exact::Z> z = primitive_integers(row);
    Y.b(r) = Q(z.back());
    if (factor) {
      const auto first = std::find_if(entries.begin(), entries.end(), [](const Q& e) { return sgn(e) != 0; });
      (*factor)[static_cast<std::size_t>(r)] =
          first == entries.end() ? Q(1) : Q(z[static_cast<std::size_t>(first - entries.begin())]) / *first;
    }
    // Zero entries of C (n = mu_i t) are dropped after the scaling.
    Y.A.add_row();
    for (std::size_t e = 0; e < cols.size(); ++e)
      if (sgn(z[e]) != 0) Y.A.push(cols[e], std::move(z[e]));
  }
  return Y;
}

IntegerUcp build_ucp(const QuasistaticProblem& p) {
  IntegerUcp u;
  u.X = build_X(p);
  u.Y = build_Y(p, &u.y_factor);
  return u;
}

const UcpInstance<Q>& UcpProblem::ucp() const {
  std::call_once(dense_->built, [this] { dense_->ucp = to_dense_rational(rows_); });
  return dense_->ucp;
}

void UcpProblem::set(IntegerUcp rows) {
  rows_ = std::move(rows);
  dense_ = std::make_shared<Dense>();
}

void UcpProblem::set(UcpInstance<Q> u) {
  rows_ = {exact::rational_rows(u.X.A, u.X.b), exact::rational_rows(u.Y.A, u.Y.b), {}};
  dense_ = std::make_shared<Dense>();
  std::call_once(dense_->built, [&] { dense_->ucp = std::move(u); });
}

nlohmann::ordered_json to_json(const UcpProblem& u) {
  nlohmann::ordered_json j;
  if (u.quasistatic) {
    const QuasistaticProblem& p = *u.quasistatic;
    j["kind"] = "quasistatic";
    j["nc"] = p.nc;
    j["nq"] = p.nq;
    j["ntheta"] = p.ntheta;
    j["P"] = to_json(p.P);
    j["Jn"] = to_json(p.Jn);
    j["Jt"] = to_json(p.Jt);
    nlohmann::ordered_json td = nlohmann::ordered_json::array();
    std::vector<bool> in_alpha(static_cast<std::size_t>(p.ntheta), false);
    for (int a : p.alpha) in_alpha[static_cast<std::size_t>(a)] = true;
    for (int k = 0; k < p.ntheta; ++k)
      td.push_back(in_alpha[static_cast<std::size_t>(k)] ? nlohmann::ordered_json(exact::to_string(p.theta_dot(k)))
                                                         : nlohmann::ordered_json(nullptr));
    j["theta_dot"] = std::move(td);
    j["alpha"] = p.alpha;
    j["d"] = to_json(p.d);
    j["mu"] = to_json(p.mu);
  } else {
    j["kind"] = "ucp";
    j["n"] = u.n();
    j["X"] = {{"A", to_json(u.ucp().X.A)}, {"b", to_json(u.ucp().X.b)}};
    j["Y"] = {{"A", to_json(u.ucp().Y.A)}, {"b", to_json(u.ucp().Y.b)}};
  }
  if (!u.source.empty()) j["source"] = u.source;
  return j;
}

std::string to_json_text(const UcpProblem& u) { return to_json(u).dump(1) + "\n"; }

UcpInstance<double> to_double(const IntegerUcp& u) {
  return convert<double>(
      u, [](const exact::Z& z) { return z.get_d(); }, [](const Q& q) { return q.get_d(); });
}

UcpInstance<Q> to_dense_rational(const IntegerUcp& u) {
  return convert<Q>(
      u, [](const exact::Z& z) { return Q(z); }, [](const Q& q) { return q; });
}

}  // namespace contactcert::solvers::ucp
