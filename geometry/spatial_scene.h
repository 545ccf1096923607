// A spatial (3-D) scene (issue 34; docs/formats.md section 3b): one rigid body - mass, 3x3 inertia about the com in
// world axes, com, optionally an axis-aligned box as its shape - and k point contacts, each a point p_i on the body
// with the inward normal n_i (the contact force on the body is along +n_i), a tangent frame (t_i1, t_i2) with
// t_i1 x t_i2 a positive multiple of n_i, and a friction pyramid: m >= 4 edge directions d_ij = u_j t_i1 + v_j t_i2
// in the tangent plane, counterclockwise about n_i, the vertices of a strictly convex polygon around the origin
// (the pyramid is the cone of the n_i + d_ij: the linearised friction cone of Stewart-Trinkle and Anitescu-Potra).
// Everything is exact and nothing is normalised: a frame stated or derived is rational, of any length.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "exact/json_input.h"
#include "exact/number.h"

namespace contactcert::geometry {

using Vec3 = std::array<exact::Q, 3>;

/// a x b.
Vec3 cross(const Vec3& a, const Vec3& b);
/// a . b.
exact::Q dot(const Vec3& a, const Vec3& b);

/// An axis-aligned box: its centre and its half extents (each > 0).
struct Box3 {
  Vec3 center, half;
};

struct SpatialBody {
  exact::Q mass;                                   ///< m > 0
  std::array<std::array<exact::Q, 3>, 3> inertia;  ///< symmetric positive definite, about the com, world axes
  Vec3 com;
  std::optional<Box3> box;  ///< the shape, if given: every contact point lies on it and every normal points into it
};

struct SpatialContact {
  Vec3 point, normal;
  Vec3 t1, t2;                                 ///< stated, or derived (default_tangent_frame)
  std::vector<std::array<exact::Q, 2>> edges;  ///< (u_j, v_j): d_j = u_j t1 + v_j t2, counterclockwise, m >= 4
  /// d_j in world coordinates.
  Vec3 edge(std::size_t j) const;
};

struct SpatialScene {
  SpatialBody body;
  std::vector<SpatialContact> contacts;  ///< their order is the order of a mode's letters
};

/// The frame derived for a normal n when none is stated: with j the first axis of the largest |n_j|,
/// t1 = n_j e_{j+1} - n_{j+1} e_j (indices mod 3) and t2 = n x t1; for n = (0, 0, 1) it is (x, y).
std::pair<Vec3, Vec3> default_tangent_frame(const Vec3& n);

/// Whether a JSON root is a spatial scene ("kind": "spatial").
bool is_spatial_scene(const exact::JsonInput& root);

/// Reads a spatial scene; InputError naming the field for anything malformed: a mass not positive, an inertia not
/// symmetric positive definite, a zero normal, a point off the box or a normal out of it, a frame not orthogonal
/// or left-handed, fewer than 4 or more than 13 edges, edges not counterclockwise, not once around the origin or
/// not strictly convex.
SpatialScene read_spatial_scene(const exact::JsonInput& root);

}  // namespace contactcert::geometry
