// The Python module `linkage` (docs/python.md): the solver's answers as numpy arrays, lists and
// dicts; a mechanism's problems as Python exceptions carrying the solver's message (ValueError
// for bad input, linkage.MotionError for a crank angle the mechanism cannot reach).
#include <dlfcn.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "linkage/elements.h"
#include "linkage/space.h"
#include "py_model.h"

namespace py = pybind11;
using linkage::py::Model;

namespace {

// This module's own file, which finds the examples installed beside it (py_model.cpp).
std::string modulePath() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&modulePath), &info) == 0 || !info.dli_fname) return {};
  return info.dli_fname;
}

// A path as str or any os.PathLike (pathlib.Path), as Python's own open() takes it.
std::string fspath(const py::object& path) {
  return py::str(py::module_::import("os").attr("fspath")(path));
}

py::tuple pair(const linkage::Vec2& v) {
  return py::make_tuple(v.x(), v.y());
}
py::tuple triple(const linkage::Vec3& v) {
  return py::make_tuple(v.x(), v.y(), v.z());
}

py::array_t<double> analyze(const Model& m, long long steps, double revs, double rpm,
                            const std::vector<std::string>& points) {
  linkage::py::Table t;
  {
    // A copy, taken while the GIL is held: another thread may edit `m` meanwhile.
    const Model snapshot = m;
    py::gil_scoped_release free;
    t = snapshot.analyze(steps, revs, rpm, points);
  }
  const auto cols = static_cast<py::ssize_t>(t.columns.size());
  py::array_t<double> a({static_cast<py::ssize_t>(t.rows()), cols});
  std::copy(t.values.begin(), t.values.end(), a.mutable_data());
  return a;
}

py::array_t<double> sweep(const Model& m, const std::string& point,
                          const py::array_t<double, py::array::c_style | py::array::forcecast>& in,
                          double rpm) {
  if (in.ndim() != 1) throw py::value_error("sweep: angles must be a one-dimensional array");
  const auto n = static_cast<size_t>(in.shape(0));
  py::array_t<double> out(
      {static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(m.sweepColumns())});
  const double* a = in.data();
  double* o = out.mutable_data();
  {
    // A long loop of pure C++: other Python threads run meanwhile. On a copy taken while the
    // GIL is held, as another thread may edit `m`; `in` and `out` are kept alive by the caller.
    const Model snapshot = m;
    py::gil_scoped_release free;
    snapshot.sweep(point, a, n, rpm, o);
  }
  return out;
}

py::list centres(const Model& m, double crankDeg) {
  const linkage::InstantCentres c = m.instantCentres(crankDeg);
  const linkage::Mechanism& d = m.design();
  py::list out;
  for (const linkage::InstantCentre& ic : c.centres) {
    py::dict e;
    e["i"] = ic.i;
    e["j"] = ic.j;
    e["body_i"] = d.body(ic.bodyI)->name;
    e["body_j"] = d.body(ic.bodyJ)->name;
    e["determined"] = ic.determined;
    e["at_infinity"] = ic.atInfinity();
    e["status"] = linkage::toString(ic.status);
    // The keys of `linkage-cli ics --json`.
    if (ic.determined && !ic.atInfinity()) {
      e["x_mm"] = ic.point().x();
      e["y_mm"] = ic.point().y();
    }
    if (ic.atInfinity()) {
      e["dir_x"] = ic.direction().x();
      e["dir_y"] = ic.direction().y();
    }
    out.append(e);
  }
  return out;
}

py::dict reaction(const linkage::Mechanism& d, const linkage::Joint& j,
                  const linkage::JointReaction& r) {
  py::dict e;
  e["joint"] = linkage::jointLabel(d, j.id);
  e["force_N"] = pair(r.force);
  e["at_mm"] = pair(r.at);
  e["couple_Nm"] = r.coupleNm;
  e["normal_N"] = r.normalN;
  e["tilt_Nm"] = pair(r.tiltNm);
  e["axial_N"] = r.axialN;
  e["transmitted_Nm"] = r.transmittedNm;
  e["contact_N"] = r.contactN;
  return e;
}

py::dict forces(const Model& m, double crankDeg, double rpm) {
  const linkage::Forces f = m.forces(crankDeg, rpm);
  const linkage::Mechanism& d = m.design();
  py::dict out;
  out["crank_deg"] = f.crankDeg;
  out["driver_torque_Nm"] = f.driverTorqueNm;
  out["shaking_force_N"] = pair(f.shakingForceN);
  out["shaking_moment_Nm"] = f.shakingMomentNm;
  out["shaking_force_3d_N"] = triple(f.shakingForce3N);
  out["shaking_moment_3d_Nm"] = triple(f.shakingMoment3Nm);
  py::list joints, undetermined;
  for (size_t i = 0; i < f.joints.size() && i < d.joints.size(); ++i)
    joints.append(reaction(d, d.joints[i], f.joints[i]));
  for (linkage::JointId j : f.undetermined) undetermined.append(linkage::jointLabel(d, j));
  out["joints"] = joints;
  out["undetermined"] = undetermined;
  return out;
}

// A planar machine's (dx, dy); a machine in space's (dx, dy, dz) in the world.
py::dict sensitivity(const Model& m, const std::string& point, double crankDeg,
                     const std::string& quantity, double rpm) {
  const int q = quantity == "position"       ? 0
                : quantity == "velocity"     ? 1
                : quantity == "acceleration" ? 2
                                             : -1;
  if (q < 0)
    throw py::value_error("quantity: position, velocity or acceleration, not '" + quantity + "'");
  const bool space = linkage::isSpatial(m.design());
  py::dict out;
  for (const auto& [name, d] : m.sensitivity(point, crankDeg, q, rpm))
    out[py::str(name)] = space ? py::make_tuple(d.x(), d.y(), d.z()) : pair(d.head<2>());
  return out;
}

py::dict strokeSensitivity(const Model& m, const std::string& point, const std::string& direction) {
  py::dict out;
  for (const auto& [name, d] : m.strokeSensitivity(point, direction)) out[py::str(name)] = d;
  return out;
}

py::dict forceSensitivity(const Model& m, const std::string& joint, double crankDeg, double rpm) {
  py::dict out;
  for (const auto& [name, d] : m.forceSensitivity(joint, crankDeg, rpm))
    out[py::str(name)] = py::tuple(py::cast(d));
  return out;
}

py::dict shakingSensitivity(const Model& m, double crankDeg, double rpm) {
  py::dict out;
  for (const auto& [name, d] : m.shakingSensitivity(crankDeg, rpm))
    out[py::str(name)] = py::tuple(py::cast(d));
  return out;
}

py::dict dimensions(const Model& m) {
  py::dict out;
  for (const auto& [name, v] : m.dimensions()) out[py::str(name)] = v;
  return out;
}

// vary: {name: (lo, hi)} in its own order; the answer as linkage-cli optimize's table says it.
py::dict optimize(Model& m, const py::dict& vary, const std::vector<std::string>& targets,
                  int starts, std::uint64_t seed, int steps, bool apply) {
  std::vector<Model::Bounds> bounds;
  for (const auto& [name, b] : vary) {
    const auto lohi = b.cast<std::pair<double, double>>();
    bounds.push_back({name.cast<std::string>(), lohi.first, lohi.second});
  }
  const Model::Optimized o = m.optimize(bounds, targets, starts, seed, steps, apply);
  const linkage::OptimizeResult& r = o.result;
  py::dict out, variables, measures, kg;
  for (size_t i = 0; i < bounds.size(); ++i)
    variables[py::str(bounds[i].name)] = py::make_tuple(r.before[i], r.after[i]);
  auto measure = [](const linkage::Evaluation& e, size_t t) {
    return e.feasible && t < e.measures.size() ? py::cast(e.measures[t]) : py::none();
  };
  for (size_t t = 0; t < targets.size(); ++t)
    measures[py::str(targets[t])] = py::make_tuple(measure(r.atBefore, t), measure(r.atAfter, t));
  for (const linkage::Counterweight& c : r.counterweights)
    kg[py::str(r.design.body(c.body)->name)] = c.kg;
  out["variables"] = variables;
  out["targets"] = measures;
  out["counterweights_kg"] = kg;
  out["objective"] = py::make_tuple(
      r.atBefore.feasible ? py::cast(r.atBefore.objective) : py::none(), r.atAfter.objective);
  out["starts"] = r.starts;
  out["starts_infeasible"] = r.infeasibleStarts;
  out["starts_found_best"] = r.foundBest;
  return out;
}

}  // namespace

PYBIND11_MODULE(linkage, mod) {
  mod.doc() =
      "The linkage solver: mechanisms' exact motion, instant centres, forces and "
      "sensitivities (docs/python.md)";
  mod.attr("__version__") = LINKAGE_VERSION;
  py::register_exception<linkage::py::MotionFailure>(mod, "MotionError", PyExc_RuntimeError);
  mod.def(
      "load", [](const py::object& name) { return Model::open(fspath(name), modulePath()); },
      py::arg("model"), "A .linkage.json file or an example's name, as linkage-cli opens it");
  mod.def(
      "examples", [] { return linkage::py::examples(modulePath()); }, "The examples' names");
  py::class_<Model>(mod, "Model")
      .def_property_readonly("path", &Model::source)
      .def_property_readonly("name", [](const Model& m) { return m.design().name; })
      .def_property_readonly("points", &Model::points)
      .def_property_readonly("bodies", &Model::bodies)
      .def_property_readonly("dimensions", &dimensions)
      .def("analyze", &analyze, py::arg("steps") = 360, py::arg("revs") = 1.0, py::arg("rpm") = 0.0,
           py::arg("points") = std::vector<std::string>{})
      .def("columns", &Model::columns, py::arg("points") = std::vector<std::string>{})
      .def("sweep", &sweep, py::arg("point"), py::arg("angles"), py::arg("rpm") = 0.0)
      .def("instant_centres", &centres, py::arg("crank_deg"))
      .def("forces", &forces, py::arg("crank_deg"), py::arg("rpm") = 0.0)
      .def("sensitivity", &sensitivity, py::arg("point"), py::arg("crank_deg"),
           py::arg("quantity") = "position", py::arg("rpm") = 0.0)
      .def("stroke_sensitivity", &strokeSensitivity, py::arg("point"), py::arg("direction") = "")
      .def("shaking_sensitivity", &shakingSensitivity, py::arg("crank_deg"), py::arg("rpm") = 0.0)
      .def("force_sensitivity", &forceSensitivity, py::arg("joint"), py::arg("crank_deg"),
           py::arg("rpm") = 0.0)
      .def("side_lengths", &Model::sideLengths, py::arg("body"))
      .def("set_side_lengths", &Model::setSideLengths, py::arg("body"), py::arg("lengths"))
      .def("set_point", &Model::setPoint, py::arg("point"), py::arg("x"), py::arg("y"))
      .def("set_dimension", &Model::setDimension, py::arg("name"), py::arg("value"))
      .def("optimize", &optimize, py::arg("vary"), py::arg("targets"), py::arg("starts") = 16,
           py::arg("seed") = 1, py::arg("steps") = 360, py::arg("apply") = false)
      .def(
          "save", [](const Model& m, const py::object& path) { m.save(fspath(path)); },
          py::arg("path"));
}
