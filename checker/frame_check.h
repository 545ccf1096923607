// The certificate checkers' own contact frames (SPEC section 3), derived and verified apart from the solvers'
// geometry/contact_frame.cpp, so that a wrong frame is not shared by a solver and the checker of its certificate.
// A frame (p, n, gap^2) of a fixel on a shape is the one the geometry defines when:
//   polygon (counter-clockwise): p lies on an edge SEGMENT [a, b] (cross(b - a, p - a) = 0 and
//     0 <= (p - a).(b - a) <= |b - a|^2); inside the segment n is a positive multiple of its inward normal
//     perp(b - a); at a vertex n is non-zero and in pos(u, v), u and v the inward normals of the two edges that
//     meet there (the normal forces those edges can exert, at a convex and at a reflex vertex alike);
//   disk (centre c, radius r): |p - c|^2 = r^2 and n is a positive multiple of c - p;
//   a fixel given by its position f: f is not strictly inside the workpiece; gap^2 = |p - f|^2; n is a positive
//     multiple of p - f when the gap is not zero; p is f's unique closest boundary point: every edge segment's
//     closest point q to f has |f - q|^2 >= gap^2, with equality only at q = p (a disk: p - c is a positive
//     multiple of f - c, the one closest point of the circle to an f outside it);
//   an explicit contact {point, normal, gap}: p and n are the file's, gap^2 is the square of its gap.
#pragma once

#include <string>

#include "exact/json_input.h"
#include "geometry/planar_scene.h"

namespace contactcert::checker::frame_check {

/// Why `frame` is not the contact frame that `shape` defines for what the file gives (see above): status kOk and
/// an empty message if it is; else kInsideWorkpiece (a fixel strictly inside), kClosestNotUnique (p not on the
/// boundary, not the unique closest point, or a wrong gap) or kNormalNotUnique (a wrong normal), and why.
geometry::FrameResult frame_violation(const geometry::Shape& shape, const geometry::FrameInput& given,
                                      const geometry::ContactFrame& frame);

/// The checker's own frame of what the file gives, verified by frame_violation, or why there is none. Its normal
/// is the one SPEC section 3 fixes: perp(b - a) on an edge, p - f off a polygon, c - f at a disk, the file's for an
/// explicit contact.
geometry::FrameResult checked_frame(const geometry::Shape& shape, const geometry::FrameInput& given);

/// A certificate's embedded scene as its checker reads it: the frames are checked_frame's (never the solvers'), and
/// `violation` names the first fixel that has none ("" when every fixel has its frame).
struct CheckedSceneRead {
  geometry::PlanarScene scene;
  std::string violation;
};

/// Reads the embedded scene `root` with the checker's frames. Throws exact::InputError on a malformed scene.
CheckedSceneRead read_checked_scene(const exact::JsonInput& root);

/// The scene a certificate embeds as text under "scene", read as read_checked_scene reads it, once its
/// "problem_sha256" is found to be the digest of that text (`violation` says so otherwise).
CheckedSceneRead read_embedded_scene(const exact::JsonInput& certificate);

}  // namespace contactcert::checker::frame_check
