#include "queries/boundary_marks.h"

#include "queries/stability_svg.h"

namespace contactcert::queries {

std::vector<BoundaryMark> verdict_marks(const geometry::PlanarScene& scene,
                                        const solvers::BoundaryPieces<exact::Q, solvers::StabilityVerdict>& pushes) {
  return boundary_marks<solvers::StabilityVerdict>(scene, pushes, [](solvers::StabilityVerdict v) {
    const char* meaning = v == solvers::StabilityVerdict::kStronglyStable ? "strongly stable"
                          : v == solvers::StabilityVerdict::kWeaklyStable ? "only weakly stable"
                                                                          : "unstable";
    return MarkStyle{verdict_colour(v), std::string("a frictionless inward push here is ") + meaning};
  });
}

std::vector<BoundaryMark> seating_marks(const geometry::PlanarScene& scene,
                                        const solvers::BoundaryPieces<exact::Q, bool>& pushes) {
  return boundary_marks<bool>(scene, pushes, [](bool in) {
    return in ? MarkStyle{"#1b7837", "a frictionless push here seats the workpiece from any contact state"}
              : MarkStyle{};
  });
}

}  // namespace contactcert::queries
