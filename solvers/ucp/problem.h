// The quasistatic multi-rigid-body contact problem of Pang, Trinkle, Lo (1994) as input data (SPEC
// section 2), and its uncoupled complementarity problem (UCP): find (x, y) in X x Y with x^T y = 0.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "exact/json_input.h"
#include "exact/number.h"
#include "geometry/contact_frame.h"
#include "solvers/number_names.h"
#include "solvers/ucp/integer_rows.h"
#include "solvers/ucp/phases.h"

namespace contactcert::solvers::ucp {

/// A polyhedron in standard form {x >= 0 : A x = b}, the form the LP layer solves over.
template <class T>
struct StandardPolyhedron {
  Mat<T> A;
  Vec<T> b;
};

/// An uncoupled complementarity problem (section 3): polyhedra X and Y in R^n_+.
template <class T>
struct UcpInstance {
  StandardPolyhedron<T> X, Y;
  Eigen::Index n() const { return X.A.cols(); }
};

/// The quasistatic contact problem (section 2), exactly as read from a `"kind": "quasistatic"` file.
struct QuasistaticProblem {
  int nc = 0, nq = 0, ntheta = 0;
  Mat<Q> P;                ///< 2nc x (nq + |abar|): [W^T  J_abar]
  Mat<Q> Jn, Jt;           ///< nc x ntheta
  Vec<Q> theta_dot;        ///< ntheta; entries of joints in abar are 0 (unknown)
  std::vector<int> alpha;  ///< joints with given velocity, ascending
  std::vector<int> abar;   ///< joints with given effort, ascending (the columns of J_abar in P)
  Vec<Q> d;                ///< [0 (nc); g_obj (nq); (g_man - tau)_abar]
  Vec<Q> mu;               ///< nc friction coefficients, >= 0

  Mat<Q> Wn() const;  ///< nq x nc normal wrench matrix (from P's first nq columns)
  Mat<Q> Wt() const;  ///< nq x nc tangential wrench matrix
  Vec<Q> g_obj() const;
  /// J_alpha theta_dot_alpha (2nc): the velocity the position-controlled joints impose at the contacts.
  Vec<Q> J_alpha_theta_alpha() const;
};

/// X and Y as the integer rows they are built from (integer_rows.h).
struct IntegerUcp {
  IntegerPolyhedron X, Y;
  /// A quasistatic problem: row r of Y is y_factor[r] > 0 times row r of [C | -d] (build_Y); empty otherwise.
  std::vector<Q> y_factor;
  Eigen::Index n() const { return X.cols(); }
};

/// A UCP problem file: either a quasistatic problem (with its X and Y built as in section 2) or a
/// generic UCP (`"kind": "ucp"`, e.g. from the Proposition 2 reduction). X and Y are held as integer rows; the
/// dense rational form, which only the exact LPs take, is made from them on first use (once; copies share it).
struct UcpProblem {
  std::optional<QuasistaticProblem> quasistatic;
  std::string source;  ///< free text carried by generated files ("reduction: ...")

  const IntegerUcp& rows() const { return rows_; }
  /// X and Y as dense rationals.
  const UcpInstance<Q>& ucp() const;
  Eigen::Index n() const { return rows_.n(); }
  /// Sets X and Y from their integer rows.
  void set(IntegerUcp rows);
  /// Sets X and Y from rationals (a generic UCP): each row is scaled to integers once, u is kept as the dense form.
  void set(UcpInstance<Q> u);

 private:
  struct Dense {
    std::once_flag built;
    UcpInstance<Q> ucp;
  };
  IntegerUcp rows_;
  std::shared_ptr<Dense> dense_ = std::make_shared<Dense>();
};

/// Reads and validates a problem (SPEC section 2, or the generic `"kind": "ucp"` form); throws
/// exact::InputError naming the field. phases (optional): receives the seconds of reading (parse) and of
/// building X and Y (build). A `"kind": "quasistatic_scene"` problem takes its contact frames from `frames`: the
/// solvers' geometry::frame_of, or a certificate checker's own.
UcpProblem read_ucp_problem(const exact::JsonInput& in, UcpPhases* phases = nullptr,
                            geometry::FrameRule frames = geometry::frame_of);
/// Loads a problem file (the file's JSON parse counts as parse).
UcpProblem load_ucp_problem(const std::string& path, UcpPhases* phases = nullptr);

/// Validates a quasistatic problem built in memory (generators); throws exact::InputError.
void validate(const QuasistaticProblem& p, const std::string& file = "");

/// X = {(v_n, v_t^+, v_t^-) >= 0 : Z_n v_n + Z_t (v_t^+ - v_t^-) + Z J_alpha theta_dot_alpha = 0} with
/// Z spanning the left null space of P (Z a = 0 iff a = P b), computed in integers (section 2, integer_rows.h),
/// its rows primitive.
IntegerPolyhedron build_X(const QuasistaticProblem& p);
/// Y = {(c_n, s_t^+, s_t^-) >= 0 : C y + d = 0} (section 2), each row of [C | -d] scaled by a positive factor
/// (factor[r], if given) to primitive integers (the same set; smaller numbers for the LPs).
IntegerPolyhedron build_Y(const QuasistaticProblem& p, std::vector<Q>* factor = nullptr);
/// Both polyhedra, with Y's row factors.
IntegerUcp build_ucp(const QuasistaticProblem& p);

/// The problem as a JSON value in SPEC section 2 form (exact numbers as strings in lowest terms).
nlohmann::ordered_json to_json(const UcpProblem& p);
/// The same as a JSON text.
std::string to_json_text(const UcpProblem& p);

/// X and Y in the number type T (the float rungs), straight from the integer rows: each integer entry a of a row
/// over den = 1 is from_z(a), every other number q (b, and A's entries over den > 1) from_q(q), the numbers of
/// the dense rational form as T would convert them.
template <class T, class FromZ, class FromQ>
UcpInstance<T> convert(const IntegerUcp& u, FromZ from_z, FromQ from_q) {
  const T zero = from_z(exact::Z(0));
  const auto conv = [&](const IntegerPolyhedron& P) {
    StandardPolyhedron<T> R{Mat<T>::Constant(P.rows(), P.cols(), zero), Vec<T>(P.rows())};
    Q q;
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
      const exact::Z& den = P.den[static_cast<std::size_t>(i)];
      for (Eigen::Index t = P.A.begin(i); t < P.A.end(i); ++t) {
        if (den == 1) {
          R.A(i, P.A.col(t)) = from_z(P.A.value(t));
        } else {
          exact::ring::to_rational(P.A.value(t), den, q);
          R.A(i, P.A.col(t)) = from_q(q);
        }
      }
      R.b(i) = from_q(P.b(i));
    }
    return R;
  };
  return {conv(u.X), conv(u.Y)};
}
/// X and Y in doubles (each number rounded as Q::get_d rounds it).
UcpInstance<double> to_double(const IntegerUcp& u);
/// X and Y as dense rationals (A[i] / den[i]: the form the exact LPs take).
UcpInstance<Q> to_dense_rational(const IntegerUcp& u);

/// Per-row factors of X's and Y's rows from equilibrate (1 for a row left as it was).
struct RowFactors {
  std::vector<double> X, Y;
};

/// For a float T, whose sign test has an absolute tolerance: every row of [A | b] whose max-norm is outside
/// [2^-10, 2^10] is multiplied by the power of two f_i that brings it into [1/2, 1): exact in binary floats,
/// the same polyhedra. (X's rows come from the left null space of P and reach 1e9 on Data Set 4, where a
/// phase-1 residual of rounding size passed for infeasibility.) A Farkas vector y' of the scaled rows is
/// f_i y'_i for the rows as given.
template <class T>
RowFactors equilibrate(UcpInstance<T>& u) {
  const auto scale = [](StandardPolyhedron<T>& P) {
    std::vector<double> factor(static_cast<std::size_t>(P.A.rows()), 1.0);
    for (Eigen::Index i = 0; i < P.A.rows(); ++i) {
      double norm = std::abs(exact::NumberTraits<T>::to_double(P.b(i)));
      for (Eigen::Index j = 0; j < P.A.cols(); ++j)
        norm = std::max(norm, std::abs(exact::NumberTraits<T>::to_double(P.A(i, j))));
      if (norm == 0 || (norm >= 0x1p-10 && norm <= 0x1p10)) continue;
      int e;
      std::frexp(norm, &e);  // norm = m 2^e, m in [1/2, 1)
      factor[static_cast<std::size_t>(i)] = std::ldexp(1.0, -e);
      const T f(factor[static_cast<std::size_t>(i)]);
      P.A.row(i) *= f;
      P.b(i) *= f;
    }
    return factor;
  };
  RowFactors r;
  r.X = scale(u.X);
  r.Y = scale(u.Y);
  return r;
}

}  // namespace contactcert::solvers::ucp
