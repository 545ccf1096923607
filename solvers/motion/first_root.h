// The first time a gap closes during a step: the gap between a moving vertex and an edge is, up to a positive
// factor, a polynomial of degree <= 3 in the step's time (Cayley parameter u = omega tau / 2, linear in tau).
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "exact/number.h"

namespace contactcert::solvers::motion {

using exact::Q;

/// A root of a gap polynomial: tau exactly (exact), or, when the root is irrational, the rational tau < root
/// with the gap still > 0 (exact = false), the lower end of a bracket of width <= H 2^-bisections around it.
template <class T>
struct GapRoot {
  T tau;
  bool exact = true;
};

/// The first root tau in (0, H] of the polynomial g (coefficients low to high, g(0) > 0) at which accept(tau)
/// holds (e.g. the moving point lies on the edge's segment), or nullopt. Roots are isolated in order by Sturm
/// sequences and bisection; for T = Q a root is exact when it is a bisection point, the simplest rational of its
/// bracket, or a root of a quadratic with a square discriminant; else the bracket's lower end (the gap > 0).
/// For T = double the bracket's upper end (a float root, to H 2^-60).
template <class T>
std::optional<GapRoot<T>> first_gap_root(const std::vector<T>& g, const T& H,
                                         const std::function<bool(const T&)>& accept);

/// The rational with the smallest denominator (then numerator) in the open interval (a, b), 0 <= a < b.
Q simplest_between(const Q& a, const Q& b);

extern template std::optional<GapRoot<Q>> first_gap_root<Q>(const std::vector<Q>&, const Q&,
                                                            const std::function<bool(const Q&)>&);
extern template std::optional<GapRoot<double>> first_gap_root<double>(const std::vector<double>&, const double&,
                                                                      const std::function<bool(const double&)>&);

}  // namespace contactcert::solvers::motion
