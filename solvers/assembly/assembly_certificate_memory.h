// Reuse of a dead prefix's certificate on later prefixes of the stability walk (assembly_stability.h). A Motzkin
// vector y of one prefix's system weighs its rows, and every row has a label that means the same in every prefix's
// system (AssemblySystem::row_label: the energy row, a contact's kinematic and friction rows, a body's Newton-Euler
// rows). Carried by those labels onto the system of another prefix (zero on the rows the first one lacks), y is
// checked there exactly against Motzkin's conditions (strict_feasibility.h); where they hold, that prefix is dead
// without an LP. They often do: the certificate of a local contradiction (one body pushed against its friction,
// say) weighs the rows of a few contacts and bodies only, and the contradiction recurs under every choice of the
// letters of the contacts before them.
#pragma once

#include <deque>
#include <optional>
#include <utility>
#include <vector>

#include "solvers/assembly/assembly_system.h"

namespace contactcert::solvers::assembly {

/// Whether y is a Motzkin certificate of s (A x = b with its signs): (y^T A)_j = 0 on free columns, >= 0 on the
/// others, y^T b <= 0, and y^T b < 0 or (y^T A)_j > 0 on a strict column.
bool motzkin_holds(const AssemblySystem& s, const Vec<Q>& y);

/// A non-zero entry of a vector y over a system's rows, with its value in doubles.
struct Multiplier {
  Eigen::Index row;
  const Q* value;
  double approx;
};

/// motzkin_holds for many y on one system, each given by its non-zero entries: the entries of A are sorted by row
/// once, and a test reads only the rows of y's support (a certificate of a local contradiction weighs few). It first
/// computes y^T A and y^T b in doubles and rejects y where a sign condition fails by far more than their rounding
/// error (1e-9 of the sum of the terms' magnitudes); only a y that passes is checked exactly, which decides.
class MotzkinTest {
 public:
  explicit MotzkinTest(const AssemblySystem& s);  ///< s must outlive the test
  bool holds(const std::vector<Multiplier>& y);

 private:
  bool plausible(const std::vector<Multiplier>& y);
  const AssemblySystem& s_;
  std::vector<std::size_t> start_, order_;  ///< row r's entries: entries[order_[start_[r] .. start_[r + 1])]
  std::vector<double> approx_;              ///< the entries in doubles, NaN until first read
  std::vector<Q> yA_;                       ///< scratch, zero between tests
  Q product_;                               ///< scratch: y_i a_ij, its limbs reused (no allocation per entry)
  std::vector<double> yA_approx_, magnitude_;
  std::vector<Eigen::Index> touched_;  ///< the columns of yA_ a test wrote
};

/// The certificates of the latest dead prefixes, a few per prefix length, by row label.
class CertificateMemory {
 public:
  explicit CertificateMemory(std::size_t per_length = 8) : per_length_(per_length) {}
  /// A certificate of s (the system of a prefix of `length` letters) carried from a remembered one, or nullopt.
  /// One that holds moves to the front of its length's list.
  std::optional<Vec<Q>> recall(const AssemblySystem& s, std::size_t length);
  /// Keeps y, a certificate of s, at the front of its length's list (the oldest beyond per_length is dropped).
  void remember(const AssemblySystem& s, std::size_t length, const Vec<Q>& y);

 private:
  struct Weight {
    Eigen::Index label;
    Q value;
    double approx;
  };
  using Labelled = std::vector<Weight>;  ///< the non-zero multipliers by row label
  std::size_t per_length_;
  std::vector<std::deque<Labelled>> by_length_;
  std::vector<Eigen::Index> row_of_label_;  ///< scratch: the row of each label in the system at hand, or -1
};

}  // namespace contactcert::solvers::assembly
