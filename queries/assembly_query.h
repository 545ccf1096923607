// The questions on an assembly (docs/formats.md section 3a; issue 31): N movable bodies, the fixed things they touch
// and the contacts between any two. Stability from rest (solvers/assembly/assembly_stability.h: strongly stable,
// weakly stable or unstable, with a witness or a certificate) and Pang, Trinkle and Lo's quasistatic problem for N
// bodies (assembly_ucp.h: solvable with each body's velocity and every contact's world force, or jammed). Both are
// answered exactly (`--arith float` is refused; adaptive runs as verified, scene_arith).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/assembly.h"
#include "queries/json_out.h"
#include "queries/limit.h"
#include "queries/options.h"
#include "queries/ucp_uniqueness.h"
#include "solvers/assembly/assembly_stability.h"
#include "solvers/ucp/solve.h"

namespace contactcert::queries {

/// An assembly file as a query reads it: its name (for messages), its text (a certificate embeds it), the assembly.
struct AssemblyInput {
  std::string name;
  std::string text;
  geometry::Assembly assembly;
};

/// The assembly in `text` named `name`; InputError naming the file and field, `$.bodies` for a file without bodies.
AssemblyInput parse_assembly(const std::string& text, const std::string& name);
/// The assembly in the file `path` (read once), as parse_assembly.
AssemblyInput load_assembly(const std::string& path);

/// One contact's force in world coordinates: the parties, the frame (n as written, t = (-n_y, n_x)), the
/// components and f = c_n n + c_t t, which acts on `to` (its opposite on `from`).
struct AssemblyContactForce {
  std::size_t contact = 0;
  geometry::Party from, to;
  geometry::Point2 point, normal, tangent;
  exact::Q c_n, c_t;
  geometry::Point2 force;
};

/// The world forces of c = (c_1n..c_kn, c_1t..c_kt) at the assembly's contacts.
std::vector<AssemblyContactForce> assembly_forces(const geometry::Assembly& a, const exact::Vec<exact::Q>& c);
/// Per contact {"contact", "from", "to" (as in the file: {"body": i}...), "point", "normal", "tangent", "c_n",
/// "c_t", "force"}, exact strings.
json assembly_forces_json(const std::vector<AssemblyContactForce>& forces);
/// One line per contact, each starting with `indent`.
std::string assembly_forces_text(const std::vector<AssemblyContactForce>& forces, const std::string& indent);

/// `contactcert assembly FILE`: stability from rest under the bodies' loads.
struct AssemblyStabilityOptions {
  CommonOptions common;
  long max_nodes = solvers::assembly::AssemblyStabilityOptions{}.max_nodes;  ///< prefixes the walk visits at most
  std::string certificate;  ///< the "assembly_stability" certificate's file ("" = none)
  std::string svg;          ///< the picture's file ("" = none)
};

struct AssemblyStabilityAnswer {
  solvers::assembly::AssemblyStabilityResult result;
  exact::Arith arith = exact::Arith::kVerified;
  std::size_t bodies = 0, contacts = 0;
  std::vector<AssemblyContactForce> resting, moving;  ///< the witnesses' world forces (empty without one)
  std::string certificate, svg;                       ///< the files written ("" = none)
  std::string certificate_text;                       ///< the certificate written ("" = none)
  /// A verdict was reached (else a budget ran out first: exit 3 with `result.covered`).
  bool decided() const { return result.status == solvers::assembly::AssemblyStatus::kDecided; }
};

/// Runs the walk under the options' budgets (ending it `unknown` with what it covered), writes the certificate
/// (decided verdicts only) and the picture.
Limited<AssemblyStabilityAnswer> run_assembly_stability(const AssemblyInput& in,
                                                        const AssemblyStabilityOptions& options);
/// The Limit of an undecided walk (its status, e.g. node_limit, and what it covered), which `assembly` reports in
/// place of the answer; nullopt for a verdict.
std::optional<Limit> limit_of(const AssemblyStabilityAnswer& answer);
/// {"verdict" (or "unknown"), "status", "arith", "bodies", "contacts", "witness": {"resting", "moving"},
/// "search": {"nodes", "lps", "dead_prefixes"}, "covered", "certificate", "svg"}.
json to_json(const AssemblyStabilityAnswer& answer);
/// The readable report of the answer (what `contactcert assembly FILE` prints without --json).
std::string to_text(const AssemblyStabilityAnswer& answer, const std::string& name);

/// `contactcert assembly FILE --ucp`: the quasistatic problem of a quasistatic_scene with bodies.
struct AssemblyUcpOptions {
  CommonOptions common;
  long max_nodes = solvers::ucp::UcpOptions{}.max_nodes;  ///< the complete search's node budget (as `ucp`)
  long max_bases = solvers::ucp::UcpOptions{}.max_bases;  ///< Step 3's bases per degenerate vertex (as `ucp`)
  std::string certificate;  ///< the ucp_solvable / ucp_jammed certificate's file ("" = none)
  std::string svg;          ///< the picture's file, with the contact forces of a solution ("" = none)
  /// `ucp ASSEMBLY --all`: is the bodies' motion unique?
  UniquenessOptions uniqueness;
  /// The command the user ran (`assembly FILE --ucp` or `ucp FILE`): it names the run in a budget's message.
  enum class Command { kAssembly, kUcp } command = Command::kAssembly;
};

/// The command that ran, as its messages name it: `assembly`, or `ucp` for `ucp ASSEMBLY`.
inline std::string command_name(const AssemblyStabilityOptions&) { return "assembly"; }
inline std::string command_name(const AssemblyUcpOptions& o) {
  return o.command == AssemblyUcpOptions::Command::kUcp ? "ucp" : "assembly";
}

/// Body b's velocity: q_dot_b = (v_x, v_y, omega) of the body point at the world origin (torques about the origin,
/// eq. (1)) and its com's velocity (v_x - omega c_y, v_y + omega c_x).
struct BodyVelocity {
  exact::Vec<exact::Q> q_dot;
  geometry::Point2 com_velocity;
};

struct AssemblyUcpAnswer {
  solvers::ucp::UcpReport report;
  std::vector<BodyVelocity> bodies;          ///< solvable: per body
  std::vector<AssemblyContactForce> forces;  ///< solvable: per contact
  std::string certificate;                   ///< the file written ("" = none: not asked, or unknown)
  std::string certificate_text;              ///< its text
  std::string svg;                           ///< the picture written ("" = none)
  /// with uniqueness.all and a decided verdict: is its motion unique (no_motion when jammed)?
  std::optional<UniquenessAnswer> uniqueness;
};

/// Builds P, Jn, Jt, d for the N bodies, solves (complete search), recovers the physics and writes the files.
Limited<AssemblyUcpAnswer> run_assembly_ucp(const AssemblyInput& in, const AssemblyUcpOptions& options);
/// {"status", "reason", "arith", "bodies": [{"body", "q_dot", "com_velocity"}], "contacts": [...], "theta_dot",
/// "tau", "conditions_2_to_10", "pairs", "lps", "nodes", "certificate", "svg", "uniqueness"}.
json to_json(const AssemblyUcpAnswer& answer);
std::string to_text(const AssemblyUcpAnswer& answer, const std::string& name);

}  // namespace contactcert::queries
