// The independent checker of assembly stability verdicts. It trusts nothing from the solver: it re-verifies every
// contact frame against the shapes, derives the relative accelerations itself from the motion of the contact point
// on each body (acc(p) = (a_x - alpha (p - com)_y, a_y + alpha (p - com)_x) from rest; a_n = n . (acc_to(p) -
// acc_from(p)), a_t likewise with t = perp(n)) and the Newton-Euler rows from the forces' action on each body
// (c_n n + c_t t on `to`, its opposite on `from`, torque about each com), and rebuilds every system in the layout of
// assembly_system.h (docs/formats.md, section 5a) with its own code (not assembly_system.h's).
#pragma once

#include <string>

#include "geometry/assembly.h"
#include "solvers/assembly/assembly_stability.h"

namespace contactcert::solvers::assembly {

/// "" if `claim` is a valid decided verdict for assembly `a` with valid evidence, else why not:
///   strongly_stable: a resting solution, no moving one, and dead prefixes that cover every mode over s l r n, each
///     with a Motzkin certificate of its system (the energy row included: assembly_system.h says why it is valid);
///   weakly_stable: a resting solution and a moving solution (some body's acceleration non-zero);
///   unstable: a Motzkin certificate of the resting system (and a moving solution, if one is given, valid).
std::string check_assembly_stability(const geometry::Assembly& a, const AssemblyStabilityResult& claim);

/// Why (vdot, c) is not a moving solution of `mode` (s l r n per contact) for assembly a, or "".
std::string assembly_motion_violation(const geometry::Assembly& a, const AssemblyMotion& m);

}  // namespace contactcert::solvers::assembly
