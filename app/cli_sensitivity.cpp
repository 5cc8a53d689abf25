// linkage-cli sensitivity: how far a point moves per unit of each dimension of the mechanism,
// exactly (linkage/sensitivity.h), at each crank angle of a turn.
#include <functional>
#include <iostream>

#include "cli_common.h"
#include "cli_parser.h"
#include "linkage/clearance_sensitivity.h"
#include "linkage/elements.h"
#include "linkage/force_sensitivity.h"
#include "linkage/io/numbers.h"
#include "linkage/optimize_text.h"
#include "linkage/sensitivity.h"
#include "linkage/shaking_sensitivity.h"
#include "linkage/space.h"
#include "linkage/stroke_sensitivity.h"
#include "linkage/tables/force_table.h"
#include "linkage/transmission_sensitivity.h"
#include "linkage/window_sensitivity.h"

namespace linkage::cli {

namespace {

const char* kHelp =
    R"(usage: linkage-cli sensitivity MODEL --point body.point [--steps N] [--velocity]
                                   [--acceleration] | --point body.point --stroke
                                   [--direction DIR] |
                                   --clearance N | --window NAME | --transmission N |
                                   --shaking | --force JOINT

The derivative of a point's position with respect to every dimension of MODEL, at each crank
angle of one turn: exact, from the constraint Jacobian (dq/dp = -J_q^-1 J_p), not by finite
differences. A dimension changes the drawing with every body's frame held: one body's points move
in that body, nothing pinned to them moves with them, and the joints close again.

Dimensions, in this order: for each body, its P0-P1 (its first two points in file order), then
for each later point Pk its P1-Pk and P0-Pk (a three-point body: its three sides, as the editor
types them), or Pk.along and Pk.across P0->P1 where Pk is on the line P0P1; each ground point's
x and y; each straight slot's offset (along its normal) and angle (about its first end, in
degrees: its rows are mm per degree), each arc slot's centre (body.slot.centre.x, .y) and
radius (body.slot.radius); each gear's ratio (mm per unit of ratio); each cam's rises (one a
rise or fall segment, cam:F.R.segmentK.rise, the next segment moving the other way taking the
difference, as the Cam dock types it), base and roller (cam:F.R.base, cam:F.R.roller).

  --point body.point   the point (required unless another output is asked for)
  --steps N            steps per revolution (default 360)
  --velocity           also the point's velocity's derivatives, mm/s per mm at the driver's
                       speed: columns dvx_mm_s_per_mm,dvy_mm_s_per_mm
  --acceleration       also its acceleration's, mm/s^2 per mm: dax_mm_s2_per_mm,day_mm_s2_per_mm
  --stroke             instead, the derivative of the point's stroke (along its ground slot,
                       else y; on a machine in space the world's y; limit positions to 1e-9 degree, the envelope theorem: each
                       extreme moves by the point's own derivative there): CSV
                       dimension,dstroke_mm_per_mm, a row a dimension
  --direction DIR      with --stroke: along DIR instead, x, y, z or DX,DY[,DZ] (any length, not
                       0; z and DZ a machine in space's, in the world)
  --clearance N        instead, the derivative of the least distance of the file's clearance N
                       (0 the first of "timing"'s "clearances"; the envelope theorem at the
                       closest approach): CSV dimension,dmin_mm_per_mm; --point not needed.
                       Refused where the two touch (0 has no derivative)
  --window NAME        instead, the derivatives of the ends of the file's timing window NAME (a
                       point's position below or above a level): CSV
                       dimension,interval,dfrom_deg_per_unit,dto_deg_per_unit (degrees of
                       crank per mm, degree or ratio; interval from 0 in crank order)
  --transmission N     instead, the derivatives of transmission angle N (0 the first mu column of
                       `linkage-cli transmission`, or its name there, e.g. mu:coupler.B) at each
                       crank angle of the turn: CSV crank_deg,dimension,dmu_deg_per_unit
                       (degrees of the angle per mm, degree or ratio); --point not needed.
                       Every kind: a dyad's (with an arc slot's centre too), a rod's on a
                       slider or in a slot; on a machine in space each in its plane
  --shaking            instead, the derivatives of the shaking force (what the frame feels: the
                       bodies' masses times their accelerations, with gravity and loads, as
                       `dynamics` writes it) at the file's speed at each crank angle: CSV
                       crank_deg,dimension,dfx_N_per_unit,dfy_N_per_unit,dm_Nm_per_unit (the
                       shaking moment's about the drawing's origin; a dimension moves points,
                       not masses: each centre of mass stays where it is drawn in its body);
                       on a machine in space the world's dfx, dfy, dfz and its moment's (about
                       the world's origin) dmx, dmy, dmz_Nm_per_unit
  --force JOINT        instead, the derivatives of a joint's reaction (JOINT as `dynamics` names
                       its columns, e.g. pin:crank.A: on the body of its first point) at the
                       file's speed at each crank angle: CSV crank_deg,dimension and a column a
                       column of its kind there, d<column>_per_unit (a pin's
                       dfx_N_per_unit,dfy_N_per_unit; a slider's also dm_Nm_per_unit; a cam's
                       also dcontact_N_per_unit; a gear's or belt's the tooth force or the pull
                       where its kind restates it, its pivots' pins with it); from J^T lambda = Q
                       differentiated exactly. On a machine in space in its plane class's frame
                       (a ball rod's daxial_N_per_unit), and a joint in a plane also what it
                       bears out of the plane, dfn_N_per_unit,dmx_Nm_per_unit,dmy_Nm_per_unit
                       (a body's bearing: its normal force and tilts). Redundant joints refused
                       by name
Output, CSV: crank_deg,dimension,dx_mm_per_mm,dy_mm_per_mm; one row a dimension a step, 17
significant digits. A singular position (a dead point of the output, where the derivatives are
unbounded) writes no rows and says so on standard error.

A machine in space (the file has "planes" or a point with three numbers): the point's world x,
y, z, columns dx_mm_per_mm,dy_mm_per_mm,dz_mm_per_mm (dvz, daz likewise); a body's dimensions
in its plane's coordinates, and after all the others each moving point's depth
(body.P.depth, where written or at a ball rod's end), each ground point's z, each ball rod's
length (ball-rod:A.P.length) and each plane's origin (planes.NAME.origin.x, .y, .z); a ground
slot's offset and angle in its block's plane. --stroke is along the world's y, as `limits`
measures it there, or along --direction in the world (z too); --clearance (to a point, a
segment or a straight slot) and --window are in the world, --transmission in the angle's plane.

Not yet: a cam on a machine in space; a cam segment's end angle.

Exit status: 0 done, 2 bad input (an unknown point, a model it cannot differentiate yet), 3 the
crank cannot turn fully (the rows up to there are written).
)";

struct Options {
  std::string model, point;
  int steps = 360;
  bool velocity = false, acceleration = false, stroke = false, shaking = false;
  bool space = false;  // the model is spatial: x, y, z in the world
  int clearance = -1;
  std::string window, transmission, force;
  std::string direction;  // --stroke's, as the optimiser's stroke target reads it
};

// Appends ",x,y" (one string appended at a time: no temporaries to concatenate).
void pair(std::string& out, const Vec2& v) {
  for (double c : {v.x(), v.y()}) {
    out += ',';
    out += formatNumber(c);
  }
}

// Appends ",x,y,z".
void triple(std::string& out, const Vec3& v) {
  for (double c : {v.x(), v.y(), v.z()}) {
    out += ',';
    out += formatNumber(c);
  }
}

std::string rows(const Kinematics& k, const Sensitivity& s, PointId p, double deg,
                 const Options& o) {
  std::string out;
  const std::string at = formatNumber(deg);
  for (size_t d = 0; d < s.dims().size(); ++d) {
    const int i = static_cast<int>(d);
    out += at;
    out += ',';
    out += s.dims()[d].name;
    if (o.space) {
      triple(out, s.point3(k, p, i));
      if (o.velocity) triple(out, s.velocity3(k, p, i));
      if (o.acceleration) triple(out, s.acceleration3(k, p, i));
    } else {
      pair(out, s.point(k, p, i));
      if (o.velocity) pair(out, s.velocity(k, p, i));
      if (o.acceleration) pair(out, s.acceleration(k, p, i));
    }
    out += '\n';
  }
  return out;
}

// One derivative a dimension: CSV dimension,COLUMN.
void writeByDimension(const char* column, const std::vector<Dimension>& dims,
                      const std::vector<double>& derivative) {
  std::string out = std::string("dimension,") + column + "\n";
  for (size_t d = 0; d < dims.size(); ++d) {
    out += dims[d].name;
    out += ',';
    out += formatNumber(derivative[d]);
    out += '\n';
  }
  std::cout << out << std::flush;
}

// The stroke's derivatives (linkage/stroke_sensitivity.h), along the point's default direction
// (in space the world's +y) or the one given.
int stroke(const Kinematics& k, PointId p, const std::string& along) {
  Vec3 direction = strokeDirection(k.mechanism(), p);
  if (!along.empty()) {
    const std::optional<Vec3> d = parseDirection(along);
    if (!d) {
      error("sensitivity: --direction " + along + ": expected x, y, z or DX,DY[,DZ] (not 0)");
      return kBadInput;
    }
    if (d->z() != 0 && !isSpatial(k.mechanism())) {
      error("sensitivity: --direction " + along +
            ": out of the plane, and this machine is planar (give DX,DY)");
      return kBadInput;
    }
    direction = d->normalized();
  }
  const StrokeSensitivity s = strokeSensitivity(k, p, direction, dimensions(k.mechanism()));
  if (!s.status.ok()) {
    error("sensitivity: " + s.status.message);
    return exitFor(s.status);
  }
  note("stroke " + formatNumber(s.limits.stroke) + " mm, from crank " +
       formatNumber(s.limits.minDeg) + " to " + formatNumber(s.limits.maxDeg) + " deg");
  writeByDimension("dstroke_mm_per_mm", s.dims, s.derivative);
  return kOk;
}

// A clearance's least distance's derivatives (linkage/clearance_sensitivity.h).
int clearance(const Mechanism& m, int n) {
  if (n >= static_cast<int>(m.timing.clearances.size())) {
    error("--clearance " + std::to_string(n) + ": the file watches " +
          std::to_string(m.timing.clearances.size()) +
          " clearance(s) (\"timing\": " + "\"clearances\", counted from 0)");
    return kBadInput;
  }
  Kinematics k;
  if (int e = prepare(k, m); e != kOk) return e;
  const ClearanceSensitivity s = clearanceSensitivity(k, m.timing.clearances[n], dimensions(m));
  if (!s.status.ok()) {
    error("sensitivity: clearance " + std::to_string(n) + ": " + s.status.message);
    return exitFor(s.status);
  }
  note("closest " + formatNumber(s.clearance.closest.distance) + " mm at crank " +
       formatNumber(s.clearance.closest.crankDeg) + " deg");
  writeByDimension("dmin_mm_per_mm", s.dims, s.derivative);
  return kOk;
}

// A window's ends' derivatives (linkage/window_sensitivity.h).
int window(const Mechanism& m, const std::string& name) {
  Kinematics k;
  if (int e = prepare(k, m); e != kOk) return e;
  const WindowSensitivity s = windowSensitivity(k, name, dimensions(m));
  if (!s.status.ok()) {
    error("sensitivity: window " + name + ": " + s.status.message);
    return exitFor(s.status);
  }
  std::string out = "dimension,interval,dfrom_deg_per_unit,dto_deg_per_unit\n";
  for (size_t i = 0; i < s.intervals.size(); ++i) {
    note("interval " + std::to_string(i) + ": crank " + formatNumber(s.intervals[i].fromDeg) +
         " to " + formatNumber(s.intervals[i].toDeg) + " deg");
    for (size_t d = 0; d < s.dims.size(); ++d) {
      out += s.dims[d].name + ',' + std::to_string(i);
      for (double v : {s.intervals[i].dFrom[d], s.intervals[i].dTo[d]}) {
        out += ',';
        out += formatNumber(v);
      }
      out += '\n';
    }
  }
  std::cout << out << std::flush;
  return kOk;
}

// The transmission angle `which` names: its index among transmissionJoints(m), from 0, or its
// label (with or without "mu:"); nullopt, said, when there is none.
std::optional<size_t> transmissionIndex(const std::vector<TransmissionJoint>& js,
                                        const std::string& which) {
  const bool number = !which.empty() && which.find_first_not_of("0123456789") == std::string::npos;
  for (size_t j = 0; j < js.size(); ++j)
    if (number ? which == std::to_string(j)
               : js[j].label == (which.rfind("mu:", 0) == 0 ? which : "mu:" + which))
      return j;
  std::string known;
  for (size_t j = 0; j < js.size(); ++j)
    known += (j ? ", " : "") + std::to_string(j) + " " + js[j].label;
  error("--transmission " + which +
        ": no such transmission angle (the model's: " + (known.empty() ? "none" : known) + ")");
  return std::nullopt;
}

// A quantity's derivatives at each step of the turn: `values` gives them for every dimension
// (several columns each, in `header`'s order) at k's pose.
using PerDimension = std::function<std::vector<std::vector<double>>(Kinematics&, Sensitivity&)>;
int perStep(Kinematics& k, Sensitivity& sens, const Options& o, const std::string& header,
            const PerDimension& values) {
  std::string out = "crank_deg,dimension," + header + "\n";
  Status failed;
  for (int i = 0; i < o.steps && failed.ok(); ++i) {
    const double deg = 360.0 * i / o.steps;
    Status s = k.moveTo(deg);
    if (s.ok()) s = sens.at(k);
    if (s.code == StatusCode::Singular) {
      note("at " + formatNumber(deg) + " deg: " + s.message + "; no rows");
      continue;
    }
    if (!(failed = s).ok()) break;
    const std::vector<std::vector<double>> d = values(k, sens);
    const std::string at = formatNumber(deg);
    for (size_t v = 0; v < d.size(); ++v) {
      out.append(at).append(",").append(sens.dims()[v].name);
      for (double x : d[v]) out.append(",").append(formatNumber(x));
      out.append("\n");
    }
  }
  std::cout << out << std::flush;
  if (!failed.ok()) error(failed.message);
  return failed.ok() ? kOk : exitFor(failed);
}

// A transmission angle's derivatives (linkage/transmission_sensitivity.h), a row a
// dimension a step.
int transmission(Kinematics& k, Sensitivity& sens, const Options& o) {
  const std::vector<TransmissionJoint> js = transmissionJoints(k.mechanism());
  const std::optional<size_t> j = transmissionIndex(js, o.transmission);
  if (!j) return kBadInput;
  return perStep(k, sens, o, "dmu_deg_per_unit", [&](Kinematics& kk, Sensitivity& ss) {
    std::vector<std::vector<double>> out;
    for (double d : transmissionAngleDerivatives(kk, js[*j], ss)) out.push_back({d});
    return out;
  });
}

// The shaking force's derivatives (linkage/shaking_sensitivity.h), N per unit at the file's
// speed, a row a dimension a step.
int shakingForce(Kinematics& k, Sensitivity& sens, const Options& o) {
  k.setAccelerations(true);
  if (isSpatial(k.mechanism()))  // in the world, with its z, and the world's moment
    return perStep(k, sens, o,
                   "dfx_N_per_unit,dfy_N_per_unit,dfz_N_per_unit,dmx_Nm_per_unit,dmy_Nm_per_unit,"
                   "dmz_Nm_per_unit",
                   [](Kinematics& kk, Sensitivity& ss) {
                     std::vector<std::vector<double>> out;
                     for (size_t d = 0; d < ss.dims().size(); ++d) {
                       const Vec3 f = shakingForceSensitivity3(kk, ss, static_cast<int>(d));
                       const Vec3 m = shakingMomentSensitivity3(kk, ss, static_cast<int>(d));
                       out.push_back({f.x(), f.y(), f.z(), m.x(), m.y(), m.z()});
                     }
                     return out;
                   });
  // A planar machine's moment about the drawing's origin too.
  return perStep(
      k, sens, o, "dfx_N_per_unit,dfy_N_per_unit,dm_Nm_per_unit",
      [](Kinematics& kk, Sensitivity& ss) {
        std::vector<std::vector<double>> out;
        for (size_t d = 0; d < ss.dims().size(); ++d) {
          const Vec2 f = shakingForceSensitivity(kk, ss, static_cast<int>(d));
          out.push_back({f.x(), f.y(), shakingMomentSensitivity(kk, ss, static_cast<int>(d))});
        }
        return out;
      });
}

// A joint's reaction's derivatives (linkage/force_sensitivity.h), N (N m) per unit at the file's
// speed, a row a dimension a step, a column a column of its kind in `dynamics`.
int jointForce(Kinematics& k, Sensitivity& sens, const Options& o) {
  const Mechanism& m = k.mechanism();
  const Joint* joint = nullptr;
  std::string known;
  for (const Joint& j : m.joints) {  // named as dynamics' columns are
    const std::string name = std::string(kindOf(j).name) + ":" + m.pointLabel(j.a);
    known += (known.empty() ? "" : ", ") + name;
    if (name == o.force) joint = &j;
  }
  if (!joint) {
    error("--force " + o.force + ": no such joint (the model's: " + known + ")");
    return kBadInput;
  }
  const JointForceSensitivity first = jointForceSensitivity(k, joint->id, sens.dims());
  if (!first.status.ok()) {
    error("sensitivity: " + first.status.message);
    return exitFor(first.status);
  }
  const ElementKind& kind = kindOf(*joint);
  const bool coupling = kind.role == Role::Coupling;
  const std::vector<const char*> columns = differentiatedColumns(m, kind);
  std::string header;
  for (const char* c : columns)
    header += (header.empty() ? "d" : ",d") + std::string(c) + "_per_unit";
  const JointId id = joint->id;
  return perStep(k, sens, o, header, [&](Kinematics& kk, Sensitivity& ss) {
    const JointForceSensitivity f = jointForceSensitivity(kk, id, ss.dims());
    std::vector<std::vector<double>> out;
    for (const JointReaction& d : f.change) {
      out.emplace_back();
      for (const char* c : columns) out.back().push_back(reactionValue(d, c, coupling));
    }
    return out;
  });
}

// The CSV header of the point's rows.
std::string header(const Options& o) {
  std::string out = "crank_deg,dimension,dx_mm_per_mm,dy_mm_per_mm";
  if (o.space) out += ",dz_mm_per_mm";
  if (o.velocity)
    out += o.space ? ",dvx_mm_s_per_mm,dvy_mm_s_per_mm,dvz_mm_s_per_mm"
                   : ",dvx_mm_s_per_mm,dvy_mm_s_per_mm";
  if (o.acceleration)
    out += o.space ? ",dax_mm_s2_per_mm,day_mm_s2_per_mm,daz_mm_s2_per_mm"
                   : ",dax_mm_s2_per_mm,day_mm_s2_per_mm";
  return out + "\n";
}

int sensitivity(Options o) {
  if (!o.direction.empty() && !o.stroke) {
    error("sensitivity: --direction goes with --stroke");
    return kBadInput;
  }
  std::optional<Mechanism> m = openDrivenModel(o.model);
  if (!m) return kBadInput;
  if (o.clearance >= 0) return clearance(*m, o.clearance);
  if (!o.window.empty()) return window(*m, o.window);
  if (!o.transmission.empty() || o.shaking || !o.force.empty()) {
    Kinematics k;
    if (int e = prepare(k, *m); e != kOk) return e;
    Sensitivity sens;
    // On a machine in space from the world's sensitivities (a transmission angle from its plane
    // class's frame, which they give too).
    const bool world = isSpatial(k.mechanism());
    if (Status s = sens.prepare(k, dimensions(k.mechanism()),
                                world ? Sensitivity::Space::World : Sensitivity::Space::Refuse);
        !s.ok()) {
      error("sensitivity: " + s.message);
      return exitFor(s);
    }
    if (!o.force.empty()) return jointForce(k, sens, o);
    return o.shaking ? shakingForce(k, sens, o) : transmission(k, sens, o);
  }
  if (o.point.empty()) {
    error("sensitivity: --point body.point is required (or --clearance N)");
    return kBadInput;
  }
  std::optional<std::vector<PointId>> ids = outputPoints(*m, {o.point});
  if (!ids) return kBadInput;
  const PointId p = ids->front();
  Kinematics k;
  if (int e = prepare(k, *m); e != kOk) return e;
  if (Status s = k.checkDetermined({p}); !s.ok()) {
    error(s.message);
    return exitFor(s);
  }
  Sensitivity sens;
  if (Status s = sens.prepare(k, dimensions(k.mechanism()), Sensitivity::Space::World); !s.ok()) {
    error("sensitivity: " + s.message);
    return exitFor(s);
  }
  if (o.stroke) return stroke(k, p, o.direction);
  o.space = isSpatial(k.mechanism());
  std::string out = header(o);
  Status failed;
  for (int i = 0; i < o.steps && failed.ok(); ++i) {
    const double deg = 360.0 * i / o.steps;
    Status s = k.moveTo(deg);
    if (s.ok()) s = sens.at(k);
    if (s.code == StatusCode::Singular)
      note("at " + formatNumber(deg) + " deg: " + s.message + "; no rows");
    else if (!s.ok())
      failed = s;
    else
      out += rows(k, sens, p, deg, o);
  }
  std::cout << out << std::flush;
  if (!failed.ok()) {
    error(failed.message);
    return exitFor(failed);
  }
  return kOk;
}

}  // namespace

Command sensitivityCommand(Parser& parser) {
  auto o = std::make_shared<Options>();
  CLI::App& c = parser.command("sensitivity", kHelp);
  addModel(c, o->model);
  addText(c, "--point", o->point);
  addWhole(c, "--steps", o->steps, 1, 1'000'000);
  addFlag(c, "--velocity", o->velocity);
  addFlag(c, "--acceleration", o->acceleration);
  addFlag(c, "--stroke", o->stroke);
  addText(c, "--direction", o->direction);
  addWhole(c, "--clearance", o->clearance, 0, 1'000'000);
  addText(c, "--window", o->window);
  addText(c, "--transmission", o->transmission);
  addFlag(c, "--shaking", o->shaking);
  addText(c, "--force", o->force);
  return {&c, [o] { return sensitivity(*o); }};
}

}  // namespace linkage::cli
