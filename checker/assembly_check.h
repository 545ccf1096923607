// The independent checker of assembly stability verdicts. It trusts nothing from the solver: it re-verifies every
// contact frame against the shapes, derives the relative accelerations itself from the motion of the contact point
// on each body (acc(p) = (a_x - alpha (p - com)_y, a_y + alpha (p - com)_x) from rest; a_n = n . (acc_to(p) -
// acc_from(p)), a_t likewise with t = perp(n)) and the Newton-Euler rows from the forces' action on each body
// (c_n n + c_t t on `to`, its opposite on `from`, torque about each com), and rebuilds every system in the layout of
// assembly_system.h (docs/formats.md, section 5a) with its own code (not assembly_system.h's).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "checker/table2_rows.h"
#include "exact/json_input.h"
#include "geometry/assembly.h"
#include "solvers/assembly/assembly_stability.h"

namespace contactcert::checker {

/// "" if every contact's frame is right (its point on both parties' boundaries, or a point party's position; its
/// normal a common normal from `from` into `to`), else which contact's is not.
std::string assembly_frames_violation(const geometry::Assembly& a);

/// "" if `claim` is a valid decided verdict for assembly `a` with valid evidence, else why not:
///   strongly_stable: a resting solution, no moving one, and dead prefixes that cover every mode over s l r n, each
///     with a Motzkin certificate of its system (the energy row included: assembly_system.h says why it is valid);
///   weakly_stable: a resting solution and a moving solution (some body's acceleration non-zero);
///   unstable: a Motzkin certificate of the resting system (and a moving solution, if one is given, valid).
std::string check_assembly_stability(const geometry::Assembly& a,
                                     const solvers::assembly::AssemblyStabilityResult& claim);

/// Why (vdot, c) is not a moving solution of `mode` (s l r n per contact) for assembly a, or "".
std::string assembly_motion_violation(const geometry::Assembly& a, const solvers::assembly::AssemblyMotion& m);

struct AssemblyCertificateCheck {
  bool valid = false;
  std::string reason;
  std::size_t bodies = 0, contacts = 0, dead = 0;  ///< of the embedded assembly and the evidence
};

/// Verifies an "assembly_stability" certificate (its format: solvers/assembly/assembly_certificate.h): the digest,
/// then the evidence by check_assembly_stability, each dead prefix listed once. A malformed certificate (an unknown
/// key, a bad vector or prefix) throws InputError naming the field.
AssemblyCertificateCheck check_assembly_certificate(const exact::JsonInput& certificate);

/// The checker's relative accelerations, for the assembly's other checkers (assembly_modes_check.h): per contact the
/// coefficients of a_n and of a_t on vdot (3N columns, body by body), from frames re-verified against the shapes;
/// `violation` names the first wrong frame ("" if none, and then `rows` is filled).
struct CheckedAccelerations {
  std::string violation;
  std::vector<std::array<std::vector<table2_check::Rows::Entry>, 2>> rows;
};
CheckedAccelerations checked_accelerations(const geometry::Assembly& a);

}  // namespace contactcert::checker
