// The enumerative baseline (the kind of algorithm the paper compares against, its reference [11]): every
// assignment of a contact mode to every contact -- separate, roll, slide +, slide - -- tested by one LP.
// It finds every solution mode for small nc.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "solvers/ucp/face_lp.h"
#include "solvers/ucp/search.h"

namespace contactcert::solvers::ucp {

struct EnumerateResult {
  UcpStatus status = UcpStatus::kUnknown;   ///< kUnknown if the LP budget was too small for all modes
  long lps = 0;                             ///< modes tested (one LP each)
  long solutions = 0;                       ///< modes with a complementary pair
  std::vector<std::string> solution_modes;  ///< per solution, one letter per contact: s r + -
  Vec<Q> x, y;                              ///< the pair of the first solution mode
  bool complete = true;                     ///< false if the deadline stopped the enumeration early
};

/// Tests all 4^nc contact-mode assignments of a quasistatic problem (per contact i: separate c_i = 0; roll
/// v_i = 0; slide + v_n = v_t^- = s_t^+ = 0; slide - v_n = v_t^+ = s_t^- = 0), one LP over X x Y each. For a
/// generic UCP it tests the 2^n choices of x_i = 0 or y_i = 0 (letters x y). Exact (or verified) LPs.
/// Every complementary pair of a quasistatic problem lies in some mode: v_t^+ and v_t^- can be lowered by
/// their minimum, keeping (x, y) in X and complementary.
/// The deadline (tested after every mode and before every pivot of its LP) stops the enumeration early (then
/// kSolvable if a solution mode was found, else kUnknown);
/// `progress` is called after every mode with (modes tested, LPs).
EnumerateResult enumerate_modes(const UcpProblem& problem, Arith arith, long max_lps,
                                const exact::Deadline& deadline = {},
                                const std::function<void(long, long)>& progress = {});

/// The evidence of a prefix tree's walk (solution_modes_by_prefix with `evidence`), for its certificate: each dead
/// prefix (one letter per contact, '?' for the contacts still undecided: the tree decides the last contact first,
/// so the letters are a suffix) with the side found empty and the LP's Farkas vector over that side's rows
/// (f^T A_j >= 0 on the face's columns, f^T b < 0), and per solution mode a point of its face of X and of Y.
struct PrefixEvidence {
  struct Dead {
    std::string prefix;
    bool x_side = true;
    Vec<Q> farkas;
  };
  std::vector<Dead> dead;
  std::vector<Vec<Q>> x, y;  ///< per solution mode (in solution_modes's order)
};

/// The same solution modes, in the same order, found by a prefix tree instead: depth first over the contacts (the
/// last first), a prefix fixing the letters of some contacts and relaxing the others' complementarity. Its face
/// of X x Y contains the faces of all its completions, so one LP that finds it empty prunes them all: the LPs are
/// (letters) x (non-empty prefixes), not 4^nc; X and Y by separate LPs, a side a letter leaves unchanged without
/// one. `x` and `y` are not set. kUnknown with complete = false when max_lps LPs or the deadline ran out (`lps`
/// then says how many were solved). With `evidence`, also what proves each branch (PrefixEvidence).
EnumerateResult solution_modes_by_prefix(const UcpProblem& problem, Arith arith, long max_lps,
                                         const exact::Deadline& deadline = {}, PrefixEvidence* evidence = nullptr);

}  // namespace contactcert::solvers::ucp
