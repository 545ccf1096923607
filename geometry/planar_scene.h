// A planar fixture scene of the wrench cone paper (SPEC section 3): one workpiece and its fixels,
// each with an exact contact frame and friction coefficients.
#pragma once

#include <optional>
#include <vector>

#include "geometry/contact_frame.h"
#include "geometry/workpiece.h"

namespace contactcert::geometry {

/// A fixel: its contact frame and its static and kinetic friction coefficients.
struct Fixel {
  ContactFrame frame;
  Q mu_s;                          ///< static friction (rolling, Table 2 rows n and m)
  Q mu_k;                          ///< kinetic friction (sliding, Table 2 rows l and r)
  std::optional<Point2> position;  ///< the fixel's own position, when the scene gave it
};

/// A workpiece and its fixels, in fixel order (the order of the letters of a mode string).
struct PlanarScene {
  Workpiece workpiece;
  std::vector<Fixel> fixels;
};

}  // namespace contactcert::geometry
