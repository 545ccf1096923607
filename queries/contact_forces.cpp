#include "queries/contact_forces.h"

#include "exact/rational_text.h"

namespace contactcert::queries {
namespace {

using exact::Q;

template <class T>
json number_json(const T& x) {
  if constexpr (std::is_same_v<T, Q>)
    return exact_json(x);
  else
    return x;
}

template <class T>
std::string number_text(const T& x) {
  if constexpr (std::is_same_v<T, Q>)
    return exact::to_string(x);
  else
    return std::to_string(x);
}

}  // namespace

template <class T>
json vector_json(const exact::Vec<T>& v) {
  if constexpr (std::is_same_v<T, Q>)
    return exact_json(v);
  else
    return approx_json(v);
}

template <class T>
json forces_json(const std::vector<solvers::WorldForce<T>>& forces, const std::string& index_key) {
  json out = json::array();
  for (const auto& w : forces)
    out.push_back({{index_key, w.fixel},
                   {"point", vector_json(w.point)},
                   {"normal", vector_json(w.normal)},
                   {"tangent", vector_json(w.tangent)},
                   {"c_n", number_json(w.c_n)},
                   {"c_t", number_json(w.c_t)},
                   {"force", vector_json(w.force)},
                   {"torque", number_json(w.torque)}});
  return out;
}

template <class T>
std::string forces_text(const std::vector<solvers::WorldForce<T>>& forces, const std::string& what,
                        const std::string& indent) {
  std::string out;
  for (const auto& w : forces)
    out += indent + what + " " + std::to_string(w.fixel) + " at " + tuple_text(w.point) + ": force " +
           tuple_text(w.force) + ", torque " + number_text(w.torque) + "  (c_n = " + number_text(w.c_n) +
           " along n = " + tuple_text(w.normal) + ", c_t = " + number_text(w.c_t) +
           " along t = " + tuple_text(w.tangent) + ")\n";
  return out;
}

template <class T>
json contacts_json(const geometry::PlanarScene& scene, const std::vector<Eigen::Index>& touching,
                   const exact::Vec<T>& c) {
  return forces_json(solvers::world_forces<T>(scene, touching, c), "fixel");
}

template <class T>
json contacts_json(const solvers::ForceFrames& frames, const std::vector<Eigen::Index>& touching,
                   const exact::Vec<T>& c) {
  return forces_json(frames.forces<T>(touching, c), "fixel");
}

template <class T>
std::string contacts_text(const geometry::PlanarScene& scene, const std::vector<Eigen::Index>& touching,
                          const exact::Vec<T>& c, const std::string& indent) {
  return forces_text(solvers::world_forces<T>(scene, touching, c), "fixel", indent);
}

namespace {

/// vdot = M^-1 (g + sum_i (f_i, torque_i)), M = diag(1, 1, I/m) (eq. 4 per unit mass).
exact::Vec<Q> acceleration(const geometry::PlanarScene& scene, const std::vector<solvers::WorldForce<Q>>& forces,
                           const exact::Vec<Q>& g) {
  exact::Vec<Q> a = g;
  for (const auto& w : forces) {
    a.head(2) += w.force;
    a(2) += w.torque;
  }
  a(2) /= scene.workpiece.inertia_per_mass;
  return a;
}

}  // namespace

json witness_json(const geometry::PlanarScene& scene, const std::vector<solvers::WorldForce<Q>>& forces,
                  const exact::Vec<Q>& g) {
  return {{"wrench", exact_json(g)},
          {"acceleration", exact_json(acceleration(scene, forces, g))},
          {"inertia_per_mass", exact_json(scene.workpiece.inertia_per_mass)},
          {"contacts", forces_json(forces, "fixel")}};
}

std::string witness_text(const geometry::PlanarScene& scene, const std::vector<solvers::WorldForce<Q>>& forces,
                         const exact::Vec<Q>& g, const std::string& indent) {
  return indent + "witness: g = " + tuple_text(g) + " has the mode with acceleration " +
         tuple_text(acceleration(scene, forces, g)) +
         " (eq. 4: M vdot = g + the contact wrenches, M = diag(1, 1, I/m), I/m = " +
         exact::to_string(scene.workpiece.inertia_per_mass) + "), contact forces (world coordinates):\n" +
         forces_text(forces, "fixel", indent + "  ");
}

json witness_json(const geometry::PlanarScene& scene, const std::vector<Eigen::Index>& touching, const exact::Vec<Q>& c,
                  const exact::Vec<Q>& g) {
  return witness_json(scene, solvers::world_forces<Q>(scene, touching, c), g);
}

std::string witness_text(const geometry::PlanarScene& scene, const std::vector<Eigen::Index>& touching,
                         const exact::Vec<Q>& c, const exact::Vec<Q>& g, const std::string& indent) {
  return witness_text(scene, solvers::world_forces<Q>(scene, touching, c), g, indent);
}

template json vector_json(const exact::Vec<Q>&);
template json vector_json(const exact::Vec<double>&);
template json forces_json(const std::vector<solvers::WorldForce<Q>>&, const std::string&);
template std::string forces_text(const std::vector<solvers::WorldForce<Q>>&, const std::string&, const std::string&);
template json contacts_json(const geometry::PlanarScene&, const std::vector<Eigen::Index>&, const exact::Vec<Q>&);
template json contacts_json(const geometry::PlanarScene&, const std::vector<Eigen::Index>&, const exact::Vec<double>&);
template json contacts_json(const solvers::ForceFrames&, const std::vector<Eigen::Index>&, const exact::Vec<Q>&);
template json contacts_json(const solvers::ForceFrames&, const std::vector<Eigen::Index>&, const exact::Vec<double>&);
template std::string contacts_text(const geometry::PlanarScene&, const std::vector<Eigen::Index>&, const exact::Vec<Q>&,
                                   const std::string&);
template std::string contacts_text(const geometry::PlanarScene&, const std::vector<Eigen::Index>&,
                                   const exact::Vec<double>&, const std::string&);

}  // namespace contactcert::queries
