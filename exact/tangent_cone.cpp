#include "exact/tangent_cone.h"

#include <bit>
#include <cstdint>

#include "exact/field_ops.h"
#include "exact/interval_number.h"
#include "exact/mpfr_number.h"

namespace contactcert::exact {

namespace {

using Index = Eigen::Index;
using Bits = std::vector<std::uint64_t>;

template <class T>
struct Ray {
  std::vector<T> w;
  Bits zero;  // constraints tight at the ray: bit j < p for w_j >= 0, bit p + i for row i of G
};

void set(Bits& b, Index i) { b[static_cast<size_t>(i / 64)] |= std::uint64_t(1) << (i % 64); }

template <class T>
void scale_first_to_one(std::vector<T>& w) {
  for (const T& x : w) {
    if (exact::is_zero(x)) continue;
    const T inv = T(1) / (exact::sign(x) > 0 ? x : T(-x));
    for (T& y : w) mul_by(y, inv);
    return;
  }
}

}  // namespace

template <class T>
OrthantConeRays<T> orthant_cone_rays(const Mat<T>& G, long max_rays) {
  const Index p = G.cols(), k = G.rows();
  const size_t words = static_cast<size_t>((p + k + 63) / 64);
  std::vector<Ray<T>> rays;
  for (Index j = 0; j < p; ++j) {
    Ray<T> r{std::vector<T>(static_cast<size_t>(p), T(0)), Bits(words, 0)};
    r.w[static_cast<size_t>(j)] = T(1);
    for (Index l = 0; l < p; ++l)
      if (l != j) set(r.zero, l);
    rays.push_back(std::move(r));
  }
  OrthantConeRays<T> out;
  T tmp;
  Bits common(words);
  for (Index i = 0; i < k; ++i) {
    // Constraint g w <= 0: rays with g r > 0 leave; pairs (positive, negative) that are adjacent give new rays.
    std::vector<T> val(rays.size());
    std::vector<size_t> pos, neg;
    for (size_t a = 0; a < rays.size(); ++a) {
      T v = T(0);
      for (Index j = 0; j < p; ++j)
        if (!exact::is_zero(rays[a].w[static_cast<size_t>(j)]))
          sub_mul(v, T(-G(i, j)), rays[a].w[static_cast<size_t>(j)], tmp);
      const int s = exact::sign(v);
      if (s > 0) pos.push_back(a);
      if (s < 0) neg.push_back(a);
      if (s == 0) set(rays[a].zero, p + i);
      val[a] = v;
    }
    if (pos.empty()) continue;
    std::vector<Ray<T>> next;
    for (size_t a = 0; a < rays.size(); ++a)
      if (!exact::is_positive(val[a])) next.push_back(rays[a]);
    for (size_t a : pos) {
      for (size_t b : neg) {
        long count = 0;
        for (size_t w = 0; w < words; ++w) {
          common[w] = rays[a].zero[w] & rays[b].zero[w];
          count += std::popcount(common[w]);
        }
        if (count < p - 2) continue;
        bool adjacent = true;
        for (size_t c = 0; c < rays.size() && adjacent; ++c) {
          if (c == a || c == b) continue;
          bool contains = true;
          for (size_t w = 0; w < words && contains; ++w) contains = (rays[c].zero[w] & common[w]) == common[w];
          adjacent = !contains;
        }
        if (!adjacent) continue;
        // val_a * r_b - val_b * r_a has g . r = 0 and positive coefficients.
        Ray<T> r{std::vector<T>(static_cast<size_t>(p), T(0)), common};
        for (Index j = 0; j < p; ++j) {
          T& x = r.w[static_cast<size_t>(j)];
          if (!exact::is_zero(rays[b].w[static_cast<size_t>(j)]))
            sub_mul(x, T(-val[a]), rays[b].w[static_cast<size_t>(j)], tmp);
          if (!exact::is_zero(rays[a].w[static_cast<size_t>(j)]))
            sub_mul(x, val[b], rays[a].w[static_cast<size_t>(j)], tmp);
          if (exact::is_zero(x)) x = T(0);
        }
        scale_first_to_one(r.w);
        set(r.zero, p + i);
        next.push_back(std::move(r));
        if (static_cast<long>(next.size()) > max_rays) {
          out.status = ConeStatus::kBudgetExceeded;
          return out;
        }
      }
    }
    rays = std::move(next);
  }
  for (Ray<T>& r : rays) {
    Vec<T> v(p);
    for (Index j = 0; j < p; ++j) v(j) = r.w[static_cast<size_t>(j)];
    out.rays.push_back(std::move(v));
  }
  return out;
}

template OrthantConeRays<double> orthant_cone_rays<double>(const Mat<double>&, long);
template OrthantConeRays<Q> orthant_cone_rays<Q>(const Mat<Q>&, long);
template OrthantConeRays<Mpfr> orthant_cone_rays<Mpfr>(const Mat<Mpfr>&, long);
template OrthantConeRays<Interval> orthant_cone_rays<Interval>(const Mat<Interval>&, long);

}  // namespace contactcert::exact
