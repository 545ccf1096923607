#include "queries/region_data.h"

#include <algorithm>
#include <map>

#include "exact/rational_text.h"
#include "solvers/stability/strong_cones.h"

namespace contactcert::queries {
namespace {

using exact::Q;
using exact::Vec;

/// Primitive integer rows of the planes in machine integers, when every entry fits comfortably (|p| < 2^40,
/// so p . g for |g_i| <= 24 cannot overflow); else empty.
std::vector<std::array<long, 3>> small_planes(const exact::Mat<Q>& planes) {
  std::vector<std::array<long, 3>> out;
  for (Eigen::Index j = 0; j < planes.rows(); ++j) {
    const auto z = exact::primitive(Vec<Q>(planes.row(j).transpose()));
    std::array<long, 3> row{};
    for (int k = 0; k < 3; ++k) {
      if (abs(z[static_cast<std::size_t>(k)]) >= exact::Z(1L << 40)) return {};
      row[static_cast<std::size_t>(k)] = z[static_cast<std::size_t>(k)].get_si();
    }
    out.push_back(row);
  }
  return out;
}

/// For each sign vector met by an integer vector of max-norm <= R, the first such vector by increasing norm.
std::map<std::string, std::array<long, 3>> small_representatives(const exact::Mat<Q>& planes, long R) {
  std::map<std::string, std::array<long, 3>> found;
  const auto P = small_planes(planes);
  if (P.empty() && planes.rows() > 0) return found;
  for (long r = 0; r <= R; ++r)
    for (long x = -r; x <= r; ++x)
      for (long y = -r; y <= r; ++y)
        for (long z = -r; z <= r; ++z) {
          if (std::max({std::labs(x), std::labs(y), std::labs(z)}) != r) continue;  // the shell of norm r only
          std::string key;
          for (const auto& p : P) {
            const long v = p[0] * x + p[1] * y + p[2] * z;
            key += v > 0 ? '+' : v < 0 ? '-' : '0';
          }
          found.emplace(key, std::array<long, 3>{x, y, z});
        }
  return found;
}

json primitive_rows(const exact::Mat<Q>& M) {
  json out = json::array();
  for (Eigen::Index r = 0; r < M.rows(); ++r) out.push_back(primitive_json(Vec<Q>(M.row(r).transpose())));
  return out;
}

}  // namespace

std::vector<Vec<Q>> cell_representatives(const solvers::StableRegion<Q>& region) {
  const auto small = small_representatives(region.planes, 24);
  std::vector<Vec<Q>> out;
  for (const auto& c : region.cells) {
    if (const auto it = small.find(solvers::sign_vector(region, c.point)); it != small.end()) {
      Vec<Q> v(3);
      v << Q(it->second[0]), Q(it->second[1]), Q(it->second[2]);
      out.push_back(v);
    } else {
      const auto z = exact::primitive(c.point);
      Vec<Q> v(3);
      for (int k = 0; k < 3; ++k) v(k) = Q(z[static_cast<std::size_t>(k)]);
      out.push_back(v);
    }
  }
  return out;
}

json region_data_json(const solvers::StableRegion<Q>& region) {
  json planes = json::array();
  for (Eigen::Index j = 0; j < region.planes.rows(); ++j)
    planes.push_back(primitive_json(Vec<Q>(region.planes.row(j).transpose())));
  const auto reps = cell_representatives(region);
  json cells = json::array();
  for (std::size_t i = 0; i < region.cells.size(); ++i) {
    const auto& c = region.cells[i];
    cells.push_back({{"dimension", c.dimension},
                     {"signs", solvers::sign_vector(region, c.point)},
                     {"representative", primitive_json(reps[i])},
                     {"point", primitive_json(c.point)},
                     {"label", solvers::verdict_name(c.label)}});
  }
  json cones = json::array();
  for (const auto& c : solvers::strongly_stable_cones(region))
    cones.push_back({{"signs", c.pattern},
                     {"dim", 3},
                     {"inequalities", primitive_rows(c.cone.inequalities)},
                     {"strict", primitive_rows(c.cone.strict)},
                     {"equalities", primitive_rows(c.cone.equalities)}});
  return {{"planes", planes}, {"cells", cells}, {"strongly_stable_cones", cones}};
}

}  // namespace contactcert::queries
