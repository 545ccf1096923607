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

/// A row of a letter: u . A vdot = 0, or > 0 if strict.
struct LetterRow {
  geometry::Vec3 u;
  bool strict = false;
};

/// The rows of letter L at contact c in the certificates' order (the solver's table, spatial_modes.h): a prefix's
/// rows are its letters', letter by letter, and a strict row has one slack sigma > 0 after vdot's six columns.
/// Empty if L is not one of its letters.
std::vector<LetterRow> letter_rows(const Seen& c, char L);

/// The rows of a prefix (its letters' letter_rows, letter by letter): columns vdot (6, free), then one slack
/// sigma > 0 per strict row (u . A vdot - sigma = 0), a prefix's kinematic system (docs/formats.md section 5b).
table2_check::Rows prefix_rows(const std::vector<Seen>& cs, const std::string& prefix);

/// Every letter's rows at every contact, built once per scene, each with the class of its direction: the rows of a
/// contact whose directions are equal or opposite share a class (one functional up to sign), so a weight on a class
/// moves onto the row of that class of any letter there (spatial_stability_check.h's reused Motzkin vectors).
class RowBlocks {
 public:
  /// A row by its class: u = sign * the class's direction.
  struct Row {
    std::size_t cls;
    int sign;
    bool strict;
  };
  explicit RowBlocks(const std::vector<Seen>& cs);
  /// The rows of letter L at contact i (nullptr if L is not one of its letters).
  const std::vector<Row>* rows(std::size_t i, char L) const;
  /// The row u . A vdot of class `cls` at contact i (its direction u) on vdot's six columns (along).
  const std::vector<table2_check::Rows::Entry>& functional(std::size_t i, std::size_t cls) const {
    return functionals_[i][cls];
  }

 private:
  std::vector<std::vector<std::vector<Row>>> rows_;  ///< per contact and letter (s, f, 'A', 'B', ...)
  std::vector<std::vector<std::vector<table2_check::Rows::Entry>>> functionals_;  ///< per contact and class
};

/// Whether vdot = (a, alpha) realises the letters, read directly from the contact point's acceleration.
bool realises(const std::vector<Seen>& cs, const std::string& mode, const exact::Vec<exact::Q>& vdot);

/// A mode (`whole`: one letter per contact) or a prefix (1 to k letters; 0 to k - 1 with `parent`) over the
/// contacts' alphabets; InputError naming the field otherwise.
std::string read_letters(const exact::JsonInput& j, const std::vector<Seen>& cs, bool whole, bool parent = false);

/// The edges on which letter L of a contact with m edges may carry force: all (f), none (s), j (2j), or j and
/// j + 1 mod m (2j + 1), in the certificates' column order.
std::vector<std::size_t> allowed(std::size_t m, char L);

/// The direction n + d_j of a force on pyramid edge j of contact c.
geometry::Vec3 edge_force(const Seen& c, std::size_t j);

/// The body's mass matrix M = diag(m, m, m, I), row d (0..5), on vdot's six columns.
std::vector<table2_check::Rows::Entry> mass_row(const geometry::SpatialBody& b, std::size_t d);

/// The rows of a mode for g (zero_acceleration: of the resting solutions, mode f..f) in the certificates' layout:
/// columns vdot and its strict slacks (prefix_rows), then each contact's allowed weights beta (>= 0); rows the
/// kinematic rows (b = 0), then the six Newton-Euler rows M vdot - sum beta (u, r x u) = g, u = n + d_j.
table2_check::Rows motion_rows(const geometry::SpatialBody& body, const std::vector<Seen>& cs, const std::string& mode,
                               const exact::Vec<exact::Q>& g, bool zero_acceleration);

}  // namespace contactcert::checker::spatial_check
