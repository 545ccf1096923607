#include "python/stability_objects.h"

#include <cmath>
#include <string>
#include <vector>

#include "exact/nearest_double.h"
#include "exact/rational_text.h"
#include "python/json_objects.h"

namespace contactcert::python {
namespace {

namespace py = pybind11;
using exact::Q;
using exact::Vec;

/// The members' names, made once and interned (never freed: they live as long as the interpreter).
struct Keys {
  py::str verdict{"verdict"}, wrench{"wrench"}, arith{"arith"}, touching_fixels{"touching_fixels"}, witness{"witness"},
      resting_forces{"resting_forces"}, resting_contacts{"resting_contacts"}, moving{"moving"}, mode{"mode"},
      forces{"forces"}, acceleration{"acceleration"}, acceleration_approx{"acceleration_approx"}, contacts{"contacts"},
      lps{"lps"}, modes_checked{"modes_checked"}, modes_kinematically_feasible{"modes_kinematically_feasible"},
      mode_tree{"mode_tree"}, nodes{"nodes"}, dead_prefixes{"dead_prefixes"}, fixel{"fixel"}, point{"point"},
      normal{"normal"}, tangent{"tangent"}, c_n{"c_n"}, c_t{"c_t"}, force{"force"}, torque{"torque"};
  Keys() {
    for (py::str* k : {&verdict,
                       &wrench,
                       &arith,
                       &touching_fixels,
                       &witness,
                       &resting_forces,
                       &resting_contacts,
                       &moving,
                       &mode,
                       &forces,
                       &acceleration,
                       &acceleration_approx,
                       &contacts,
                       &lps,
                       &modes_checked,
                       &modes_kinematically_feasible,
                       &mode_tree,
                       &nodes,
                       &dead_prefixes,
                       &fixel,
                       &point,
                       &normal,
                       &tangent,
                       &c_n,
                       &c_t,
                       &force,
                       &torque}) {
      PyObject* p = k->release().ptr();
      PyUnicode_InternInPlace(&p);
      *k = py::reinterpret_steal<py::str>(p);
    }
  }
};

const Keys& keys() {
  static const Keys* k = new Keys;  // the first call holds the GIL
  return *k;
}

void put(const py::dict& d, const py::str& key, const py::object& value) {
  if (PyDict_SetItem(d.ptr(), key.ptr(), value.ptr()) != 0) throw py::error_already_set();
}

/// exact_json(x): the rational's text.
py::str text(const Q& x) { return py::str(exact::to_string(x)); }

/// exact_json(v): the list of its entries' texts.
py::list texts(const Vec<Q>& v) {
  py::list l(static_cast<std::size_t>(v.size()));
  for (Eigen::Index i = 0; i < v.size(); ++i) PyList_SET_ITEM(l.ptr(), i, text(v(i)).release().ptr());
  return l;
}

/// approx_json(v): the nearest doubles (None where one is not finite, as json.loads reads dump()'s null).
py::list approx(const Vec<Q>& v) {
  const Vec<double> d = exact::nearest_doubles(v);
  py::list l(static_cast<std::size_t>(d.size()));
  for (Eigen::Index i = 0; i < d.size(); ++i) {
    py::object x = std::isfinite(d(i)) ? py::object(py::float_(d(i))) : py::object(py::none());
    PyList_SET_ITEM(l.ptr(), i, x.release().ptr());
  }
  return l;
}

/// contacts_json(frames, touching, c) (queries/contact_forces.h).
py::list contacts(const solvers::ForceFrames& frames, const std::vector<Eigen::Index>& touching, const Vec<Q>& c) {
  const Keys& k = keys();
  const std::vector<solvers::WorldForce<Q>> forces = frames.forces<Q>(touching, c);
  py::list l(forces.size());
  for (std::size_t i = 0; i < forces.size(); ++i) {
    const solvers::WorldForce<Q>& w = forces[i];
    py::dict d;
    put(d, k.fixel, py::int_(static_cast<std::int64_t>(w.fixel)));
    put(d, k.point, texts(w.point));
    put(d, k.normal, texts(w.normal));
    put(d, k.tangent, texts(w.tangent));
    put(d, k.c_n, text(w.c_n));
    put(d, k.c_t, text(w.c_t));
    put(d, k.force, texts(w.force));
    put(d, k.torque, text(w.torque));
    PyList_SET_ITEM(l.ptr(), static_cast<Py_ssize_t>(i), d.release().ptr());
  }
  return l;
}

/// queries::to_json of the exact answer (queries/stability_query.cpp, result_json without margin or certificate).
py::object exact_object(const queries::StabilityVerdicts& oracle, const Vec<Q>& g,
                        const solvers::StabilityResult<Q>& r) {
  const Keys& k = keys();
  py::dict j;
  put(j, k.verdict, py::str(solvers::verdict_name(r.verdict)));
  put(j, k.wrench, texts(g));
  put(j, k.arith, py::str(exact::arith_name(oracle.arith())));
  py::list touching(r.touching.size());
  for (std::size_t i = 0; i < r.touching.size(); ++i)
    PyList_SET_ITEM(touching.ptr(), static_cast<Py_ssize_t>(i),
                    py::int_(static_cast<std::int64_t>(r.touching[i])).release().ptr());
  put(j, k.touching_fixels, touching);
  py::object w = py::none();  // neither witness: JSON null
  if (r.has_resting || r.has_moving) {
    py::dict d;
    if (r.has_resting) {
      put(d, k.resting_forces, texts(r.resting_forces));
      put(d, k.resting_contacts, contacts(oracle.frames(), r.touching, r.resting_forces));
    }
    if (r.has_moving) {
      py::dict m;
      put(m, k.mode, py::str(r.moving.mode.text()));
      put(m, k.forces, texts(r.moving.forces));
      put(m, k.acceleration, texts(r.moving.acceleration));
      put(m, k.acceleration_approx, approx(r.moving.acceleration));
      put(m, k.contacts, contacts(oracle.frames(), r.touching, r.moving.forces));
      put(d, k.moving, m);
    }
    w = std::move(d);
  }
  put(j, k.witness, w);
  put(j, k.lps, py::int_(static_cast<std::int64_t>(r.lps)));
  put(j, k.modes_checked, py::int_(static_cast<std::int64_t>(r.modes_checked)));
  put(j, k.modes_kinematically_feasible, py::int_(static_cast<std::int64_t>(r.modes_kinematically_feasible)));
  py::dict tree;
  put(tree, k.nodes, py::int_(static_cast<std::int64_t>(r.tree_nodes)));
  put(tree, k.dead_prefixes, py::int_(static_cast<std::int64_t>(r.dead_prefixes)));
  put(j, k.mode_tree, tree);
  return j;
}

}  // namespace

py::object stability_object(const queries::StabilityVerdicts& oracle, const Vec<Q>& g,
                            const queries::StabilityOutcome& verdict) {
  if (const auto* r = std::get_if<solvers::StabilityResult<Q>>(&verdict)) return exact_object(oracle, g, *r);
  return json_objects(queries::to_json(oracle.answer(g, verdict)));  // the float path: its doubles through the tree
}

}  // namespace contactcert::python
