// Contact forces as a person reads them: each touching fixel's force as a world vector with its torque, and the
// components c_n, c_t against the frame (n_i, t_i) stated beside them (solvers/stability/world_forces.h), for
// the reports of `stability` and `cone`, the certificates they write and `check`'s view of them.
#pragma once

#include <string>
#include <vector>

#include "geometry/planar_scene.h"
#include "queries/json_out.h"
#include "solvers/stability/world_forces.h"

namespace contactcert::queries {

/// A vector as exact strings (T = Q) or doubles.
template <class T>
json vector_json(const exact::Vec<T>& v);

/// Per force, `index_key` (its index), `point`, `normal`, `tangent`, `c_n`, `c_t`, `force`, `torque`: exact
/// strings (T = Q) or doubles.
template <class T>
json forces_json(const std::vector<solvers::WorldForce<T>>& forces, const std::string& index_key);

/// One line per force, each starting with `indent`: "<what> i at (x, y): force (fx, fy), torque tau (c_n = ..
/// along n = (..), c_t = .. along t = (..))".
template <class T>
std::string forces_text(const std::vector<solvers::WorldForce<T>>& forces, const std::string& what,
                        const std::string& indent);

/// Per touching fixel `fixel`, `point`, `normal`, `tangent`, `c_n`, `c_t`, `force`, `torque`: exact strings
/// (T = Q) or doubles. `c` is the model's vector (c_1n..c_kn, c_1t..c_kt) of the fixels `touching`.
template <class T>
json contacts_json(const geometry::PlanarScene& scene, const std::vector<Eigen::Index>& touching,
                   const exact::Vec<T>& c);
/// The same from the scene's force frames, prepared once for many answers.
template <class T>
json contacts_json(const solvers::ForceFrames& frames, const std::vector<Eigen::Index>& touching,
                   const exact::Vec<T>& c);

/// One line per touching fixel, each starting with `indent`: "fixel i at (x, y): force (fx, fy), torque tau
/// (c_n = .. along n = (..), c_t = .. along t = (..))".
template <class T>
std::string contacts_text(const geometry::PlanarScene& scene, const std::vector<Eigen::Index>& touching,
                          const exact::Vec<T>& c, const std::string& indent);

/// A wrench cone witness as a person reads it: the wrench g, the workpiece's acceleration
/// vdot = M^-1 (g + sum_i (f_i, torque_i)) (eq. 4 per unit mass, M = diag(1, 1, I/m)), I/m, and the world forces
/// of the contact forces c of the fixels `touching`: {"wrench", "acceleration", "inertia_per_mass", "contacts"}.
json witness_json(const geometry::PlanarScene& scene, const std::vector<Eigen::Index>& touching,
                  const exact::Vec<exact::Q>& c, const exact::Vec<exact::Q>& g);

/// The same as lines of text, each starting with `indent`.
std::string witness_text(const geometry::PlanarScene& scene, const std::vector<Eigen::Index>& touching,
                         const exact::Vec<exact::Q>& c, const exact::Vec<exact::Q>& g, const std::string& indent);

/// The same two from the world forces `forces` of the witness (check's views: the checker's own,
/// checker/world_forces.h).
json witness_json(const geometry::PlanarScene& scene, const std::vector<solvers::WorldForce<exact::Q>>& forces,
                  const exact::Vec<exact::Q>& g);
std::string witness_text(const geometry::PlanarScene& scene, const std::vector<solvers::WorldForce<exact::Q>>& forces,
                         const exact::Vec<exact::Q>& g, const std::string& indent);

}  // namespace contactcert::queries
