// The picture of `contactcert design`: one panel per reported placement, in the style of the wrench cone
// paper's Figure 6 (the workpiece, its fixels as discs outside the boundary with their inward normals), the
// candidate positions as small dots. Doubles: a picture, not a verdict.
#pragma once

#include <string>
#include <vector>

#include "solvers/design/ranking.h"

namespace contactcert::queries {

/// A complete <svg> element; `captions` holds one line per placement.
std::string design_svg(const solvers::DesignProblem& problem, const std::vector<solvers::Ranked>& best,
                       const std::vector<std::string>& captions, const std::string& title);

}  // namespace contactcert::queries
