#include "checker/sparse_motzkin_reader.h"

#include <string>

namespace contactcert::checker {

using exact::Q;
using exact::Vec;
using exact::Z;

Vec<Q> read_sparse_motzkin(const exact::JsonInput& list, std::size_t rows) {
  Vec<Q> y = Vec<Q>::Zero(static_cast<Eigen::Index>(rows));
  for (auto& [row, w] : read_sparse_motzkin_pairs(list, rows)) y(static_cast<Eigen::Index>(row)) = std::move(w);
  return y;
}

std::vector<std::pair<std::size_t, Q>> read_sparse_motzkin_pairs(const exact::JsonInput& list, std::size_t rows) {
  const std::size_t n = list.size();
  if (n == 0) list.fail("a Motzkin vector: at least one [row, weight] pair (the zero vector proves nothing)");
  std::vector<std::pair<std::size_t, Q>> y;
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
    y.emplace_back(static_cast<std::size_t>(row), w);
  }
  if (common != 1) list.fail("a primitive integer vector: the weights have the common factor " + common.get_str());
  return y;
}

}  // namespace contactcert::checker
