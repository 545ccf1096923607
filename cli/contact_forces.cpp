#include "cli/contact_forces.h"

#include "exact/rational_text.h"
#include "solvers/stability/world_forces.h"

namespace contactcert::cli {
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
json contacts_json(const geometry::PlanarScene& scene, const std::vector<Eigen::Index>& touching,
                   const exact::Vec<T>& c) {
  json out = json::array();
  for (const auto& w : solvers::world_forces<T>(scene, touching, c))
    out.push_back({{"fixel", w.fixel},
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
std::string contacts_text(const geometry::PlanarScene& scene, const std::vector<Eigen::Index>& touching,
                          const exact::Vec<T>& c, const std::string& indent) {
  std::string out;
  for (const auto& w : solvers::world_forces<T>(scene, touching, c))
    out += indent + "fixel " + std::to_string(w.fixel) + " at " + tuple_text(w.point) + ": force " +
           tuple_text(w.force) + ", torque " + number_text(w.torque) + "  (c_n = " + number_text(w.c_n) +
           " along n = " + tuple_text(w.normal) + ", c_t = " + number_text(w.c_t) +
           " along t = " + tuple_text(w.tangent) + ")\n";
  return out;
}

template json vector_json(const exact::Vec<Q>&);
template json vector_json(const exact::Vec<double>&);
template json contacts_json(const geometry::PlanarScene&, const std::vector<Eigen::Index>&, const exact::Vec<Q>&);
template json contacts_json(const geometry::PlanarScene&, const std::vector<Eigen::Index>&, const exact::Vec<double>&);
template std::string contacts_text(const geometry::PlanarScene&, const std::vector<Eigen::Index>&, const exact::Vec<Q>&,
                                   const std::string&);
template std::string contacts_text(const geometry::PlanarScene&, const std::vector<Eigen::Index>&,
                                   const exact::Vec<double>&, const std::string&);

}  // namespace contactcert::cli
