#include "solvers/motion/first_root.h"

namespace contactcert::solvers::motion {
namespace {

constexpr int kBisections = 60;

template <class T>
using Poly = std::vector<T>;

template <class T>
void trim(Poly<T>& p) {
  while (!p.empty() && exact::is_zero(p.back())) p.pop_back();
}

template <class T>
T eval(const Poly<T>& p, const T& x) {
  T r(0);
  for (auto i = p.size(); i-- > 0;) r = r * x + p[i];
  return r;
}

/// True if g > 0 on [0, H] by the cheap bound g(tau) >= g_0 + sum_{i >= 1} min(0, g_i) H^i (0 <= tau <= H): most
/// candidate gaps of a step never come near closing, and this spares them the Sturm sequence.
template <class T>
bool positive_on(const Poly<T>& g, const T& H) {
  T bound = g[0], power(1);
  for (std::size_t i = 1; i < g.size(); ++i) {
    power *= H;
    if (exact::sign(g[i]) < 0) bound += g[i] * power;
  }
  return exact::sign(bound) > 0;
}

/// The remainder of a divided by b (deg b >= 0).
template <class T>
Poly<T> remainder(Poly<T> a, const Poly<T>& b) {
  while (a.size() >= b.size() && !a.empty()) {
    const T f = a.back() / b.back();
    const std::size_t shift = a.size() - b.size();
    for (std::size_t i = 0; i < b.size(); ++i) a[shift + i] -= f * b[i];
    a.pop_back();
    trim(a);
  }
  return a;
}

/// The Sturm sequence p0 = g, p1 = g', p_{k+1} = -rem(p_{k-1}, p_k).
template <class T>
std::vector<Poly<T>> sturm(const Poly<T>& g) {
  std::vector<Poly<T>> s{g};
  Poly<T> d;
  for (std::size_t i = 1; i < g.size(); ++i) d.push_back(T(static_cast<long>(i)) * g[i]);
  trim(d);
  while (!d.empty()) {
    s.push_back(d);
    Poly<T> r = remainder(s[s.size() - 2], d);
    for (T& c : r) c = -c;
    d = r;
  }
  return s;
}

/// Sign changes of the sequence at x (zeros skipped).
template <class T>
int changes(const std::vector<Poly<T>>& s, const T& x) {
  int n = 0, last = 0;
  for (const Poly<T>& p : s) {
    const int sg = exact::sign(eval(p, x));
    if (sg == 0) continue;
    if (last != 0 && sg != last) ++n;
    last = sg;
  }
  return n;
}

/// True if the root in the bracket (a, b] of g is recognised as a rational r (set), for T = Q.
bool exact_root(const Poly<Q>& g, const Q& a, const Q& b, Q& r) {
  if (sgn(eval(g, b)) == 0) return r = b, true;
  r = simplest_between(a, b);
  if (sgn(eval(g, r)) == 0) return true;
  if (g.size() != 3) return false;
  // a u^2 + b u + c with a square discriminant: both roots rational.
  const Q disc = g[1] * g[1] - 4 * g[2] * g[0];
  if (sgn(disc) < 0) return false;
  const exact::Z n = disc.get_num(), d = disc.get_den();
  if (!mpz_perfect_square_p(n.get_mpz_t()) || !mpz_perfect_square_p(d.get_mpz_t())) return false;
  const Q root_disc(exact::Z(sqrt(n)), exact::Z(sqrt(d)));
  for (const Q& cand : {Q((-g[1] - root_disc) / (2 * g[2])), Q((-g[1] + root_disc) / (2 * g[2]))})
    if (cand > a && cand <= b) return r = cand, true;
  return false;
}

}  // namespace

Q simplest_between(const Q& a, const Q& b) {
  exact::Z f;
  mpz_fdiv_q(f.get_mpz_t(), a.get_num_mpz_t(), a.get_den_mpz_t());
  if (Q(f + 1) < b) return Q(f + 1);
  // (a, b) lies in [f, f + 1]: f + 1 / (the simplest rational in (1 / (b - f), 1 / (a - f)))
  const Q lo = b - f, hi = a - f;
  if (sgn(hi) == 0) {
    exact::Z k;
    const Q inv = 1 / lo;
    mpz_fdiv_q(k.get_mpz_t(), inv.get_num_mpz_t(), inv.get_den_mpz_t());
    return Q(f) + Q(1) / Q(k + 1);
  }
  return Q(f) + Q(1) / simplest_between(1 / lo, 1 / hi);
}

template <class T>
std::optional<GapRoot<T>> first_gap_root(const std::vector<T>& g0, const T& H,
                                         const std::function<bool(const T&)>& accept) {
  Poly<T> g = g0;
  trim(g);
  if (g.size() < 2) return std::nullopt;  // a constant gap never closes
  if (positive_on(g, H)) return std::nullopt;
  const std::vector<Poly<T>> s = sturm(g);
  T lo(0);
  // Distinct roots in (a, b] = V(a) - V(b); take them in order.
  while (changes(s, lo) - changes(s, H) > 0) {
    T a = lo, b = H;
    for (int i = 0; i < kBisections; ++i) {
      const T m = (a + b) / T(2);
      if (changes(s, a) - changes(s, m) > 0)
        b = m;
      else
        a = m;
    }
    GapRoot<T> root{b, true};
    if constexpr (std::is_same_v<T, Q>) {
      Q r;
      root = exact_root(g, a, b, r) ? GapRoot<T>{r, true} : GapRoot<T>{a, false};
    }
    if (accept(root.tau)) return root;
    lo = b;
  }
  return std::nullopt;
}

template std::optional<GapRoot<Q>> first_gap_root<Q>(const std::vector<Q>&, const Q&,
                                                     const std::function<bool(const Q&)>&);
template std::optional<GapRoot<double>> first_gap_root<double>(const std::vector<double>&, const double&,
                                                               const std::function<bool(const double&)>&);

}  // namespace contactcert::solvers::motion
