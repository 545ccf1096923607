#include "solvers/wrench_cone/cone_form.h"

#include "exact/ladder_numbers.h"

namespace contactcert::solvers {
namespace {

/// What Table 2 says about each of the 4n elements of y = (a_n, a_t, c_n, c_t), and the friction
/// coefficient that multiplies c_n in the R or S substitution.
struct YConstraints {
  Eigen::Index n = 0;
  std::vector<SignConstraint> sign;          ///< 4n; c_t entries: kFree when R or S handles them
  std::vector<FrictionConstraint> friction;  ///< n
  std::vector<Q> mu;                         ///< n: mu_s for the static cone, mu_k for sliding
  bool unconstrained(Eigen::Index j) const {
    return j < 2 * n && sign[static_cast<std::size_t>(j)] == SignConstraint::kFree;
  }
  bool eliminated(Eigen::Index j) const {  // the set V of section 5.5
    if (j < 2 * n)
      return sign[static_cast<std::size_t>(j)] == SignConstraint::kFree ||
             sign[static_cast<std::size_t>(j)] == SignConstraint::kZero;
    if (j < 3 * n) return sign[static_cast<std::size_t>(j)] == SignConstraint::kZero;
    return friction[static_cast<std::size_t>(j - 3 * n)] != FrictionConstraint::kStaticCone;
  }
};

YConstraints classify(const geometry::PlanarScene& scene, const ModeString& mode) {
  YConstraints y;
  y.n = static_cast<Eigen::Index>(mode.letters.size());
  const auto n = static_cast<std::size_t>(y.n);
  y.sign.assign(4 * n, SignConstraint::kFree);
  y.friction.assign(n, FrictionConstraint::kZero);
  y.mu.assign(n, Q(0));
  for (std::size_t i = 0; i < n; ++i) {
    const geometry::Fixel& f = scene.fixels[i];
    const InteractionConstraints c = table2(mode.letters[i], f.frame.touching());
    y.sign[i] = c.a_n;
    y.sign[n + i] = c.a_t;
    y.sign[2 * n + i] = c.c_n;
    y.friction[i] = c.c_t;
    y.mu[i] = c.c_t == FrictionConstraint::kStaticCone ? f.mu_s : f.mu_k;
  }
  return y;
}

/// Fixel i in the names of z (c0n, a1t, ...): numbered from 0 like every report (docs/formats.md, Numbering).
std::string fixel_name(Eigen::Index i) { return std::to_string(i); }

/// One column of K (eq. 15): an acceleration y_j (sign -1 when N flips it) or the force column of
/// fixel i, C(:, 2n + i) + (coef_sign mu_i) C(:, 3n + i) after R and S.
struct KColumn {
  bool acceleration = false;
  Eigen::Index j = 0;  ///< the y index
  Eigen::Index i = 0;  ///< the fixel
  int sign = 1;        ///< acceleration: -1 for a negative variable
  int coef_sign = 0;   ///< force: the sign of mu_i's coefficient (0: a pure c_n column)
};

/// The rows kept by E (5.1) and the columns kept by V (5.5), in order.
void rows_and_columns(const YConstraints& y, std::vector<Eigen::Index>& rows, std::vector<KColumn>& cols) {
  const Eigen::Index n = y.n, n2 = 2 * n, n4 = 4 * n;
  for (Eigen::Index j = 0; j < n2; ++j)
    if (!y.unconstrained(j)) rows.push_back(j);
  for (Eigen::Index j = 0; j < n4; ++j) {
    if (y.eliminated(j)) continue;
    KColumn c;
    c.j = j;
    if (j < n2) {
      c.acceleration = true;
      c.i = j % n;
      c.sign = y.sign[static_cast<std::size_t>(j)] == SignConstraint::kNegative ? -1 : 1;
    } else {
      c.i = (j - n2) % n;
      const FrictionConstraint f = y.friction[static_cast<std::size_t>(c.i)];
      if (j >= 3 * n)  // the c_t column of a static friction cone
        c.coef_sign = 1;
      else if (f == FrictionConstraint::kStaticCone || f == FrictionConstraint::kLeftEdge)
        c.coef_sign = -1;
      else if (f == FrictionConstraint::kRightEdge)
        c.coef_sign = 1;
    }
    cols.push_back(c);
  }
}

}  // namespace

template <class T>
ModeMatrices<T> mode_matrices(const geometry::PlanarScene& scene, const ModeString& mode) {
  const YConstraints y = classify(scene, mode);
  const Eigen::Index n = y.n, n2 = 2 * n, n4 = 4 * n;
  ModeMatrices<T> m;
  // 5.1: E drops the rows of I_2n of unconstrained accelerations.
  std::vector<Eigen::Index> rows, cols;
  for (Eigen::Index j = 0; j < n2; ++j)
    if (!y.unconstrained(j)) rows.push_back(j);
  m.E = Mat<T>::Zero(static_cast<Eigen::Index>(rows.size()), n2);
  for (std::size_t r = 0; r < rows.size(); ++r) m.E(static_cast<Eigen::Index>(r), rows[r]) = T(1);
  // 5.2: N flips the sign of negative variables.
  m.N = Mat<T>::Identity(n4, n4);
  for (Eigen::Index j = 0; j < n2; ++j)
    if (y.sign[static_cast<std::size_t>(j)] == SignConstraint::kNegative) m.N(j, j) = T(-1);
  // 5.3 and 5.4: R for the static friction cone, S for the sliding edges. Friction opposes sliding
  // (Table 2): l has c_t = -mu_k c_n, r has c_t = mu_k c_n.
  m.R = Mat<T>::Identity(n4, n4);
  m.S = Mat<T>::Identity(n4, n4);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Index cn = 2 * n + i, ct = 3 * n + i;
    const T mu = from_exact<T>(y.mu[static_cast<std::size_t>(i)]);
    switch (y.friction[static_cast<std::size_t>(i)]) {
      case FrictionConstraint::kStaticCone:
        m.R(ct, ct) = mu;
        m.R(cn, ct) = T(1);
        m.R(ct, cn) = -mu;
        break;
      case FrictionConstraint::kLeftEdge:
        m.S(ct, cn) = -mu;
        break;
      case FrictionConstraint::kRightEdge:
        m.S(ct, cn) = mu;
        break;
      case FrictionConstraint::kZero:
        break;
    }
  }
  // 5.5: V drops the columns of zero, sliding c_t and unconstrained variables.
  for (Eigen::Index j = 0; j < n4; ++j)
    if (!y.eliminated(j)) cols.push_back(j);
  m.V = Mat<T>::Zero(n4, static_cast<Eigen::Index>(cols.size()));
  for (std::size_t c = 0; c < cols.size(); ++c) m.V(cols[c], static_cast<Eigen::Index>(c)) = T(1);
  return m;
}

template <class T>
ConeForm<T> cone_form(const geometry::PlanarScene& scene, const ContactModel<T>& model, const ModeString& mode) {
  const YConstraints y = classify(scene, mode);
  std::vector<Eigen::Index> rows;
  std::vector<KColumn> cols;
  rows_and_columns(y, rows, cols);
  const auto m = static_cast<Eigen::Index>(rows.size());
  const Mat<T> A = to_field<T>(model.A), B = to_field<T>(model.B);
  ConeForm<T> out;
  // eq. (17): P = E B.
  out.P.resize(m, 3);
  for (Eigen::Index r = 0; r < m; ++r) out.P.row(r) = B.row(rows[static_cast<std::size_t>(r)]);
  // eq. (15): K = E C N R S V, column by column. C = [I  -A] (eq. 8).
  out.K = Mat<T>::Zero(m, static_cast<Eigen::Index>(cols.size()));
  for (std::size_t c = 0; c < cols.size(); ++c) {
    const KColumn& col = cols[c];
    const auto ec = static_cast<Eigen::Index>(c);
    if (col.acceleration) {
      for (Eigen::Index r = 0; r < m; ++r)
        if (rows[static_cast<std::size_t>(r)] == col.j) out.K(r, ec) = T(col.sign);
      out.strict.push_back(y.sign[static_cast<std::size_t>(col.j)] == SignConstraint::kPositive || col.sign < 0);
      out.acceleration.push_back(true);
      out.names.push_back(std::string(col.sign < 0 ? "-a" : "a") + fixel_name(col.i) + (col.j < y.n ? "n" : "t"));
      out.fixel.push_back(col.i);
      out.t_per_n.push_back(Q(0));
      continue;
    }
    // K(:, c) = -A(:, i) - coef A(:, n + i) on the kept rows.
    const Q t_per_n(col.coef_sign * y.mu[static_cast<std::size_t>(col.i)]);
    const T coef = from_exact<T>(t_per_n);
    for (Eigen::Index r = 0; r < m; ++r) {
      const Eigen::Index row = rows[static_cast<std::size_t>(r)];
      T& k = out.K(r, ec);
      k = -A(row, col.i);
      if (col.coef_sign != 0) k -= T(coef * A(row, y.n + col.i));
    }
    out.strict.push_back(false);
    out.acceleration.push_back(false);
    std::string name = std::string("c") + fixel_name(col.i);
    name += col.coef_sign < 0 ? "[n-mu t]" : col.coef_sign > 0 ? "[n+mu t]" : "n";
    out.names.push_back(name);
    out.fixel.push_back(col.i);
    out.t_per_n.push_back(t_per_n);
  }
  return out;
}

Vec<Q> contact_forces(const ConeForm<Q>& form, const std::vector<Eigen::Index>& touching, const Vec<Q>& z) {
  const auto k = static_cast<Eigen::Index>(touching.size());
  Vec<Q> c = Vec<Q>::Zero(2 * k);
  for (Eigen::Index i = 0; i < k; ++i)
    for (std::size_t j = 0; j < form.fixel.size(); ++j) {
      if (form.acceleration[j] || form.fixel[j] != touching[static_cast<std::size_t>(i)]) continue;
      c(i) += z(static_cast<Eigen::Index>(j));
      c(k + i) += form.t_per_n[j] * z(static_cast<Eigen::Index>(j));
    }
  return c;
}

template <class R, class T>
RingForm<R> ring_form(const geometry::PlanarScene& scene, const ContactModel<T>& model, const ModeString& mode) {
  namespace rg = exact::ring;
  const YConstraints y = classify(scene, mode);
  std::vector<Eigen::Index> rows;
  std::vector<KColumn> cols;
  rows_and_columns(y, rows, cols);
  RingForm<R> out;
  out.k = static_cast<Eigen::Index>(cols.size());
  const auto w = static_cast<std::size_t>(out.d + out.k);
  out.rows = exact::IntMatrix<R>(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(w));
  // mu_i = p / q scales the force column of fixel i by q: -(q A(:, i) + coef_sign p A(:, n + i)).
  std::vector<R> p(static_cast<std::size_t>(y.n)), q(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) rg::from_rational(y.mu[i], p[i], q[i]);
  R a1, a2;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    R* row = out.rows.row(static_cast<Eigen::Index>(r));
    for (Eigen::Index j = 0; j < out.d; ++j)
      rg::get(model.B, rows[r], j, row[static_cast<std::size_t>(j)]);  // eq. (17)
    for (std::size_t c = 0; c < cols.size(); ++c) {
      const KColumn& col = cols[c];
      R& k = row[static_cast<std::size_t>(out.d) + c];
      if (col.acceleration) {
        if (rows[r] == col.j) rg::from_integer(long{col.sign}, k);
        continue;
      }
      const auto i = static_cast<std::size_t>(col.i);
      rg::get(model.A, rows[r], col.i, a1);
      if (col.coef_sign == 0) {
        k = -a1;
        continue;
      }
      rg::get(model.A, rows[r], y.n + col.i, a2);
      k = rg::sub(-rg::mul(q[i], a1), rg::mul(col.coef_sign > 0 ? p[i] : R(-p[i]), a2));
    }
    rg::normalize(row, static_cast<Eigen::Index>(w));
  }
  for (const KColumn& col : cols)
    out.strict.push_back(col.acceleration &&
                         (y.sign[static_cast<std::size_t>(col.j)] == SignConstraint::kPositive || col.sign < 0));
  return out;
}

#define CONTACTCERT_CONE_FORM_INSTANTIATE(T)                                                  \
  template ModeMatrices<T> mode_matrices<T>(const geometry::PlanarScene&, const ModeString&); \
  template ConeForm<T> cone_form<T>(const geometry::PlanarScene&, const ContactModel<T>&, const ModeString&);
CONTACTCERT_CONE_FORM_INSTANTIATE(double)
CONTACTCERT_CONE_FORM_INSTANTIATE(Q)
CONTACTCERT_CONE_FORM_INSTANTIATE(exact::Mpfr)
CONTACTCERT_CONE_FORM_INSTANTIATE(exact::Interval)
#undef CONTACTCERT_CONE_FORM_INSTANTIATE
template RingForm<double> ring_form<double, double>(const geometry::PlanarScene&, const ContactModel<double>&,
                                                    const ModeString&);
template RingForm<exact::Mpfr> ring_form<exact::Mpfr, exact::Mpfr>(const geometry::PlanarScene&,
                                                                   const ContactModel<exact::Mpfr>&, const ModeString&);
template RingForm<exact::Interval> ring_form<exact::Interval, exact::Interval>(const geometry::PlanarScene&,
                                                                               const ContactModel<exact::Interval>&,
                                                                               const ModeString&);
template RingForm<std::int64_t> ring_form<std::int64_t, Q>(const geometry::PlanarScene&, const ContactModel<Q>&,
                                                           const ModeString&);
template RingForm<exact::Z> ring_form<exact::Z, Q>(const geometry::PlanarScene&, const ContactModel<Q>&,
                                                   const ModeString&);

}  // namespace contactcert::solvers
