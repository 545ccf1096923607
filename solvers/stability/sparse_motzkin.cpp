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
  const std::vector<Z> w = exact::primitive(values);
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < w.size(); ++i) out.push_back({rows[i], w[i].get_str()});
  return out;
}

Vec<Q> read_sparse_motzkin(const exact::JsonInput& list, std::size_t rows) {
  const std::size_t n = list.size();
  if (n == 0) list.fail("a Motzkin vector: at least one [row, weight] pair (the zero vector proves nothing)");
  Vec<Q> y = Vec<Q>::Zero(static_cast<Eigen::Index>(rows));
  Z common = 0;
  long previous = -1;
  for (std::size_t i = 0; i < n; ++i) {
    const exact::JsonInput pair = list.at(i);
    if (!pair.is_array() || pair.size() != 2) pair.fail("a pair [row, weight]");
    if (rows == 0) pair.at(0).fail("a row of the system, which has none");
    const long row = pair.at(0).integer(0, static_cast<long>(rows) - 1);
    if (row <= previous)
      pair.at(0).fail("a row above " + std::to_string(previous) + ": rows strictly increasing, each weighted row once" +
                      (row == previous ? " (row " + std::to_string(row) + " is repeated)" : ""));
    previous = row;
    const Q w = pair.at(1).rational();
    if (sgn(w) == 0 || w.get_den() != 1)
      pair.at(1).fail("a non-zero integer weight (only weighted rows are listed, as primitive integers)");
    common = gcd(common, w.get_num());
    y(row) = w;
  }
  if (common != 1) list.fail("a primitive integer vector: the weights have the common factor " + common.get_str());
  return y;
}

}  // namespace contactcert::solvers
