// What the tests of machines in space share: numbers written into model text to the last bit,
// the RSSR crank-rocker's dimensions (resources/examples/spatial.py: the crank R on the z axis,
// its ball at depth 5; the rocker W about the axis through H along the normal of the plane
// (X, Y) inclined 23 degrees), and the lockstitch-bevel machine's closed form, derived from its
// drawing alone: the hook turns at twice the arm shaft's angle phi about z, so its point is
// K = (20 - 25 sin 2phi, -200 + 25 cos 2phi, 0); the needle bar is a slider-crank (crank 16,
// rod 45) along y in the plane x = 0, its points N 131 mm and T 96 mm below the block B.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "linkage/model.h"

namespace linkage::test {

inline std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}
inline std::string vec(const Vec3& v) {
  return "[" + num(v.x()) + ", " + num(v.y()) + ", " + num(v.z()) + "]";
}
inline std::string vec2(const Vec2& v) {
  return "[" + num(v.x()) + ", " + num(v.y()) + "]";
}

// Masses on every moving body (a point at each centre of mass, for its motion in the world), the
// file's gravity, a force in one body's plane and a torque on another.
inline Mechanism withMasses(Mechanism m, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.2, 1.0), off(-5, 5);
  std::vector<BodyId> moving;
  for (const Body& b : m.bodies)
    if (!b.ground) moving.push_back(b.id);
  for (BodyId id : moving) {
    Vec2 c = Vec2::Zero();
    int n = 0;
    for (const Point& p : m.points)
      if (p.body == id) c += p.pos, ++n;
    c = c / std::max(n, 1) + Vec2(off(rng), off(rng));
    m.body(id)->mass = Mass{u(rng), c, 100 * u(rng), ""};
    m.addPoint(id, "G_com", c);
  }
  m.gravity = Vec2(3, -9.81);
  const Body& last = *m.body(moving.back());
  const Point* p = nullptr;
  for (const Point& q : m.points)
    if (q.body == last.id && q.name != "G_com") p = &q;
  m.addLoad(Load{p->id, {}, Vec2(3, -7), 0, 40.0, 200.0, ""});
  m.addLoad(Load{{}, moving.front(), Vec2::Zero(), 0.05, std::nullopt, std::nullopt, ""});
  return m;
}

// An oscillating block's coupler in a plane tilted 30 degrees about x, guided by a ground pin P
// (60, 0) in its slot (its one joint with the ground, a bearing with no point on its body), with
// a mass of 0.5 kg at (70, 5) in its plane, under gravity (0, -9.81, -3).
inline std::string tiltedOscillatingBlock() {
  return R"({"format": "linkage", "version": 1, "name": "oscillating block",
  "planes": {"tilt": {"origin": [0, 0, 0], "x_axis": [1, 0, 0],
                      "y_axis": [0, 0.8660254037844387, 0.5]}},
  "bodies": [
    {"name": "ground", "ground": true, "points": {"O": [0, 0], "P": [60, 0]}},
    {"name": "crank", "plane": "tilt", "points": {"O": [0, 0], "A": [20, 0]}},
    {"name": "coupler", "plane": "tilt", "points": {"A": [20, 0]},
     "slots": {"s": [[30, 0], [120, 0]]},
     "mass": {"kg": 0.5, "com": [70, 5], "j_kg_mm2": 100}}],
  "joints": [{"type": "pin", "a": "ground.O", "b": "crank.O"},
    {"type": "pin", "a": "crank.A", "b": "coupler.A"},
    {"type": "pin-in-slot", "a": "ground.P", "slot": "coupler.s"}],
  "driver": {"joint": 0, "rpm": 120, "direction": "ccw"},
  "gravity": [0, -9.81, -3]})";
}

// A slotted lever in a plane tilted 30 degrees about x: the crank's pin A (at depth 3) runs in a
// slot of the rocker, which turns on the ground pin H (its point at depth 6, another at -4), with
// masses on both under gravity (0, -9.81, -3). The rocker's bearing carries the pin in the slot's
// force, whose joint has no point on the rocker (it acts at the rocker's plane's depth) and whose
// row turns with the slot.
inline std::string slottedLever() {
  return R"({"format": "linkage", "version": 1, "name": "slotted lever",
  "planes": {"tilt": {"origin": [0, 0, 0], "x_axis": [1, 0, 0],
                      "y_axis": [0, 0.8660254037844387, 0.5]}},
  "bodies": [
    {"name": "ground", "ground": true, "points": {"O": [0, 0], "H": [60, 0]}},
    {"name": "crank", "plane": "tilt", "points": {"O": [0, 0], "A": [20, 0, 3]},
     "mass": {"kg": 0.3, "com": [10, 2], "j_kg_mm2": 50}},
    {"name": "rocker", "plane": "tilt", "points": {"H": [60, 0, 6], "E": [30, 10, -4]},
     "slots": {"s": [[50, 0], [-30, 0]]},
     "mass": {"kg": 0.5, "com": [30, 5], "j_kg_mm2": 100}}],
  "joints": [{"type": "pin", "a": "ground.O", "b": "crank.O"},
    {"type": "pin", "a": "ground.H", "b": "rocker.H"},
    {"type": "pin-in-slot", "a": "crank.A", "slot": "rocker.s"}],
  "driver": {"joint": 0, "rpm": 300, "direction": "ccw"},
  "gravity": [0, -9.81, -3]})";
}

namespace rssr {
constexpr double kR = 7.5, kDepth = 5, kW = 28.5, kRho = 23 * M_PI / 180;
constexpr double kPhi0 = 30 * M_PI / 180, kPsi0 = 160 * M_PI / 180;
inline const Vec3 kH(0, 0, 80);
inline const Vec3 kX(0, std::cos(kRho), std::sin(kRho)), kY(0, -std::sin(kRho), std::cos(kRho));
}  // namespace rssr

// An RSSR's crank radius and rocker axis point: the example's, or others (where the rod cannot
// reach at every crank angle).
struct RssrDims {
  double r = rssr::kR;
  Vec3 H = rssr::kH;
};

// The RSSR as a file (the crank's ball drawn at kPhi0, the rocker's at kPsi0).
inline std::string rssrText(const RssrDims& dims = {}) {
  using namespace rssr;
  const double r = dims.r;
  const Vec3& H = dims.H;
  return R"({"format": "linkage", "version": 1, "name": "RSSR",
  "planes": {"rocker": {"origin": )" +
         vec(H) + R"(, "x_axis": )" + vec(kX) + R"(, "y_axis": )" + vec(kY) + R"(}},
  "bodies": [
    {"name": "ground", "ground": true, "points": {"O": [0, 0], "H": )" +
         vec(H) + R"(}},
    {"name": "crank", "points": {"O": [0, 0], "A": [)" +
         num(r * std::cos(kPhi0)) + ", " + num(r * std::sin(kPhi0)) + ", " + num(kDepth) +
         R"(]}},
    {"name": "rocker", "plane": "rocker", "points": {"H": [0, 0], "C": [)" +
         num(kW * std::cos(kPsi0)) + ", " + num(kW * std::sin(kPsi0)) + R"(]}}
  ],
  "joints": [
    {"type": "pin", "a": "ground.O", "b": "crank.O"},
    {"type": "pin", "a": "ground.H", "b": "rocker.H"},
    {"type": "ball-rod", "a": "crank.A", "b": "rocker.C"}
  ],
  "driver": {"joint": 0, "rpm": 90, "direction": "ccw"}
})";
}

// The rod's length as the RSSR is drawn.
inline double rssrRod(const RssrDims& d = {}) {
  using namespace rssr;
  const Vec3 A0(d.r * std::cos(kPhi0), d.r * std::sin(kPhi0), kDepth);
  return (A0 - (d.H + kW * (std::cos(kPsi0) * kX + std::sin(kPsi0) * kY))).norm();
}

// The rocker's closed form a cos(psi) + b sin(psi) = c at crank angle phi (from the drawing),
// rod l: psi = atan2(b, a) +- acos(c / hypot(a, b)); and psi's first two derivatives
// by phi at a root, from F(phi, psi) = |A - C|^2 - l^2 = 0 differentiated twice (an independent
// derivation: no solver row is used).
struct RssrEquation {
  double a, b, c;
  bool reaches() const { return std::abs(c) <= std::hypot(a, b); }
  double root(int sign) const { return std::atan2(b, a) + sign * std::acos(c / std::hypot(a, b)); }
};
inline Vec3 rssrBall(double phi, double r) {
  const double t = rssr::kPhi0 + phi;
  return Vec3(r * std::cos(t), r * std::sin(t), rssr::kDepth);
}
inline RssrEquation rssrEquation(double phi, double l, const RssrDims& d = {}) {
  using namespace rssr;
  const Vec3 AH = rssrBall(phi, d.r) - d.H;
  return {2 * kW * AH.dot(kX), 2 * kW * AH.dot(kY), AH.squaredNorm() + kW * kW - l * l};
}
struct Rocker {
  double psi, d1, d2;
};
inline Rocker rockerAt(double phi, double psi, const RssrDims& d = {}) {
  using namespace rssr;
  const double t = kPhi0 + phi, r = d.r;
  const Vec3 A = rssrBall(phi, r);
  const Vec3 A1(-r * std::sin(t), r * std::cos(t), 0), A2(-r * std::cos(t), -r * std::sin(t), 0);
  const Vec3 C = d.H + kW * (std::cos(psi) * kX + std::sin(psi) * kY);
  const Vec3 C1 = kW * (-std::sin(psi) * kX + std::cos(psi) * kY);
  const Vec3 C2 = -kW * (std::cos(psi) * kX + std::sin(psi) * kY);
  const Vec3 D = A - C;
  const double Fphi = 2 * D.dot(A1), Fpsi = -2 * D.dot(C1);
  const double d1 = -Fphi / Fpsi;
  const double Fpp = 2 * (A1.dot(A1) + D.dot(A2)), Fps = -2 * A1.dot(C1),
               Fss = 2 * (C1.dot(C1) - D.dot(C2));
  const double d2 = -(Fpp + 2 * Fps * d1 + Fss * d1 * d1) / Fpsi;
  return {psi, d1, d2};
}
// The root nearest `near` (as an angle near it, whole turns counted).
inline Rocker rockerNear(double phi, double near, double l, const RssrDims& d = {}) {
  const RssrEquation e = rssrEquation(phi, l, d);
  double psi = e.root(1);
  const double other = e.root(-1);
  auto gap = [&](double x) { return std::abs(std::remainder(x - near, 2 * M_PI)); };
  if (gap(other) < gap(psi)) psi = other;
  return rockerAt(phi, near + std::remainder(psi - near, 2 * M_PI), d);
}

namespace lockstitch_bevel {
inline Vec3 hookK(double phi) {
  return Vec3(20 - 25 * std::sin(2 * phi), -200 + 25 * std::cos(2 * phi), 0);
}
// The needle bar's point `below` mm under its block B, which is below the crank pin
// A = 16 (-sin phi, cos phi) in the needle's plane (its y is the world's).
inline Vec3 needleAt(double phi, double below) {
  const double ax = -16 * std::sin(phi), ay = 16 * std::cos(phi);
  return Vec3(0, ay - std::sqrt(45 * 45 - ax * ax) - below, 0);
}
}  // namespace lockstitch_bevel

// A lone crank turning in a plane through the world's origin inclined rho about the world's x
// axis (x (1, 0, 0), y (0, cos rho, sin rho), normal (0, -sin rho, cos rho)), pinned to the
// ground at the origin: its centre of mass at kCom in its plane, kKg, kJ about it, at kRpm.
namespace inclined_crank {
constexpr double kRho = 35 * M_PI / 180, kKg = 0.4, kJ = 300, kRpm = 300;
inline const Vec2 kCom(12, 5);
inline const Vec3 kX(1, 0, 0), kY(0, std::cos(kRho), std::sin(kRho)), kN = kX.cross(kY);
// The model's text with `gravity` (the file's array text, "" for none) and `more` bodies' text
// (each a JSON object, after the crank's) and joints (after the crank's pin), for machines built
// on it.
inline std::string text(const std::string& gravity, const std::string& moreBodies = "",
                        const std::string& moreJoints = "", const std::string& morePlanes = "") {
  return R"({"format": "linkage", "version": 1, "name": "a crank in an inclined plane",
    "units": {"length": "mm"},
    "planes": {"tilted": {"origin": [0, 0, 0], "x_axis": )" +
         vec(kX) + R"(, "y_axis": )" + vec(kY) + "}" + morePlanes + R"(},
    "bodies": [
      {"name": "ground", "ground": true, "points": {"O": [0, 0, 0]}},
      {"name": "crank", "plane": "tilted", "points": {"O": [0, 0], "A": [30, 0]},
       "mass": {"kg": )" +
         num(kKg) + R"(, "com": )" + vec2(kCom) + R"(, "j_kg_mm2": )" + num(kJ) + "}}" +
         moreBodies + R"(],
    "joints": [{"type": "pin", "a": "ground.O", "b": "crank.O"})" +
         moreJoints + R"(],
    "driver": {"joint": 0, "rpm": )" +
         num(kRpm) + R"(, "direction": "ccw"})" +
         (gravity.empty() ? "" : ", \"gravity\": " + gravity) + "}";
}
}  // namespace inclined_crank

// Two cranks on crossed shafts joined by a bevel pair of ratio 1: "one" in the drawing plane
// about the z axis (driven), "two" in the plane x = 50 about the x axis (x (0, 1, 0), y (0, 0,
// 1)); each a mass off its axis: one's at kCom1, two's kR2 along its x.
namespace crossed_cranks {
constexpr double kKg1 = 0.3, kKg2 = 0.2, kR2 = 15, kRpm = 600;
inline const Vec2 kCom1(10, 4);
inline std::string text() {
  return R"({"format": "linkage", "version": 1, "name": "cranks on crossed shafts",
    "units": {"length": "mm"},
    "planes": {"side": {"origin": [50, 0, 0], "x_axis": [0, 1, 0], "y_axis": [0, 0, 1]}},
    "bodies": [
      {"name": "ground", "ground": true, "points": {"O": [0, 0], "S": [50, 0, 0]}},
      {"name": "one", "points": {"O": [0, 0], "A": [20, 0]},
       "mass": {"kg": )" +
         num(kKg1) + R"(, "com": )" + vec2(kCom1) + R"(, "j_kg_mm2": 50}},
      {"name": "two", "plane": "side", "points": {"S": [0, 0], "B": [25, 0]},
       "mass": {"kg": )" +
         num(kKg2) + R"(, "com": [)" + num(kR2) + R"(, 0], "j_kg_mm2": 80}}],
    "joints": [{"type": "pin", "a": "ground.O", "b": "one.O"},
               {"type": "pin", "a": "ground.S", "b": "two.S"},
               {"type": "gear", "a": "one.O", "b": "two.S", "ratio": 1}],
    "driver": {"joint": 0, "rpm": )" +
         num(kRpm) + R"(, "direction": "ccw"}})";
}
}  // namespace crossed_cranks

}  // namespace linkage::test
