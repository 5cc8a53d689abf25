// linkage-cli ics: the instant centres of a mechanism at one crank angle (Kennedy-Aronhold), and
// the velocity of a point by a chain of centres, the way a hand solution checks it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include "cli_common.h"
#include "cli_parser.h"
#include "linkage/elements.h"
#include "linkage/instant_centres.h"
#include "linkage/io/numbers.h"
#include "linkage/space.h"
#include "linkage/velocity_chain.h"

namespace linkage::cli {

namespace {

const char* kHelp =
    R"(usage: linkage-cli ics MODEL --angle DEG [--json] [--out FILE]
       linkage-cli ics MODEL --angle DEG --point body.point [--via N[,N...]] [--rpm RPM]
                           [--json] [--out FILE]

All n(n-1)/2 instant centres of MODEL (a .linkage.json file or an example name) at crank angle
DEG, numbered as in the textbook: the ground is 1, then the bodies in file order, or by their
"number" field. Primary centres come from the joints (a pin's point; a slider's centre at
infinity normal to its slot; a pin-in-slot gives a line, the normal to the slot through the
pin), secondary ones from Kennedy's theorem by the circle-diagram method. Every centre is
checked against the one the solved velocities give; a disagreement is a warning on standard
error. A centre Kennedy's lines do not fix at this position is taken from the velocities and
marked so.

CSV, one row per pair i < j:
  crank_deg,i,j,body_i,body_j,x_mm,y_mm,at_infinity,dir_x,dir_y,status
x_mm, y_mm are empty for a centre at infinity, dir_x, dir_y (its unit direction, unoriented,
written with dir_x > 0 or upwards) empty otherwise; all four are empty when the two bodies do
not move relative to each other at this instant (no centre). status: primary, kennedy, velocity.
A machine in space (docs/spatial.md): the centres of bodies of parallel planes (and the
ground) are found among them, in the frame of the first of those planes, named in a last
column, plane; bodies of planes that are not parallel have none: status across-planes.

  --angle DEG       crank angle (required)
  --json            JSON instead: the same, plus the lines each centre was found from
  --point B.P       instead, the velocity of point B.P by a chain of centres from the crank,
                    step by step, with the solver's exact velocity beside it
  --via N[,N...]    with --point: go through these bodies (textbook numbers), in order
  --rpm RPM         driver speed for the chain instead of the file's
  --out FILE        write to FILE (atomically) instead of standard output

Exit status: 0 success, 2 bad input (options, file, numbering, a point or chain that is not
there), 3 the mechanism cannot reach the crank angle or is singular there.
)";

std::string num(double v, int digits = 17) {
  return formatNumber(std::abs(v) == 0 ? 0.0 : v, digits);
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string jsonString(const std::string& s) {
  std::string q = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      q += '\\';
      q += static_cast<char>(c);
    } else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      q += buf;
    } else {
      q += static_cast<char>(c);
    }
  }
  return q + "\"";
}

std::string bodyName(const Mechanism& m, BodyId id) {
  const Body* b = m.body(id);
  return b ? b->name : "?";
}

std::string ic(int i, int j) {
  return "IC(" + std::to_string(i) + "," + std::to_string(j) + ")";
}

// A vector for the step lines, to 6 digits; rounding noise (below 1e-12 of `scale`, or of the
// vector) is written as 0.
std::string pair2(const Vec2& v, double scale = 0) {
  const double floor = 1e-12 * std::max(scale, v.cwiseAbs().maxCoeff());
  auto clean = [&](double x) { return std::abs(x) < floor ? 0.0 : x; };
  // (Appended, not "(" + ...: GCC 12 warns falsely on that with -Wrestrict, bug 105329.)
  std::string s = "(";
  return s.append(num(clean(v.x()), 6)).append(", ").append(num(clean(v.y()), 6)).append(")");
}

// A centre's status as the tables write it: "across-planes" where none exists.
std::string statusText(const InstantCentre& c) {
  return c.across ? "across-planes" : toString(c.status);
}

// The plane a centre's coordinates are in: its class's frame.
std::string planeText(const InstantCentres& ics, const InstantCentre& c) {
  return c.across ? std::string() : ics.classes.frames[c.planeClass].name;
}

std::string csv(const Mechanism& m, const InstantCentres& ics, double angle) {
  const bool space = isSpatial(m);
  std::string s = "crank_deg,i,j,body_i,body_j,x_mm,y_mm,at_infinity,dir_x,dir_y,status";
  s += space ? ",plane\n" : "\n";
  for (const InstantCentre& c : ics.centres) {
    s += num(angle) + "," + std::to_string(c.i) + "," + std::to_string(c.j) + "," +
         csvField(bodyName(m, c.bodyI)) + "," + csvField(bodyName(m, c.bodyJ)) + ",";
    if (!c.determined)
      s += ",,0,,";
    else if (c.atInfinity())
      s += ",,1," + num(c.h.x()) + "," + num(c.h.y());
    else
      s += num(c.h.x()) + "," + num(c.h.y()) + ",0,,";
    s += "," + statusText(c);
    s += space ? "," + csvField(planeText(ics, c)) + "\n" : "\n";
  }
  return s;
}

std::string jsonCentreValue(const Eigen::Vector3d& h, bool determined) {
  if (!determined) return "\"determined\": false";
  if (h.z() == 0)
    return "\"determined\": true, \"at_infinity\": true, \"dir_x\": " + num(h.x()) +
           ", \"dir_y\": " + num(h.y());
  return "\"determined\": true, \"at_infinity\": false, \"x_mm\": " + num(h.x()) +
         ", \"y_mm\": " + num(h.y());
}

std::string jsonLine(const Mechanism& m, const InstantCentre& c, const CentreLine& l) {
  if (l.k == 0) return "{\"joint\": " + jsonString(jointLabel(m, l.joint)) + "}";
  return "{\"through\": [[" + std::to_string(std::min(c.i, l.k)) + ", " +
         std::to_string(std::max(c.i, l.k)) + "], [" + std::to_string(std::min(c.j, l.k)) + ", " +
         std::to_string(std::max(c.j, l.k)) + "]]}";
}

std::string json(const Mechanism& m, const InstantCentres& ics, double angle) {
  std::string s = "{\n  \"model\": " + jsonString(m.name) + ",\n  \"crank_deg\": " + num(angle) +
                  ",\n  \"size_mm\": " + num(ics.size) +
                  ",\n  \"velocities\": " + (ics.velocitiesValid ? "true" : "false") +
                  ",\n  \"kennedy_rounds\": " + std::to_string(ics.kennedyRounds) +
                  ",\n  \"bodies\": [";
  for (size_t t = 0; t < ics.bodies.size(); ++t)
    s += std::string(t ? ", " : "") + "{\"number\": " + std::to_string(ics.numbers[t]) +
         ", \"name\": " + jsonString(bodyName(m, ics.bodies[t])) + "}";
  s += "],\n  \"centres\": [\n";
  for (size_t p = 0; p < ics.centres.size(); ++p) {
    const InstantCentre& c = ics.centres[p];
    s += "    {\"i\": " + std::to_string(c.i) + ", \"j\": " + std::to_string(c.j) +
         ", \"body_i\": " + jsonString(bodyName(m, c.bodyI)) +
         ", \"body_j\": " + jsonString(bodyName(m, c.bodyJ)) + ", \"status\": \"" + statusText(c) +
         "\", " + jsonCentreValue(c.h, c.determined);
    if (isSpatial(m) && !c.across) s += ", \"plane\": " + jsonString(planeText(ics, c));
    if (c.status == CentreStatus::Primary && c.joint && !c.lines[0].joint)
      s += ", \"joint\": " + jsonString(jointLabel(m, c.joint));
    if (c.status == CentreStatus::Kennedy || c.lines[0].joint) {
      s += ", \"lines\": [" + jsonLine(m, c, c.lines[0]) + ", " + jsonLine(m, c, c.lines[1]) + "]";
      if (c.status == CentreStatus::Kennedy) s += ", \"round\": " + std::to_string(c.round);
    }
    if (c.status == CentreStatus::Velocity && c.kennedyFailure != KennedyFailure::None)
      s += ", \"kennedy\": " + jsonString(toString(c.kennedyFailure));
    s += ", \"from_velocities\": {" + jsonCentreValue(c.fromVelocity, c.velocityDetermined) + "}";
    if (c.checked)
      s += ", \"check\": {\"difference\": " + num(c.difference) +
           ", \"tolerance\": " + num(c.tolerance) + ", \"unit\": \"" +
           (c.euclidean ? "mm" : "chordal") + "\"}";
    s += std::string("}") + (p + 1 < ics.centres.size() ? "," : "") + "\n";
  }
  s += "  ],\n  \"disagreements\": [";
  for (size_t d = 0; d < ics.disagreements.size(); ++d) {
    const CentreDisagreement& x = ics.disagreements[d];
    s += std::string(d ? ", " : "") + "{\"i\": " + std::to_string(x.i) +
         ", \"j\": " + std::to_string(x.j) + ", \"difference\": " + num(x.difference) +
         ", \"tolerance\": " + num(x.tolerance) + ", \"unit\": \"" +
         (x.euclidean ? "mm" : "chordal") + "\"}";
  }
  return s + "]\n}\n";
}

std::string omegaText(int body, double w) {
  return "omega" + std::to_string(body) + " = " + num(w, 6) + " rad/s" +
         (w > 0   ? " (ccw)"
          : w < 0 ? " (cw)"
                  : "");
}

std::string motionText(int body, const BodyMotion& mo, const std::string& from, double scaleMm) {
  const std::string b = std::to_string(body);
  switch (mo.kind) {
    case BodyMotion::Kind::Turns:
      return "body " + b + " turns about " + ic(1, body) + " = " + pair2(mo.pivot, scaleMm) + from;
    case BodyMotion::Kind::Translates:
      return ic(1, body) + " is at infinity: body " + b + " translates, v" + b + " = " +
             pair2(mo.v) + " mm/s";
    case BodyMotion::Kind::AtRest:
      break;
  }
  return "body " + b + " does not move at this instant (no " + ic(1, body) + ")";
}

std::string chainText(const Mechanism& m, const InstantCentres& ics, const VelocityChain& ch,
                      double rpm) {
  const std::string label = m.pointLabel(ch.point);
  const double L = ics.size;
  std::string s = "velocity of " + label + " (body " + std::to_string(ch.body) + ", " +
                  bodyName(m, ics.bodyNumbered(ch.body)) + ") at crank angle " +
                  num(ics.crankDeg, 9) + " deg, by instant centres\n";
  const BodyMotion& c = ch.crankMotion;
  s += "crank: body " + std::to_string(ch.crank) + " (" + bodyName(m, ics.bodyNumbered(ch.crank)) +
       ") turns about " + ic(1, ch.crank) + " = " + pair2(c.pivot, L) + ", " + "omega" +
       std::to_string(ch.crank) + " = " + num(c.omega, 6) + " rad/s (" + num(rpm, 6) + " rpm " +
       (c.omega < 0 ? "cw" : "ccw") + ")\n";
  for (size_t i = 0; i < ch.steps.size(); ++i) {
    const ChainStep& st = ch.steps[i];
    const std::string from = std::to_string(st.from), to = std::to_string(st.to);
    const std::string P = ic(std::min(st.from, st.to), std::max(st.from, st.to));
    s += "step " + std::to_string(i + 1) + ": body " + from + " to body " + to + " through ";
    if (st.centreAtInfinity) {
      s += P + ", at infinity in direction " + pair2(st.centre) + ": the two bodies turn alike\n";
      s += "  " +
           motionText(
               st.to, st.toMotion,
               ", omega" + to + " = omega" + from + " = " + num(st.toMotion.omega, 6) + " rad/s",
               L) +
           "\n";
      continue;
    }
    s += "P = " + P + " = " + pair2(st.centre, L) + "\n  ";
    if (st.fromMotion.kind == BodyMotion::Kind::Turns)
      s += "|" + ic(1, st.from) + " P| = " + num(st.fromArm, 6) + " mm; v_P = omega" + from +
           " x (P - " + ic(1, st.from) + ") = ";
    else
      s += "v_P = v" + from + " = ";
    s += pair2(st.vP) + " mm/s, |v_P| = " + num(st.vP.norm(), 6) + " mm/s\n  ";
    if (st.toMotion.kind == BodyMotion::Kind::Turns)
      s += ic(1, st.to) + " = " + pair2(st.toMotion.pivot, L) + ": |" + ic(1, st.to) +
           " P| = " + num(st.toArm, 6) + " mm; omega" + to + " = (P - " + ic(1, st.to) +
           ") x v_P / |" + ic(1, st.to) + " P|^2: " + omegaText(st.to, st.toMotion.omega) + "\n";
    else
      s += motionText(st.to, st.toMotion, "", L) + "\n";
  }
  const BodyMotion& b = ch.bodyMotion;
  if (ch.body == 1)
    s += label + " is on the ground: v = 0\n";
  else if (b.kind == BodyMotion::Kind::Turns)
    s += label + " = " + pair2(ch.position, L) + ": |" + ic(1, ch.body) + " " + label +
         "| = " + num(ch.arm, 6) + " mm; v = omega" + std::to_string(ch.body) + " x (" + label +
         " - " + ic(1, ch.body) + ")\n";
  else if (b.kind == BodyMotion::Kind::Translates)
    s += label + " moves with body " + std::to_string(ch.body) + ": v = v" +
         std::to_string(ch.body) + "\n";
  s += "by the chain: v = (" + num(ch.velocity.x()) + ", " + num(ch.velocity.y()) +
       ") mm/s, |v| = " + num(ch.velocity.norm()) + " mm/s\n";
  s += "solver:       v = (" + num(ch.solverVelocity.x()) + ", " + num(ch.solverVelocity.y()) +
       ") mm/s, |v| = " + num(ch.solverVelocity.norm()) + " mm/s; difference " +
       num((ch.velocity - ch.solverVelocity).norm(), 3) + " mm/s\n";
  return s;
}

std::string jsonVec(const Vec2& v) {
  std::string s = "[";  // (appended: see pair2)
  return s.append(num(v.x())).append(", ").append(num(v.y())).append("]");
}

std::string jsonMotion(const BodyMotion& mo) {
  switch (mo.kind) {
    case BodyMotion::Kind::Turns:
      return "{\"motion\": \"turns\", \"pivot_mm\": " + jsonVec(mo.pivot) +
             ", \"omega_rad_s\": " + num(mo.omega) + "}";
    case BodyMotion::Kind::Translates:
      return "{\"motion\": \"translates\", \"v_mm_s\": " + jsonVec(mo.v) + "}";
    case BodyMotion::Kind::AtRest:
      break;
  }
  return "{\"motion\": \"at_rest\"}";
}

std::string chainJson(const Mechanism& m, const InstantCentres& ics, const VelocityChain& ch) {
  std::string s = "{\n  \"point\": " + jsonString(m.pointLabel(ch.point)) +
                  ",\n  \"body\": " + std::to_string(ch.body) +
                  ",\n  \"crank_deg\": " + num(ics.crankDeg) +
                  ",\n  \"crank\": {\"body\": " + std::to_string(ch.crank) +
                  ", \"motion\": " + jsonMotion(ch.crankMotion) + "},\n  \"steps\": [";
  for (size_t i = 0; i < ch.steps.size(); ++i) {
    const ChainStep& st = ch.steps[i];
    s += std::string(i ? "," : "") + "\n    {\"from\": " + std::to_string(st.from) +
         ", \"to\": " + std::to_string(st.to) +
         ", \"centre\": {\"i\": " + std::to_string(std::min(st.from, st.to)) +
         ", \"j\": " + std::to_string(std::max(st.from, st.to)) + ", " +
         jsonCentreValue(
             Eigen::Vector3d(st.centre.x(), st.centre.y(), st.centreAtInfinity ? 0.0 : 1.0), true) +
         "}";
    if (!st.centreAtInfinity) {
      s += ", \"v_centre_mm_s\": " + jsonVec(st.vP);
      if (st.fromMotion.kind == BodyMotion::Kind::Turns)
        s += ", \"from_arm_mm\": " + num(st.fromArm);
      if (st.toMotion.kind == BodyMotion::Kind::Turns) s += ", \"to_arm_mm\": " + num(st.toArm);
    }
    s += ", \"to_motion\": " + jsonMotion(st.toMotion) + "}";
  }
  s += std::string(ch.steps.empty() ? "" : "\n  ") +
       "],\n  \"body_motion\": " + jsonMotion(ch.bodyMotion) +
       ",\n  \"position_mm\": " + jsonVec(ch.position) +
       ",\n  \"velocity_mm_s\": " + jsonVec(ch.velocity) +
       ",\n  \"solver_velocity_mm_s\": " + jsonVec(ch.solverVelocity) + "\n}\n";
  return s;
}

struct Options {
  std::string model, out, point;
  std::vector<long long> via;
  std::optional<double> angle;
  double rpm = 0;
  bool json = false;
};

// The options, read into `o`.
CLI::App* addOptions(Parser& parser, Options& o) {
  CLI::App& c = parser.command("ics", kHelp);
  addModel(c, o.model);
  addNumber(c, "--angle", o.angle);
  addNumber(c, "--rpm", o.rpm, NumberRule::Positive);
  addText(c, "--out", o.out);
  addText(c, "--point", o.point);
  addWholeList(c, "--via", o.via);
  addFlag(c, "--json", o.json);
  return &c;
}

// The options checked against each other: the bodies of --via (textbook numbers), or the exit
// status when they cannot be used.
std::optional<int> checkOptions(const Options& o, std::vector<int>& via) {
  // Required, but checked here rather than by CLI11 to say what it takes.
  if (!o.angle) {
    error("ics: --angle DEG is required");
    return kBadInput;
  }
  if (!o.via.empty() && o.point.empty()) {
    error("ics: --via needs --point");
    return kBadInput;
  }
  for (long long n : o.via) via.push_back(static_cast<int>(std::clamp(n, -1LL, 1LL << 30)));
  return std::nullopt;
}

// Warnings and notes on the centres: disagreements with the velocities, centres Kennedy's
// theorem does not fix here.
void report(const InstantCentres& ics) {
  for (const CentreDisagreement& d : ics.disagreements)
    std::cerr << "linkage-cli: warning: " << ic(d.i, d.j)
              << ": Kennedy's centre and the velocities' differ by " << num(d.difference, 3)
              << (d.euclidean ? " mm" : " (chordal)") << ", more than " << num(d.tolerance, 3)
              << "\n";
  for (const InstantCentre& c : ics.centres)
    if (c.status == CentreStatus::Velocity && !c.across)
      note(ic(c.i, c.j) + " is not determined by Kennedy's theorem here (" +
           toString(c.kennedyFailure) + "): " +
           (c.determined ? "taken from the solved velocities"
                         : "the two bodies do not move relative to each other"));
}

int ics(const Options& o) {
  std::vector<int> via;
  if (std::optional<int> e = checkOptions(o, via)) return *e;
  std::optional<Mechanism> m = openDrivenModel(o.model);
  if (!m) return kBadInput;
  std::optional<PointId> pid;
  if (!o.point.empty()) {
    std::optional<std::vector<PointId>> ids = outputPoints(*m, {o.point});
    if (!ids) return kBadInput;
    pid = ids->front();
  }
  Kinematics k;
  if (int e = prepare(k, *m); e != kOk) return e;
  if (o.rpm > 0) k.setRpm(o.rpm);
  InstantCentreSolver solver;
  if (Status s = solver.prepare(k); !s.ok()) {
    error(s.message);
    return kBadInput;
  }
  if (Status s = k.moveTo(*o.angle); !s.ok()) {
    error(s.message);
    return exitFor(s);
  }
  const InstantCentres& ics = solver.compute(k);
  report(ics);
  if (!pid) return writeOutput(o.out, o.json ? json(*m, ics, *o.angle) : csv(*m, ics, *o.angle));
  const VelocityChain ch = velocityChain(k, ics, *pid, via);
  if (!ch.status.ok()) {
    error("--point " + o.point + ": " + ch.status.message);
    return ch.status.code == StatusCode::BadModel || !via.empty() ? kBadInput : kFailure;
  }
  return writeOutput(o.out, o.json ? chainJson(*m, ics, ch) : chainText(*m, ics, ch, k.rpm()));
}

}  // namespace

Command icsCommand(Parser& parser) {
  auto o = std::make_shared<Options>();
  return {addOptions(parser, *o), [o] { return ics(*o); }};
}

}  // namespace linkage::cli
