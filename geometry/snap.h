// Float input made exact on purpose (SPEC section 1 keeps every number as written; this is the explicit way to
// read floats): points put exactly on the workpiece boundary they are meant to touch (a polygon edge, or a disk
// circle at a Pythagorean direction), other numbers replaced by the simplest rational within a tolerance, every
// change reported, and what cannot be snapped within the tolerance refused with its field named.
#pragma once

#include <string>
#include <vector>

#include "geometry/workpiece.h"

namespace contactcert::geometry {

/// sqrt(q) for q >= 0 when it is rational, else floor(sqrt(q) 2^bits) / 2^bits (and *rational = false).
Q rational_length(const Q& squared, bool* rational = nullptr, unsigned long bits = 40);

/// The rational point c + r ((1 - t^2) / (1 + t^2), 2 t / (1 + t^2)) turned by `quadrant` quarter turns
/// counter-clockwise (the rational parametrisation of the circle, t = tan(phi / 2)): exactly on |p - c| = r.
Point2 circle_point(const Point2& c, const Q& r, const Q& t, long quadrant);

/// The simplest rational in [lo, hi] (lo <= hi): the smallest denominator, then the smallest |numerator|
/// (Stern-Brocot descent by continued fractions).
Q simplest_between(const Q& lo, const Q& hi);

/// One snap: the field (its JSON path), the exact value before and after (numbers, or points "[x, y]" as
/// exact texts) and the squared distance moved, exact.
struct Snap {
  std::string field, original, snapped;
  Q distance_squared;
};

/// A planar scene's text with its numbers snapped, and every snap made.
struct SnappedScene {
  std::string text;
  std::vector<Snap> snaps;
};

/// Snaps a planar scene (SPEC section 3) read from float input with tolerance tol > 0. Numbers outside the
/// fixel points become the simplest rational within tol. A fixel's explicit "point" goes to its nearest point on
/// the boundary (the exact projection onto the nearest polygon edge; on a disk a rational point of the circle),
/// refused if that is farther than tol. A "position" within tol of the boundary goes onto it the same way;
/// farther, on a polygon its coordinates are snapped as numbers, on a disk it moves to a rational distance
/// along a Pythagorean direction. An explicit contact's normal within angle asin(tol) of the exact inward normal at
/// the snapped point becomes its projection onto it. Every point moves by at most tol (checked exactly). The
/// labels name and description are kept, source and note dropped. Throws exact::InputError
/// naming the file and field for what cannot be snapped, or for an invalid tolerance or shape.
SnappedScene snap_planar_scene(const std::string& text, const std::string& file, const Q& tol);

}  // namespace contactcert::geometry
