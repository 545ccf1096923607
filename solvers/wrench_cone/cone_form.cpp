#include "solvers/wrench_cone/cone_form.h"

#include "exact/ladder_numbers.h"

namespace contactcert::solvers {
namespace {

/// What Table 2 says about each of the 4n elements of y = (a_n, a_t, c_n, c_t), and the friction
/// coefficient that multiplies c_n in the R or S substitution.
struct YConstraints {
  Eigen::Index n = 0;
  std::vector<SignConstraint> sign;        ///< 4n; c_t entries: kFree when R or S handles them
  std::vector<FrictionConstraint> friction;  ///< n
  std::vector<Q> mu;                        ///< n: mu_s for the static cone, mu_k for sliding
  bool unconstrained(Eigen::Index j) const { return j < 2 * n && sign[static_cast<std::size_t>(j)] == SignConstraint::kFree; }
  bool eliminated(Eigen::Index j) const {  // the set V of section 5.5
    if (j < 2 * n) return sign[static_cast<std::size_t>(j)] == SignConstraint::kFree || sign[static_cast<std::size_t>(j)] == SignConstraint::kZero;
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

std::string fixel_name(Eigen::Index i) { return std::to_string(i + 1); }

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
      case FrictionConstraint::kLeftEdge: m.S(ct, cn) = -mu; break;
      case FrictionConstraint::kRightEdge: m.S(ct, cn) = mu; break;
      case FrictionConstraint::kZero: break;
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
  const Eigen::Index n = y.n, n2 = 2 * n, n4 = 4 * n;
  std::vector<Eigen::Index> rows;
  for (Eigen::Index j = 0; j < n2; ++j)
    if (!y.unconstrained(j)) rows.push_back(j);
  const auto m = static_cast<Eigen::Index>(rows.size());
  ConeForm<T> out;
  // eq. (17): P = E B.
  out.P.resize(m, 3);
  for (Eigen::Index r = 0; r < m; ++r) out.P.row(r) = model.B.row(rows[static_cast<std::size_t>(r)]);
  // eq. (15): K = E C N R S V, column by column, written in place. C = [I  -A] (eq. 8).
  Eigen::Index columns = 0;
  for (Eigen::Index j = 0; j < n4; ++j) columns += y.eliminated(j) ? 0 : 1;
  out.K = Mat<T>::Zero(m, columns);
  T scratch;
  // K(:, c) = C(:, 2n + i) + coef * C(:, 3n + i) on the kept rows.
  auto force_column = [&](Eigen::Index c, Eigen::Index i, const T& coef) {
    for (Eigen::Index r = 0; r < m; ++r) {
      const Eigen::Index row = rows[static_cast<std::size_t>(r)];
      T& k = out.K(r, c);
      k = -model.A(row, i);
      if (!exact::is_zero(coef)) {
        scratch = coef * model.A(row, n + i);
        k -= scratch;
      }
    }
  };
  Eigen::Index c = 0;
  for (Eigen::Index j = 0; j < n4; ++j) {
    if (y.eliminated(j)) continue;
    if (j < n2) {
      const SignConstraint s = y.sign[static_cast<std::size_t>(j)];
      for (Eigen::Index r = 0; r < m; ++r)
        if (rows[static_cast<std::size_t>(r)] == j) out.K(r, c) = s == SignConstraint::kNegative ? T(-1) : T(1);
      out.strict.push_back(s == SignConstraint::kPositive || s == SignConstraint::kNegative);
      out.acceleration.push_back(true);
      out.names.push_back(std::string(s == SignConstraint::kNegative ? "-a" : "a") + fixel_name(j % n) + (j < n ? "n" : "t"));
      ++c;
      continue;
    }
    const Eigen::Index i = (j - n2) % n;
    const FrictionConstraint f = y.friction[static_cast<std::size_t>(i)];
    const T mu = from_exact<T>(y.mu[static_cast<std::size_t>(i)]);
    T coef = T(0);
    std::string name = std::string("c") + fixel_name(i);
    if (j < 3 * n) {  // the c_n column, combined with c_t by R or S
      if (f == FrictionConstraint::kStaticCone || f == FrictionConstraint::kLeftEdge) {
        coef = -mu;
        name += "[n-mu t]";
      } else if (f == FrictionConstraint::kRightEdge) {
        coef = mu;
        name += "[n+mu t]";
      } else {
        name += "n";
      }
    } else {  // the c_t column of a static friction cone
      coef = mu;
      name += "[n+mu t]";
    }
    force_column(c++, i, coef);
    out.strict.push_back(false);
    out.acceleration.push_back(false);
    out.names.push_back(name);
  }
  return out;
}

#define CONTACTCERT_CONE_FORM_INSTANTIATE(T)                                                    \
  template ModeMatrices<T> mode_matrices<T>(const geometry::PlanarScene&, const ModeString&);   \
  template ConeForm<T> cone_form<T>(const geometry::PlanarScene&, const ContactModel<T>&, const ModeString&);
CONTACTCERT_CONE_FORM_INSTANTIATE(double)
CONTACTCERT_CONE_FORM_INSTANTIATE(Q)
CONTACTCERT_CONE_FORM_INSTANTIATE(exact::Mpfr)
CONTACTCERT_CONE_FORM_INSTANTIATE(exact::Interval)
#undef CONTACTCERT_CONE_FORM_INSTANTIATE

}  // namespace contactcert::solvers
