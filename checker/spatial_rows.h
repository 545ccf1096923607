// The spatial checkers' own reading of a body in space from rest (issue 34; docs/formats.md section 3b), shared by
// checker/spatial_modes_check.h and checker/spatial_stability_check.h and written apart from the solver's model
// (solvers/spatial/spatial_modes.h): per contact r = p - com, the normal, the frame and the world pyramid edges d_j;
// the contact point's acceleration A vdot = a + alpha x r; a letter's rows u . A vdot = u . a + (r x u) . alpha in
// the certificates' layout; and the letters read directly from A vdot (s: n . A vdot > 0; f: A vdot = 0; sliding:
// n . A vdot = 0, A vdot != 0 and the edges minimising d_j . A vdot over all edges are the letter's).
#pragma once

#include <string>
#include <vector>

#include "checker/table2_rows.h"
#include "exact/json_input.h"
#include "geometry/spatial_scene.h"

namespace contactcert::checker::spatial_check {

/// A contact as the checker reads it: r = p - com, the normal, the frame and the world edges d_j.
struct Seen {
  geometry::Vec3 r, n, t1, t2;
  std::vector<geometry::Vec3> d;
};

/// The contacts of a scene as the checker reads them.
std::vector<Seen> seen(const geometry::SpatialScene& s);

/// Contact i's frame as the checker relies on it, verified rather than taken from the reader: t1 and t2 non-zero,
/// orthogonal to the normal and to each other, t1 x t2 along +normal. Empty if so, else the reason.
std::string frame_fault(const std::vector<Seen>& cs);

/// The letters of a contact with m pyramid edges: s f, then 'A' .. 'A' + 2m - 1.
std::string alphabet(std::size_t m);

/// The row u . (a + alpha x r) on vdot's six columns, by its non-zero entries in column order.
std::vector<table2_check::Rows::Entry> along(const Seen& c, const geometry::Vec3& u);

/// The rows of a prefix in the certificates' layout: per letter its directions u (rows u . A vdot) and which of them
/// are strict (one slack sigma > 0 each, after vdot's six columns).
table2_check::Rows prefix_rows(const std::vector<Seen>& cs, const std::string& prefix);

/// Whether vdot = (a, alpha) realises the letters, read directly from the contact point's acceleration.
bool realises(const std::vector<Seen>& cs, const std::string& mode, const exact::Vec<exact::Q>& vdot);

/// A mode (`whole`: one letter per contact) or a prefix (1 to k letters) over the contacts' alphabets; InputError
/// naming the field otherwise.
std::string read_letters(const exact::JsonInput& j, const std::vector<Seen>& cs, bool whole);

/// The edges on which letter L of a contact with m edges may carry force: all (f), none (s), j (2j), or j and
/// j + 1 mod m (2j + 1), in the certificates' column order.
std::vector<std::size_t> allowed(std::size_t m, char L);

/// The body's mass matrix M = diag(m, m, m, I), row d (0..5), on vdot's six columns.
std::vector<table2_check::Rows::Entry> mass_row(const geometry::SpatialBody& b, std::size_t d);

/// The rows of a mode for g (zero_acceleration: of the resting solutions, mode f..f) in the certificates' layout:
/// columns vdot and its strict slacks (prefix_rows), then each contact's allowed weights beta (>= 0); rows the
/// kinematic rows (b = 0), then the six Newton-Euler rows M vdot - sum beta (u, r x u) = g, u = n + d_j.
table2_check::Rows motion_rows(const geometry::SpatialBody& body, const std::vector<Seen>& cs, const std::string& mode,
                               const exact::Vec<exact::Q>& g, bool zero_acceleration);

}  // namespace contactcert::checker::spatial_check
