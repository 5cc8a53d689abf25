#include "py_model.h"

#include <cmath>
#include <filesystem>

#include "linkage/edits.h"
#include "linkage/elements.h"
#include "linkage/force_sensitivity.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "linkage/limits.h"
#include "linkage/optimize_text.h"
#include "linkage/sensitivity.h"
#include "linkage/shaking_sensitivity.h"
#include "linkage/space.h"
#include "linkage/stroke_sensitivity.h"
#include "linkage/tables/force_table.h"
#include "linkage/tables/motion_table.h"

namespace linkage::py {

namespace {

// The command line's split of a status (app/cli_common.cpp, exitFor): what the crank cannot
// reach is not bad input.
bool motionFailure(const Status& s) {
  return s.code == StatusCode::Unreachable || s.code == StatusCode::Singular ||
         s.code == StatusCode::NotConverged;
}

// The header of the motion table split at its commas (names hold none: the reader refuses them).
std::vector<std::string> splitColumns(const std::string& header) {
  std::vector<std::string> out;
  size_t from = 0;
  for (size_t comma; (comma = header.find(',', from)) != std::string::npos; from = comma + 1)
    out.push_back(header.substr(from, comma - from));
  out.push_back(header.substr(from));
  return out;
}

// The examples installed with the module: <prefix>/lib/python3/dist-packages/linkage*.so finds
// <prefix>/share/linkage/examples, as <prefix>/bin/linkage-cli does (linkage/io/model_lookup.h
// looks in ../share next to the program's path given).
std::string programPathFor(const std::string& modulePath) {
  if (modulePath.empty()) return {};
  namespace fs = std::filesystem;
  const fs::path prefix = fs::path(modulePath).parent_path() / ".." / ".." / "..";
  return (prefix / "bin" / "python").lexically_normal().string();
}

}  // namespace

void raise(const Status& s) {
  if (s.ok()) return;
  if (motionFailure(s)) throw MotionFailure(s.message);
  throw BadInput(s.message);
}

std::vector<std::string> examples(const std::string& modulePath) {
  return listExamples(programPathFor(modulePath));
}

Model Model::open(const std::string& nameOrPath, const std::string& modulePath) {
  const std::string program = programPathFor(modulePath);
  std::optional<std::string> path = resolveModel(nameOrPath, program);
  if (!path) {
    std::string msg = nameOrPath + ": no such file, and no example of that name";
    const std::vector<std::string> names = listExamples(program);
    if (!names.empty()) {
      msg += " (examples:";
      for (const std::string& n : names) msg += " " + n;
      msg += ")";
    }
    throw BadInput(msg);
  }
  LoadResult r = loadMechanismFile(*path);
  if (!r.mechanism) throw BadInput(r.error);
  if (!r.mechanism->driver)
    throw BadInput(nameOrPath +
                   ": the mechanism has no driver: add \"driver\": {\"joint\": <pin index>, ...}");
  Model m;
  m.source_ = *path;
  m.design_ = std::move(*r.mechanism);
  raise(m.base_.load(m.design_));
  return m;
}

std::vector<std::string> Model::points() const {
  std::vector<std::string> out;
  for (const Body& b : design_.bodies)
    for (const Point& p : design_.points)
      if (p.body == b.id) out.push_back(design_.pointLabel(p.id));
  return out;
}

std::vector<std::string> Model::bodies() const {
  std::vector<std::string> out;
  for (const Body& b : design_.bodies) out.push_back(b.name);
  return out;
}

PointId Model::pointNamed(const std::string& label) const {
  if (std::optional<PointId> id = design_.findPoint(label)) return *id;
  const size_t dot = label.rfind('.');
  if (dot == std::string::npos) throw BadInput("point " + label + ": expected body.point");
  const std::string body = label.substr(0, dot);
  if (!design_.bodyNamed(body)) throw BadInput("point " + label + ": no body \"" + body + "\"");
  throw BadInput("point " + label + ": no point \"" + label.substr(dot + 1) + "\" on body \"" +
                 body + "\"");
}

BodyId Model::bodyNamed(const std::string& name) const {
  if (const Body* b = design_.bodyNamed(name)) return b->id;
  throw BadInput("no body \"" + name + "\"");
}

std::vector<PointId> Model::outputPoints(const std::vector<std::string>& names) const {
  if (names.empty() && design_.outputs.empty())
    throw BadInput("the model names no output points: give one or more points");
  if (names.empty()) return design_.outputs;
  std::vector<PointId> out;
  for (const std::string& n : names) out.push_back(pointNamed(n));
  return out;
}

std::vector<std::string> Model::columns(const std::vector<std::string>& names) const {
  return splitColumns(motionTableHeader(design_, outputPoints(names)));
}

Kinematics Model::at(double crankDeg, double rpm) const {
  if (!std::isfinite(crankDeg)) throw BadInput("the crank angle is not a finite number");
  if (!(rpm >= 0 && std::isfinite(rpm))) throw BadInput("rpm must be positive");
  Kinematics k = base_;
  if (rpm > 0) k.setRpm(rpm);
  raise(k.moveTo(crankDeg));
  return k;
}

Table Model::analyze(long long steps, double revs, double rpm,
                     const std::vector<std::string>& names) const {
  MotionTableSpec spec;
  spec.steps = steps;
  spec.revs = revs;
  spec.rpm = rpm;
  if (!(rpm >= 0 && std::isfinite(rpm))) throw BadInput("analyze: rpm must be positive");
  const long long rows = motionTableRows(spec);
  if (rows < 0)
    throw BadInput("analyze: steps times revs must be a positive whole number of steps");
  if (rows > 50'000'000)  // linkage-cli analyze's limit
    throw BadInput("analyze: " + std::to_string(rows) +
                   " rows is more than the 50000000 a table holds; use fewer steps or revolutions");
  spec.points = outputPoints(names);
  Kinematics k = base_;
  raise(k.checkDetermined(spec.points));
  if (rpm > 0) k.setRpm(rpm);
  Table t;
  t.columns = splitColumns(motionTableHeader(design_, spec.points));
  t.values.reserve(static_cast<size_t>(rows) * t.columns.size());
  const bool spatial = isSpatial(design_);
  for (long long i = 0; i < rows; ++i) {
    // The angle and t as sweepMotionTable and motionTableRow compute them.
    const double crank = static_cast<double>(i) * 360.0 / static_cast<double>(spec.steps);
    raise(k.moveTo(crank));
    t.values.push_back(crank / (6.0 * k.rpm()));
    t.values.push_back(crank);
    for (PointId p : spec.points) {
      if (spatial) {
        const Kinematics::PointMotion3 m = k.motionInSpace(p);
        for (const Vec3* v : {&m.position, &m.velocity, &m.acceleration})
          for (int c = 0; c < 3; ++c) t.values.push_back((*v)[c]);
        continue;
      }
      const Kinematics::PointMotion m = k.motion(p);
      for (double v : {m.position.x(), m.position.y(), m.velocity.x(), m.velocity.y(),
                       m.acceleration.x(), m.acceleration.y()})
        t.values.push_back(v);
    }
  }
  return t;
}

int Model::sweepColumns() const {
  return isSpatial(design_) ? 9 : 6;
}

void Model::sweep(const std::string& point, const double* angles, size_t n, double rpm,
                  double* out) const {
  const PointId p = pointNamed(point);
  if (!(rpm >= 0 && std::isfinite(rpm))) throw BadInput("sweep: rpm must be positive");
  Kinematics k = base_;
  raise(k.checkDetermined({p}));
  if (rpm > 0) k.setRpm(rpm);
  const bool spatial = isSpatial(design_);
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(angles[i]))
      throw BadInput("sweep: angle " + std::to_string(i) + " is not finite");
    raise(k.moveTo(angles[i]));
    if (spatial) {
      const Kinematics::PointMotion3 m = k.motionInSpace(p);
      for (int c = 0; c < 3; ++c) {
        out[9 * i + c] = m.position[c];
        out[9 * i + 3 + c] = m.velocity[c];
        out[9 * i + 6 + c] = m.acceleration[c];
      }
      continue;
    }
    const Kinematics::PointMotion m = k.motion(p);
    double* row = out + 6 * i;
    row[0] = m.position.x();
    row[1] = m.position.y();
    row[2] = m.velocity.x();
    row[3] = m.velocity.y();
    row[4] = m.acceleration.x();
    row[5] = m.acceleration.y();
  }
}

InstantCentres Model::instantCentres(double crankDeg) const {
  const Kinematics k = at(crankDeg);
  InstantCentres c = computeInstantCentres(k);
  raise(c.status);
  return c;
}

Forces Model::forces(double crankDeg, double rpm) const {
  const Kinematics k = at(crankDeg, rpm);
  ForceSolver solver;
  raise(solver.prepare(k));
  Forces f = solver.compute(k);
  raise(f.status);
  return f;
}

std::vector<std::pair<std::string, Vec3>> Model::sensitivity(const std::string& point,
                                                             double crankDeg, int quantity,
                                                             double rpm) const {
  const PointId p = pointNamed(point);
  raise(base_.checkDetermined({p}));
  Kinematics k = at(crankDeg, rpm);
  if (quantity == 2) k.setAccelerations(true);
  Sensitivity s;
  raise(s.prepare(k, linkage::dimensions(k.mechanism()), Sensitivity::Space::World));
  raise(s.at(k));
  std::vector<std::pair<std::string, Vec3>> out;
  for (size_t d = 0; d < s.dims().size(); ++d) {
    const int i = static_cast<int>(d);
    out.emplace_back(s.dims()[d].name, quantity == 0   ? s.point3(k, p, i)
                                       : quantity == 1 ? s.velocity3(k, p, i)
                                                       : s.acceleration3(k, p, i));
  }
  return out;
}

std::vector<std::pair<std::string, double>> Model::strokeSensitivity(
    const std::string& point, const std::string& direction) const {
  const PointId p = pointNamed(point);
  Vec3 along = strokeDirection(design_, p);
  if (!direction.empty()) {  // as `sensitivity --direction` reads it
    const std::optional<Vec3> d = parseDirection(direction);
    if (!d) throw BadInput("direction '" + direction + "': expected x, y, z or DX,DY[,DZ] (not 0)");
    if (d->z() != 0 && !isSpatial(design_))
      throw BadInput("direction '" + direction +
                     "': out of the plane, and this machine is planar (give DX,DY)");
    along = d->normalized();
  }
  const StrokeSensitivity s =
      linkage::strokeSensitivity(base_, p, along, linkage::dimensions(design_));
  raise(s.status);
  std::vector<std::pair<std::string, double>> out;
  for (size_t d = 0; d < s.dims.size(); ++d) out.emplace_back(s.dims[d].name, s.derivative[d]);
  return out;
}

std::vector<std::pair<std::string, std::vector<double>>> Model::shakingSensitivity(
    double crankDeg, double rpm) const {
  Kinematics k = at(crankDeg, rpm);
  k.setAccelerations(true);
  const bool space = isSpatial(k.mechanism());
  Sensitivity s;
  raise(s.prepare(k, linkage::dimensions(k.mechanism()),
                  space ? Sensitivity::Space::World : Sensitivity::Space::Refuse));
  raise(s.at(k));
  std::vector<std::pair<std::string, std::vector<double>>> out;
  for (size_t d = 0; d < s.dims().size(); ++d) {
    const int i = static_cast<int>(d);
    if (space) {
      const Vec3 f = shakingForceSensitivity3(k, s, i), m = shakingMomentSensitivity3(k, s, i);
      out.emplace_back(s.dims()[d].name,
                       std::vector<double>{f.x(), f.y(), f.z(), m.x(), m.y(), m.z()});
    } else {
      const Vec2 f = shakingForceSensitivity(k, s, i);
      out.emplace_back(s.dims()[d].name,
                       std::vector<double>{f.x(), f.y(), shakingMomentSensitivity(k, s, i)});
    }
  }
  return out;
}

std::vector<std::pair<std::string, std::vector<double>>> Model::forceSensitivity(
    const std::string& joint, double crankDeg, double rpm) const {
  const Joint* found = nullptr;
  for (const Joint& j : design_.joints)
    if (std::string(kindOf(j).name) + ":" + design_.pointLabel(j.a) == joint) found = &j;
  if (!found) throw BadInput("no joint '" + joint + "' (named as linkage-cli dynamics names it)");
  const JointForceSensitivity f =
      jointForceSensitivity(at(crankDeg, rpm), found->id, linkage::dimensions(design_));
  raise(f.status);
  const ElementKind& kind = kindOf(*found);
  std::vector<std::pair<std::string, std::vector<double>>> out;
  for (size_t d = 0; d < f.dims.size(); ++d) {
    std::vector<double> v;
    for (const char* c : differentiatedColumns(design_, kind))
      v.push_back(reactionValue(f.change[d], c, kind.role == Role::Coupling));
    out.emplace_back(f.dims[d].name, std::move(v));
  }
  return out;
}

std::vector<std::pair<std::string, double>> Model::dimensions() const {
  std::vector<std::pair<std::string, double>> out;
  for (const Dimension& d : linkage::dimensions(design_)) out.emplace_back(d.name, d.value);
  return out;
}

}  // namespace linkage::py
