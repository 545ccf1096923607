#include "solvers/stability/sparse_motzkin.h"

#include <string>

#include "exact/rational_text.h"

namespace contactcert::solvers {

using exact::Q;
using exact::Vec;
using exact::Z;

nlohmann::ordered_json sparse_motzkin_json(const Vec<Q>& y) {
  const std::vector<Z> w = exact::primitive(y);
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (std::size_t r = 0; r < w.size(); ++r)
    if (sgn(w[r]) != 0) out.push_back({r, w[r].get_str()});
  return out;
}

}  // namespace contactcert::solvers
