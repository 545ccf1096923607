// A point as messages and reports print it: "(x, y)", each coordinate exact in lowest terms.
#pragma once

#include <string>

#include "exact/rational_text.h"
#include "geometry/workpiece.h"

namespace contactcert::geometry {

/// "(x, y)" of p, exact.
inline std::string point_text(const Point2& p) {
  std::string s = "(";  // appended, not "(" + string: gcc 12's -Wrestrict false positive
  s += exact::to_string(p.x);
  s += ", ";
  s += exact::to_string(p.y);
  return s += ")";
}

}  // namespace contactcert::geometry
