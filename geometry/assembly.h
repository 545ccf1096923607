// A planar assembly (issue 31): N movable rigid bodies, fixed obstacles, point fixels and point fingers, and the
// contacts between any two of them, all exact. Contact i acts between two parties `from` and `to` at a point p_i on
// both boundaries; its normal n_i points from `from` into `to` (a common normal of the two boundaries), and
// t_i = (-n_iy, n_ix). The force c_in n_i + c_it t_i acts on `to` and its opposite on `from`.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "exact/json_input.h"
#include "geometry/workpiece.h"

namespace contactcert::geometry {

/// A movable body: its shape, centre of mass, mass and inertia about the com, and the wrench applied to it.
struct Body {
  Shape shape;
  Point2 com;
  Q mass;                           ///< m > 0
  Q inertia;                        ///< I > 0 about the com
  Q load_fx, load_fy, load_torque;  ///< the external wrench (f_x, f_y, torque about the com)
};

/// One party of a contact: a movable body, a fixed obstacle (a shape), a point fixel or a point finger.
struct Party {
  enum class Kind { kBody, kObstacle, kFixel, kFinger };
  Kind kind = Kind::kBody;
  std::size_t index = 0;  ///< into bodies, obstacles, fixels or fingers
  bool movable() const { return kind == Kind::kBody; }
};

/// A point finger of a quasistatic scene: where it is and how it is driven (docs/formats.md, section 2).
struct Finger {
  Point2 position;
  bool world_axes = false;        ///< joints along x and y; else along n and t of its contact
  bool force_controlled = false;  ///< `force` given; else `velocity`
  Point2 given;                   ///< the velocity or the force, in the finger's axes
};

/// A contact: the two parties, the point, the normal from `from` into `to`, and the friction coefficients.
struct AssemblyContact {
  Party from, to;
  Point2 point, normal;
  Q mu_s, mu_k;
};

/// N >= 1 bodies, the fixed things they may touch, and the contacts (their order is the order of a mode's letters).
struct Assembly {
  std::vector<Body> bodies;
  std::vector<Shape> obstacles;
  std::vector<Point2> fixels;
  std::vector<Finger> fingers;
  std::vector<AssemblyContact> contacts;
};

/// Whether a JSON root is an assembly (a `planar` or `quasistatic_scene` file with `bodies`).
bool is_assembly(const exact::JsonInput& root);

/// Reads an assembly from a `"kind": "planar"` or `"kind": "quasistatic_scene"` root with `bodies`
/// (docs/formats.md, section 3a). Throws exact::InputError naming the field: a bad shape; a disk without a mass;
/// bodies or obstacles whose interiors overlap; a contact whose parties are the same or both fixed, whose point is
/// not on both boundaries, or whose normal is not a common normal pointing from `from` into `to`; negative friction.
Assembly read_assembly(const exact::JsonInput& root);

}  // namespace contactcert::geometry
