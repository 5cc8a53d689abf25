// A pin in an arc slot's reaction (and its crank's and rod's pins') differentiated with respect
// to every dimension (linkage/force_sensitivity.h), the arc's centre and radius included, against
// the changed designs (tests/reaction_checks.h). (The arc's row is scaled by 1 / rho; a reaction,
// lambda times the row's gradient, does not depend on a row's scale, so the scale's change with
// the radius cancels between dlambda and dJ.)
#include <gtest/gtest.h>

#include <cmath>

#include "reaction_checks.h"

namespace linkage {
namespace {

TEST(ArcForceSensitivity, APinInAnArcMovesAsChangedDesignsDo) {
  Mechanism m;
  const BodyId ground = m.addBody("ground", true), crank = m.addBody("crank"),
               rod = m.addBody("rod");
  const Vec2 c(40, 0);  // a crank-rocker: crank 15, rod 37.7, rocker 40, frame 40
  const double R = 40;
  auto on = [&](double deg) {
    return Vec2(c + R * Vec2(std::cos(deg * M_PI / 180), std::sin(deg * M_PI / 180)));
  };
  const SlotId track = m.addArcSlot(ground, "track", on(20), on(100), on(180));
  const Vec2 A(15 * std::cos(M_PI / 6), 15 * std::sin(M_PI / 6)), B = on(100);
  const JointId drive =
      m.addPin(m.addPoint(ground, "O", Vec2(0, 0)), m.addPoint(crank, "O", Vec2(0, 0)));
  m.addPin(m.addPoint(crank, "A", A), m.addPoint(rod, "A", A));
  m.addPinInSlot(m.addPoint(rod, "B", B), track);
  m.body(crank)->mass = Mass{0.2, Vec2(6, 5), 30, ""};
  m.body(rod)->mass = Mass{0.3, 0.5 * (A + B) + Vec2(2, -3), 120, ""};
  m.gravity = Vec2(0, -9.81);
  m.driver = Driver{drive, 900, Direction::Ccw, 0, ""};
  bool radius = false;
  for (const Dimension& d : dimensions(m)) radius = radius || d.name == "ground.track.radius";
  ASSERT_TRUE(radius);
  test::expectReactionsMoveAsChangedDesignsDo(m, 30);
}

}  // namespace
}  // namespace linkage
