#include "solvers/stability/sparse_motzkin.h"

#include <string>

#include "exact/rational_text.h"

namespace contactcert::solvers {

using exact::Q;
using exact::Vec;
using exact::Z;

nlohmann::ordered_json sparse_motzkin_json(const Vec<Q>& y) {
  // The primitive vector of the non-zero entries alone: a zero changes neither the lcm of the denominators nor the
  // gcd of the numerators.
  std::vector<std::size_t> rows;
  std::vector<Q> values;
  for (Eigen::Index r = 0; r < y.size(); ++r)
    if (sgn(y(r)) != 0) {
      rows.push_back(static_cast<std::size_t>(r));
      values.push_back(y(r));
    }
  return sparse_motzkin_json(rows, values);
}

nlohmann::ordered_json sparse_motzkin_json(const std::vector<std::size_t>& rows, const std::vector<Q>& values) {
  const std::vector<Z> w = exact::primitive(values);
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < w.size(); ++i) out.push_back({rows[i], w[i].get_str()});
  return out;
}

}  // namespace contactcert::solvers
