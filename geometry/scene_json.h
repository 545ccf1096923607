// Reading planar fixture scenes (SPEC section 3, "kind": "planar") exactly, with InputError naming
// the file, the JSON path and what was expected.
#pragma once

#include <string>

#include "exact/json_input.h"
#include "geometry/planar_scene.h"

namespace contactcert::geometry {

/// A fixel as its scene file gives it, before its frame is derived.
struct FixelInput {
  FrameInput given;
  Q mu_s, mu_k;  ///< its own, else the scene's; mu_k defaults to mu_s
};

/// A planar scene as its file gives it: the workpiece and what each fixel's frame is to be derived from.
struct PlanarSceneInput {
  Workpiece workpiece;
  std::vector<FixelInput> fixels;
};

/// Parses a planar scene without deriving its frames (a certificate checker derives them itself). Throws
/// exact::InputError on any invalid field, as read_planar_scene does, but for the frames.
PlanarSceneInput read_planar_scene_input(const exact::JsonInput& root);

/// Parses a planar scene from its JSON root. Throws exact::InputError on any invalid field: a
/// degenerate or clockwise polygon, a non-positive radius, mass or inertia, a fixel inside the
/// workpiece, a fixel whose closest point or normal is not unique, a disk fixel at irrational
/// distance from the centre, negative friction, a negative gap, unknown keys.
PlanarScene read_planar_scene(const exact::JsonInput& root);

/// A point [x, y] of two exact numbers (SPEC section 1); InputError naming the field otherwise.
Point2 read_point(const exact::JsonInput& node);
/// An exact number > 0; InputError naming the field otherwise.
Q read_positive(const exact::JsonInput& node);
/// An exact number >= 0 (a friction coefficient, a gap); InputError naming the field otherwise.
Q read_nonnegative(const exact::JsonInput& node);

/// Parses a shape ({"type": "polygon", "vertices"} or {"type": "disk", "center", "radius"}, SPEC section 3). Throws
/// exact::InputError on a degenerate, clockwise or self-intersecting polygon or a non-positive radius.
Shape read_shape(const exact::JsonInput& node);

/// Parses a workpiece ({"shape", "com", "mass", "inertia"}, SPEC section 3): com defaults to the centroid, I/m
/// to uniform density. Throws exact::InputError on an invalid field.
Workpiece read_workpiece(const exact::JsonInput& node);

/// Loads and parses a planar scene file.
PlanarScene load_planar_scene(const std::string& path);

}  // namespace contactcert::geometry
