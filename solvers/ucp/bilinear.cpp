#include "solvers/ucp/bilinear.h"

#include "exact/interval_number.h"
#include "exact/mpfr_number.h"

namespace contactcert::solvers::ucp {

namespace {
using Index = Eigen::Index;

template <class T>
T dot(const Vec<T>& a, const Vec<T>& b) {
  T s = T(0);
  for (Index i = 0; i < a.size(); ++i)
    if (!exact::is_negligible(a(i)) && !exact::is_negligible(b(i))) s += a(i) * b(i);
  return s;
}
}  // namespace

template <class T>
BilinearResult<T> bilinear(const Face<T>& FX, const Face<T>& FY, const BilinearOptions& opts, std::mt19937_64& rng) {
  BilinearResult<T> r;
  LpCounters& count = r.counters;
  // Step 0: (x^0, y^0) from two LPs with a zero objective.
  const auto stopped = [&](const FaceLpResult<T>& lp) {
    if (lp.status == FaceLpStatus::kTimeLimit) r.status = BilinearStatus::kTimeLimit;
    return lp.status == FaceLpStatus::kTimeLimit;
  };
  FaceLpResult<T> x0 = minimize_on_face(FX, Vec<T>(Vec<T>::Zero(FX.n)), opts.arith, count, opts.deadline);
  if (stopped(x0)) return r;
  if (x0.status == FaceLpStatus::kEmpty) {
    r.status = BilinearStatus::kXEmpty;
    r.farkas = x0.farkas;
    return r;
  }
  FaceLpResult<T> y0 = minimize_on_face(FY, Vec<T>(Vec<T>::Zero(FY.n)), opts.arith, count, opts.deadline);
  if (stopped(y0)) return r;
  if (y0.status == FaceLpStatus::kEmpty) {
    r.status = BilinearStatus::kYEmpty;
    r.farkas = y0.farkas;
    return r;
  }
  FaceVertex<T> xv = x0.vertex, yv = y0.vertex;
  T val = dot(xv.x, yv.x);
  r.x = xv, r.y = yv, r.xTy = val;
  auto record = [&] {
    if (exact::sign(T(val - r.xTy)) < 0) r.x = xv, r.y = yv, r.xTy = val;
  };
  bool step1 = true;
  while (!exact::is_zero(val) && r.pairs < opts.max_pairs) {
    if (opts.deadline.expired()) {
      r.status = BilinearStatus::kTimeLimit;
      return r;
    }
    if (step1) {
      // Step 1: x^{nu+1} solves (14), then y^{nu+1} solves (15).
      FaceLpResult<T> xn = minimize_on_face(FX, yv.x, opts.arith, count, opts.deadline);
      if (stopped(xn)) return r;
      FaceLpResult<T> yn = minimize_on_face(FY, xn.vertex.x, opts.arith, count, opts.deadline);
      if (stopped(yn)) return r;
      ++r.pairs;
      const T nv = dot(xn.vertex.x, yn.vertex.x);
      // Step 2: exact termination at x^T y = 0; a strict decrease returns to Step 1.
      if (exact::is_zero(nv) || exact::sign(T(val - nv)) > 0) {
        xv = xn.vertex, yv = yn.vertex, val = nv;
        record();
        continue;
      }
      // (16): (x^nu, y^nu) is stationary; continue with Step 3 from it.
    }
    // Step 3: all adjacent extreme points E(x^nu), E(y^nu), degenerate vertices included.
    std::vector<FaceVertex<T>> EX = adjacent_on_face(FX, xv, opts.max_bases, count),
                               EY = adjacent_on_face(FY, yv, opts.max_bases, count);
    if (EX.empty()) EX.push_back(xv);
    if (EY.empty()) EY.push_back(yv);
    std::size_t bi = 0, bj = 0;
    T bv = dot(EX[0].x, EY[0].x);
    for (std::size_t i = 0; i < EX.size(); ++i)
      for (std::size_t j = 0; j < EY.size(); ++j) {
        const T v = dot(EX[i].x, EY[j].x);
        if (exact::sign(T(v - bv)) < 0) bi = i, bj = j, bv = v;
      }
    ++r.pairs;
    if (exact::sign(T(val - bv)) > 0) {
      xv = EX[bi], yv = EY[bj], val = bv;
      record();
      step1 = true;
      continue;
    }
    // No adjacent pair decreases x^T y: move to a random adjacent pair.
    if (++r.random_moves > opts.max_random_moves) {
      --r.pairs;
      break;
    }
    xv = EX[std::uniform_int_distribution<std::size_t>(0, EX.size() - 1)(rng)];
    yv = EY[std::uniform_int_distribution<std::size_t>(0, EY.size() - 1)(rng)];
    val = dot(xv.x, yv.x);
    record();
    step1 = opts.step3 == Step3Rule::kModified;
  }
  r.status = exact::is_zero(r.xTy) ? BilinearStatus::kComplementary : BilinearStatus::kStopped;
  return r;
}

template <class T>
BilinearStatus alternate_lps(const Face<T>& FX, const Face<T>& FY, FaceVertex<T>& x, FaceVertex<T>& y, Arith arith,
                             int max_rounds, LpCounters& count, const exact::Deadline& deadline) {
  T val = dot(x.x, y.x);
  for (int round = 0; round < max_rounds && !exact::is_zero(val); ++round) {
    FaceLpResult<T> xn = minimize_on_face(FX, y.x, arith, count, deadline);
    if (xn.status == FaceLpStatus::kTimeLimit) return BilinearStatus::kTimeLimit;
    FaceLpResult<T> yn = minimize_on_face(FY, xn.vertex.x, arith, count, deadline);
    if (yn.status == FaceLpStatus::kTimeLimit) return BilinearStatus::kTimeLimit;
    const T nv = dot(xn.vertex.x, yn.vertex.x);
    if (exact::sign(T(val - nv)) < 0) break;
    const bool decreased = exact::sign(T(val - nv)) > 0;
    x = xn.vertex, y = yn.vertex, val = nv;
    if (!decreased) break;
  }
  return exact::is_zero(val) ? BilinearStatus::kComplementary : BilinearStatus::kStopped;
}

#define CONTACTCERT_BILINEAR_INSTANTIATE(T)                                                                            \
  template BilinearResult<T> bilinear<T>(const Face<T>&, const Face<T>&, const BilinearOptions&, std::mt19937_64&);    \
  template BilinearStatus alternate_lps<T>(const Face<T>&, const Face<T>&, FaceVertex<T>&, FaceVertex<T>&, Arith, int, \
                                           LpCounters&, const exact::Deadline&);
CONTACTCERT_BILINEAR_INSTANTIATE(double)
CONTACTCERT_BILINEAR_INSTANTIATE(Q)
CONTACTCERT_BILINEAR_INSTANTIATE(exact::Mpfr)
CONTACTCERT_BILINEAR_INSTANTIATE(exact::Interval)
#undef CONTACTCERT_BILINEAR_INSTANTIATE

}  // namespace contactcert::solvers::ucp
