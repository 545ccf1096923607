// The pieces shared by the spatial certificates in lines (docs/formats.md sections 5b and 5c; the reader is
// checker/certificate_lines.h): each distinct Motzkin vector written once by the functionals it weighs (a contact
// and a letter's row naming the direction u of w_u = (u, r x u), up to sign), and the tree's dead prefixes grouped by
// their parent, each naming its vector. The tree reuses a dead prefix's proof on later prefixes weighing the same
// functionals (spatial_modes.h), so ~110 000 dead prefixes of a box on a plane at k = 16 name ~1 600 vectors.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "solvers/spatial/spatial_modes.h"

namespace contactcert::solvers::spatial {

/// Every letter row of every contact by the first row (letters in alphabet order, rows in the table's order) of the
/// same functional up to sign: a Motzkin vector moved between letters (move_rows) weighs the same first rows, so its
/// text repeats exactly.
class RowNames {
 public:
  explicit RowNames(const SpatialModel& model);

  /// The vector's line: {"rows": [[contact, letter, row], ...], "motzkin": [[index, weight], ...]}, its weights on
  /// the first rows (in contact, letter, row order; a row's weight times its sign), followed with `dynamics` by the
  /// six Newton-Euler rows' (y's last six entries), as one sparse primitive Motzkin vector. y is over the rows of
  /// `letters` (prefix_system's layout: a prefix's rows a_n >= 0 of the later contacts after its letters', named by
  /// the functional n, the row of `s`).
  std::string line(const std::string& letters, const Vec<Q>& y, bool dynamics) const;

 private:
  struct Name {
    std::size_t letter, row;  ///< the first row: letter index in the contact's alphabet, row in its table
    int sign;                 ///< this row's functional = sign * the first row's
  };
  std::vector<std::string> alphabets_;
  std::vector<std::vector<std::vector<Name>>> names_;  ///< per contact, letter (alphabet index) and row
};

/// The distinct vectors' lines in order of first use, each by its index.
class VectorLines {
 public:
  std::size_t index(std::string line);
  std::vector<std::string> lines() const;

 private:
  std::unordered_map<std::string, std::size_t> index_;
  std::vector<const std::string*> lines_;
};

/// The lines of the list "dead": the tree's dead prefixes grouped by their parent, {"parent", "letters",
/// "vectors"}, each prefix naming the index (in `vectors`) of its proof's line. A tree proof moved onto any prefix it
/// proves weighs the same functionals by the same amounts (move_rows), so its line is the same on each: built once,
/// from the first prefix it proves.
std::vector<std::string> dead_lines(const SpatialModeTree& tree, const RowNames& names, VectorLines& vectors);

/// Appends `,\n "name": [`, the lines one a line, and `\n ]` (checker/certificate_lines.h's layout).
void put_lines(std::string& out, const char* name, const std::vector<std::string>& lines);

}  // namespace contactcert::solvers::spatial
