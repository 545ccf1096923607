#include "solvers/stability/strong_cones.h"

#include <set>

namespace contactcert::solvers {
namespace {

/// Merges patterns as strongly_stable_cones describes, until no pair merges.
std::set<std::string> merged(std::set<std::string> patterns) {
  for (bool changed = true; changed;) {
    changed = false;
    for (auto it = patterns.begin(); it != patterns.end() && !changed; ++it)
      for (std::size_t k = 0; k < it->size(); ++k) {
        if ((*it)[k] != '+') continue;
        std::string q = *it, r = *it, m = *it;
        q[k] = '-';
        r[k] = '0';
        m[k] = '*';
        if (!patterns.count(q) || !patterns.count(r)) continue;
        const std::string p = *it;
        patterns.erase(p);
        patterns.erase(q);
        patterns.erase(r);
        patterns.insert(m);
        changed = true;
        break;
      }
  }
  return patterns;
}

}  // namespace

std::string sign_vector(const StableRegion<Q>& region, const Vec<Q>& g) {
  std::string s;
  for (Eigen::Index j = 0; j < region.planes.rows(); ++j) {
    const int v = sgn(Q(region.planes.row(j).dot(g)));
    s += v > 0 ? '+' : v < 0 ? '-' : '0';
  }
  return s;
}

std::vector<SignCone> strongly_stable_cones(const StableRegion<Q>& region) {
  std::set<std::string> strong;
  for (const auto& c : region.cells)
    if (c.label == StabilityVerdict::kStronglyStable) strong.insert(sign_vector(region, c.point));
  std::vector<SignCone> out;
  for (const std::string& p : merged(strong)) {
    std::vector<Vec<Q>> S, E;
    for (std::size_t j = 0; j < p.size(); ++j) {
      const Vec<Q> row = region.planes.row(static_cast<Eigen::Index>(j)).transpose();
      if (p[j] == '+') S.push_back(-row);
      if (p[j] == '-') S.push_back(row);
      if (p[j] == '0') E.push_back(row);
    }
    auto stack = [](const std::vector<Vec<Q>>& rows) {
      Mat<Q> M(static_cast<Eigen::Index>(rows.size()), 3);
      for (std::size_t i = 0; i < rows.size(); ++i) M.row(static_cast<Eigen::Index>(i)) = rows[i].transpose();
      return M;
    };
    out.push_back({p, geometry::FaceCone<Q>::from_rows(3, Mat<Q>(0, 3), stack(E), stack(S))});
  }
  return out;
}

}  // namespace contactcert::solvers
