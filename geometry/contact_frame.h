// Contact frames of the wrench cone paper (section 2.1, with the docs/papers.md errata): for fixel
// i, p_i is the unique closest workpiece point, n_i points from the fixel toward p_i (into the
// workpiece) and t_i = (-n_iy, n_ix). Normals are rational and need not be unit: a wrench cone does
// not change when a frame (n, t) is scaled by a positive factor.
#pragma once

#include <optional>
#include <string>

#include "geometry/workpiece.h"

namespace contactcert::geometry {

/// One contact frame: the workpiece point, the (non-unit) inward normal, and the squared gap.
struct ContactFrame {
  Point2 point;   ///< p_i, on the workpiece boundary
  Point2 normal;  ///< n_i, pointing into the workpiece; any positive length
  Q gap_squared;  ///< (distance from the fixel to p_i)^2; exact even when the gap is irrational
  bool touching() const { return sgn(gap_squared) == 0; }
  Point2 tangent() const { return perp(normal); }  ///< t_i = (-n_iy, n_ix)
};

/// Outcome of building a frame from a fixel position.
enum class FrameStatus {
  kOk,
  kInsideWorkpiece,      ///< the fixel lies strictly inside the workpiece
  kClosestNotUnique,     ///< two or more workpiece points are equally close
  kNormalNotUnique,      ///< the fixel touches a polygon vertex: the normal is not determined
  kIrrationalDirection,  ///< a disk fixel whose direction from the centre has irrational length
};

/// A frame and, when it could not be built, why and how to fix the input.
struct FrameResult {
  FrameStatus status = FrameStatus::kOk;
  ContactFrame frame;
  std::string message;  ///< empty when kOk
};

/// What a scene file gives for one fixel (SPEC section 3): its position, or an explicit contact.
struct FrameInput {
  std::optional<Point2> position;  ///< the "position" form; the fields below are then unused
  Point2 point, normal;            ///< the explicit contact's workpiece point and inward normal
  Q gap;                           ///< the explicit contact's gap, >= 0
};

/// A way of turning what the file gives into a frame: frame_of (the solvers'), or a certificate checker's own.
using FrameRule = FrameResult (*)(const Shape& shape, const FrameInput& given);

/// The frame of a fixel at `fixel` (SPEC section 3, "position" form).
FrameResult frame_from_position(const Shape& shape, const Point2& fixel);

/// Checks an explicit contact (SPEC section 3, "point"/"normal"/"gap" form): the point lies on the
/// boundary, the normal is non-zero and points into the workpiece. Returns the frame or why not.
FrameResult frame_from_contact(const Shape& shape, const Point2& point, const Point2& normal, const Q& gap);

/// frame_from_position or frame_from_contact, as the file gives the fixel.
FrameResult frame_of(const Shape& shape, const FrameInput& given);

}  // namespace contactcert::geometry
