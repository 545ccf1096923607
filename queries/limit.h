// A run stopped by one of its budgets (time, nodes, placements) before an answer: what ran out and what the run
// covered until then. The CLI prints it and exits 3; Python raises contactcert.BudgetExceeded with its text.
#pragma once

#include <string>

namespace contactcert::queries {

struct Limit {
  std::string what;     ///< e.g. "design scene.json: time limit of 10 s reached"
  std::string covered;  ///< e.g. "12 of 120 placements in 12 of 120 chunks"
  /// "WHAT (covered: COVERED)".
  std::string text() const { return what + " (covered: " + covered + ")"; }
};

}  // namespace contactcert::queries
