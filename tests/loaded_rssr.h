// The RSSR crank-rocker (resources/examples) loaded for the force tests (masses on its crank and
// rocker, gravity across both planes; the same machine with one body drawn in a plane turned in
// its class), and the searches over it those tests run.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "examples.h"
#include "linkage/optimize.h"
#include "linkage/optimize_text.h"
#include "linkage/sensitivity.h"
#include "linkage/space.h"

namespace linkage::test {

// The RSSR with masses on its crank and rocker and gravity across both planes.
inline Mechanism loadedRssr() {
  Mechanism m = test::example("rssr-crank-rocker");
  Body* crank = m.body(m.bodyNamed("crank")->id);
  Body* rocker = m.body(m.bodyNamed("rocker")->id);
  const Vec2 c0 = m.point(*m.findPoint("crank.A"))->pos,
             r0 = m.point(*m.findPoint("rocker.C"))->pos;
  crank->mass = Mass{0.3, 0.5 * c0 + Vec2(2, -1), 60, ""};
  rocker->mass = Mass{0.2, 0.6 * r0 + Vec2(-3, 2), 90, ""};
  m.gravity = Vec2(0, -9.81);
  m.gravityZ = -3.0;
  return m;
}

// The loaded RSSR with one body drawn in a plane turned 35 degrees in its own plane's class (the
// same machine): a counterweight's moment on it is turned into the class frame.
inline Mechanism turned(const char* name) {
  Mechanism m = loadedRssr();
  Body* body = m.body(m.bodyNamed(name)->id);
  const Plane own = planeNamed(m, body->plane) ? *planeNamed(m, body->plane) : drawingPlane();
  const double a = 35 * M_PI / 180;
  const Rot back = Rot::of(-a);
  Plane turned = own;
  turned.name = "turned";
  turned.xAxis = std::cos(a) * own.xAxis + std::sin(a) * own.yAxis;
  turned.yAxis = -std::sin(a) * own.xAxis + std::cos(a) * own.yAxis;
  m.planes->push_back(turned);
  body->plane = "turned";
  for (Point& q : m.points)
    if (q.body == body->id) q.pos = back * q.pos;
  body->mass->com = back * body->mass->com;
  return m;
}

// A search over a depth, the rod's length and a plane's origin for the target `text`, and the
// design's values of those (where the gradient is checked).
inline OptimizeSpec spaceSpec(const Mechanism& m, const char* text, std::vector<double>& x) {
  OptimizeSpec spec;
  spec.variables = {{"crank.A.depth", -20, 20},
                    {"ball-rod:crank.A.length", 70, 90},
                    {"planes.rocker.origin.x", 30, 60}};
  std::string why;
  OptTarget t;
  EXPECT_TRUE(parseOptTarget(m, text, t, why)) << why;
  spec.targets = {t};
  x.clear();
  for (const OptVariable& v : spec.variables)
    for (const Dimension& d : dimensions(m))
      if (d.name == v.name) x.push_back(d.value);
  return spec;
}

// The crank's and the rocker's counterweights as variables (x, y each, -60 to 60 kg mm).
inline OptimizeSpec bothCounterweights() {
  OptimizeSpec spec;
  for (const char* body : {"crank", "rocker"})
    for (const char* axis : {".counterweight.x", ".counterweight.y"})
      spec.variables.push_back({std::string(body) + axis, -60, 60});
  return spec;
}

}  // namespace linkage::test
