// Every kinematically feasible contact mode of an assembly from rest (issue 31; Balkcom-Trinkle Table 2 for N bodies).
// The relative accelerations of contact i are linear in the 3N body accelerations vdot = (vdot_0, ..., vdot_{N-1}):
// a_in = sum_b w^b_in . vdot_b and a_it = sum_b w^b_it . vdot_b (assembly_system.h, eq. 6 from rest), so they are
// J^T vdot for the 3N x 2k matrix J whose column i holds the w^b_in and column k + i the w^b_it, body by body. The
// single-body mode tree (solvers/stability/mode_tree.h) walks that J as it walks one workpiece's: each feasible mode
// with an acceleration that realises it, each dead prefix with a Motzkin certificate of its kinematic rows
// (kinematic_system, here on 3N columns), and the output-sensitive bound of mode_tree.h with 2i planes through the
// origin of R^3N. Every contact touches, so the letters are Table 2's s l r n (s strict: a_n > 0).
#pragma once

#include <string>

#include "geometry/assembly.h"
#include "solvers/assembly/assembly_system.h"
#include "solvers/stability/contact_modes.h"

namespace contactcert::solvers::assembly {

/// The feasible modes of an assembly with a witness each, and the tree that proves the list complete.
struct AssemblyModes {
  ModeAlphabet alphabet;  ///< s l r n at every contact
  MotionModel<Q> model;   ///< J (3N x 2k) as above; the tree reads nothing else
  ModeTree<Q> tree;       ///< modes, accelerations (3N each, body by body) and the dead prefixes
};

/// J of the assembly's model: J(3b + d, i) = w^b_in[d], J(3b + d, k + i) = w^b_it[d] (zero for a body off contact i).
MotionModel<Q> assembly_motion_model(const AssemblyModel& model);

AssemblyModes assembly_modes(const geometry::Assembly& a, const ModeTreeOptions& options = {});

/// The "assembly_modes" certificate (docs/formats.md section 5a): the assembly text, every mode with its
/// acceleration, every dead prefix with its Motzkin certificate (sparse, sparse_motzkin.h); its checker is
/// checker/assembly_modes_check.h.
std::string assembly_modes_certificate(const std::string& scene_text, const AssemblyModes& modes);

}  // namespace contactcert::solvers::assembly
