// A cam's profile and checks (linkage/cam_checks.h) against closed forms written here: the
// pressure angle of an offset translating roller follower, atan((s' - e) / (d0 + s)) (the
// spec's), a flat face's radius base + s + s'', a dwell's pitch circle; the extremes against a
// search of those closed forms (a grid of 36,000 then golden sections), never the program's
// own functions; and an oscillating follower's pitch curve against its tangent and curvature by
// central differences of its points.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "linkage/cam_checks.h"

namespace linkage::cam {
namespace {

constexpr double kDeg = M_PI / 180;

Program program(double rise) {
  return Program({{90, rise, Law::Cycloidal},
                  {150, 0, std::nullopt},
                  {270, -rise, Law::Polynomial345},
                  {360, 0, std::nullopt}});
}

CamGeometry offsetRoller(double base = 30, double roller = 8, double e = 6) {
  CamGeometry g;
  g.motion = FollowerMotion::Translating;
  g.face = roller > 0 ? FollowerFace::Roller : FollowerFace::Knife;
  g.baseMm = base;
  g.rollerMm = roller;
  g.program = program(10);
  g.u = Vec2(0, 1);
  g.offsetMm = e;
  return g;
}

// The largest of f over a turn, by a grid of 36,000 and a golden-section search about its best.
struct Max {
  double value, deg;
};
Max searchMax(const std::function<double(double)>& f) {
  Max best{-INFINITY, 0};
  for (int i = 0; i < 36000; ++i) {
    const double v = f(i * 0.01 * kDeg);
    if (v > best.value) best = {v, i * 0.01};
  }
  double a = (best.deg - 0.01) * kDeg, b = (best.deg + 0.01) * kDeg;
  const double r = (std::sqrt(5.0) - 1) / 2;
  for (int i = 0; i < 100; ++i) {
    const double c = b - r * (b - a), d = a + r * (b - a);
    (f(c) > f(d) ? b : a) = f(c) > f(d) ? d : c;
  }
  const double x = (a + b) / 2;
  return {std::max(best.value, f(x)), f(x) >= best.value ? x / kDeg : best.deg};
}

TEST(CamProfile, AnOffsetRollersPressureAngleIsTheSpecsClosedForm) {
  const CamGeometry g = offsetRoller();
  const double d0 = std::sqrt(38.0 * 38.0 - 36.0);
  auto closed = [&](double t) {
    const Displacement d = g.program.at(t);
    return std::atan((d.v - 6) / (d0 + d.s)) / kDeg;
  };
  for (int i = 0; i < 720; ++i) {
    const double t = i * 0.5 * kDeg;
    EXPECT_NEAR(camPointAt(g, t).pressureDeg, closed(t), 1e-11) << i * 0.5;
  }
  const CamChecks c = camChecks(g);
  const Max want = searchMax([&](double t) { return std::abs(closed(t)); });
  ASSERT_TRUE(c.pressureMax.found);
  EXPECT_NEAR(c.pressureMax.value, want.value, 1e-9);
  EXPECT_NEAR(c.pressureMax.atDeg, want.deg, 1e-4);
  EXPECT_GT(c.pressureMax.value, 10);  // a real rise, not a flat answer
}

TEST(CamProfile, TheRollerRunsOnTheSurfaceAndADwellIsACircle) {
  const CamGeometry g = offsetRoller();
  for (double deg : {10.0, 45.0, 100.0, 200.0, 300.0}) {
    const CamPoint p = camPointAt(g, deg * kDeg);
    EXPECT_NEAR((p.pitch - p.surface).norm(), 8, 1e-12) << deg;
  }
  // In the dwell at the top the follower's point stands still in the guide: on the cam it runs
  // on a circle through it about the centre, of radius sqrt(e^2 + (d0 + 10)^2); the surface's
  // radius is that less the roller's.
  const double R = std::hypot(6.0, std::sqrt(38.0 * 38.0 - 36.0) + 10);
  const CamPoint p = camPointAt(g, 120 * kDeg);
  EXPECT_NEAR(p.pitch.norm(), R, 1e-12);
  EXPECT_NEAR(p.radiusMm, R - 8, 1e-9);
  // The drawing: b at d0 along u, e along w = u turned clockwise (here +x).
  const CamPoint z = camPointAt(g, 0);
  EXPECT_NEAR((z.pitch - Vec2(6, std::sqrt(38.0 * 38.0 - 36.0))).norm(), 0, 1e-12);
}

TEST(CamProfile, AFlatFacesRadiusIsBasePlusSPlusSDoublePrime) {
  CamGeometry g = offsetRoller(30, 0, 0);
  g.face = FollowerFace::Flat;
  auto closed = [&](double t) {
    const Displacement d = g.program.at(t);
    return 30 + d.s + d.a;
  };
  for (int i = 0; i < 360; ++i)
    EXPECT_NEAR(camPointAt(g, i * kDeg).radiusMm, closed(i * kDeg), 1e-10) << i;
  // Its contact is s' from the face's centre line (towards w at a rise).
  const double t = 45 * kDeg;
  const Displacement d = g.program.at(t);
  const Vec2 guide = (30 + d.s) * Vec2(0, 1) + d.v * Vec2(1, 0);
  EXPECT_NEAR((camPointAt(g, t).surface - Rot::of(-t) * guide).norm(), 0, 1e-12);
  CamChecks c = camChecks(g);
  const Max least = searchMax([&](double t) { return -closed(t); });
  ASSERT_TRUE(c.surfaceRadiusMin.found);
  EXPECT_NEAR(c.surfaceRadiusMin.value, -least.value, 1e-9);
  EXPECT_FALSE(c.undercut);
  // A small base with the same rise: the surface turns concave, which a flat face cannot touch.
  g.baseMm = 5;
  g.program = program(10);
  c = camChecks(g);
  EXPECT_LT(c.surfaceRadiusMin.value, 0);
  EXPECT_TRUE(c.undercut);
  EXPECT_NE(c.undercutWhy.find("not convex"), std::string::npos) << c.undercutWhy;
}

TEST(CamProfile, ARollerLargerThanThePitchCurvesRadiusUndercuts) {
  const CamGeometry small = offsetRoller(30, 8, 6);
  const CamChecks ok = camChecks(small);
  ASSERT_TRUE(ok.pitchRadiusMin.found);
  EXPECT_FALSE(ok.undercut);
  // The same pitch curve (base + roller kept at 38) with a roller past its smallest radius.
  const CamGeometry big =
      offsetRoller(38 - (ok.pitchRadiusMin.value + 1), ok.pitchRadiusMin.value + 1, 6);
  const CamChecks c = camChecks(big);
  EXPECT_NEAR(c.pitchRadiusMin.value, ok.pitchRadiusMin.value, 1e-9);
  EXPECT_TRUE(c.undercut);
  EXPECT_NE(c.undercutWhy.find("larger than the pitch curve"), std::string::npos);
}

TEST(CamProfile, AnOscillatingFollowersPitchCurveAgreesWithItsPointsDifferences) {
  CamGeometry g;
  g.motion = FollowerMotion::Oscillating;
  g.face = FollowerFace::Roller;
  g.baseMm = 25;
  g.rollerMm = 6;
  g.program = Program({{120, 15, Law::ModifiedSine},
                       {180, 0, std::nullopt},
                       {300, -15, Law::ModifiedTrapezoid},
                       {360, 0, std::nullopt}},
                      kDeg);
  g.pivot = Vec2(50, 10);
  g.b0 = Vec2(0, 31);  // |b0| = base + roller
  g.sigma = g.b0.dot(perp(g.b0 - g.pivot)) > 0 ? 1 : -1;
  ASSERT_EQ(checkCamGeometry(g), "");
  const double h = 1e-4;
  for (double deg = 7; deg < 360; deg += 23) {
    const double t = deg * kDeg;
    const CamPoint p = camPointAt(g, t);
    const Vec2 a = camPointAt(g, t - h).pitch, b = camPointAt(g, t + h).pitch;
    const Vec2 d1 = (b - a) / (2 * h), d2 = (b - 2 * p.pitch + a) / (h * h);
    // The pressure angle from the tangent: b's motion m against the normal (outward: the
    // curve runs clockwise), in the guide's frame.
    const double psi =
        std::atan2(g.b0.y() - g.pivot.y(), g.b0.x() - g.pivot.x()) + g.sigma * g.program.at(t).s;
    const Vec2 m = g.sigma * perp(Vec2(std::cos(psi), std::sin(psi)));
    const Vec2 n = perp(Rot::of(t) * d1);
    EXPECT_NEAR(p.pressureDeg, std::atan(cross(m, n) / m.dot(n)) / kDeg, 1e-5) << deg;
    const double rho = -std::pow(d1.norm(), 3) / cross(d1, d2);
    EXPECT_NEAR(p.radiusMm + g.rollerMm, rho, 1e-4 * std::abs(rho)) << deg;
  }
  // As the follower rises its point leaves the cam's centre.
  EXPECT_GT(camPointAt(g, 120 * kDeg).pitch.norm(), camPointAt(g, 0).pitch.norm() + 1);
}

// A knife edge is a roller of no radius: the spec's closed form with base for base + roller,
// atan((s' - e) / (sqrt(base^2 - e^2) + s)), with and without offset, and its largest.
TEST(CamProfile, AKnifeEdgesPressureAngleIsTheClosedFormWithAndWithoutOffset) {
  for (double e : {6.0, 0.0, -9.0}) {
    const CamGeometry g = offsetRoller(30, 0, e);
    ASSERT_EQ(g.face, FollowerFace::Knife);
    const double d0 = std::sqrt(30.0 * 30.0 - e * e);
    auto closed = [&](double t) {
      const Displacement d = g.program.at(t);
      return std::atan((d.v - e) / (d0 + d.s)) / kDeg;
    };
    for (int i = 0; i < 720; ++i) {
      const double t = i * 0.5 * kDeg;
      const CamPoint p = camPointAt(g, t);
      EXPECT_NEAR(p.pressureDeg, closed(t), 1e-11) << e << " at " << i * 0.5;
      EXPECT_NEAR((p.surface - p.pitch).norm(), 0, 1e-12) << e << " at " << i * 0.5;
    }
    const CamChecks c = camChecks(g);
    const Max want = searchMax([&](double t) { return std::abs(closed(t)); });
    ASSERT_TRUE(c.pressureMax.found) << e;
    EXPECT_NEAR(c.pressureMax.value, want.value, 1e-9) << e;
    EXPECT_NEAR(c.pressureMax.atDeg, want.deg, 1e-4) << e;
  }
}

// A flat face's radius does not depend on its offset: base + s + s'' with the face's line off
// the cam's centre too, and the checks' smallest against a search of it.
TEST(CamProfile, AnOffsetFlatFacesRadiusIsBasePlusSPlusSDoublePrime) {
  CamGeometry g = offsetRoller(30, 0, 7);
  g.face = FollowerFace::Flat;
  auto closed = [&](double t) {
    const Displacement d = g.program.at(t);
    return 30 + d.s + d.a;
  };
  for (int i = 0; i < 720; ++i)
    EXPECT_NEAR(camPointAt(g, i * 0.5 * kDeg).radiusMm, closed(i * 0.5 * kDeg), 1e-10) << i;
  const CamChecks c = camChecks(g);
  const Max least = searchMax([&](double t) { return -closed(t); });
  ASSERT_TRUE(c.surfaceRadiusMin.found);
  EXPECT_NEAR(c.surfaceRadiusMin.value, -least.value, 1e-9);
  EXPECT_NEAR(c.surfaceRadiusMin.atDeg, least.deg, 1e-4);
}

// An oscillating follower about c, its point b0 as drawn (the cam's centre a at the origin).
CamGeometry oscillating(FollowerFace face, double base, double roller, Vec2 pivot, Vec2 b0) {
  CamGeometry g;
  g.motion = FollowerMotion::Oscillating;
  g.face = face;
  g.baseMm = base;
  g.rollerMm = roller;
  g.program = Program({{100, 18, Law::Cycloidal},
                       {170, 0, std::nullopt},
                       {290, -18, Law::Polynomial345},
                       {360, 0, std::nullopt}},
                      kDeg);
  g.pivot = pivot;
  g.b0 = b0;
  // The spec: a rise moves b away from a. Turning counter-clockwise about c moves b along
  // J (b0 - c); sigma is +1 when that leaves a.
  g.sigma = b0.dot(perp(b0 - pivot)) > 0 ? 1 : -1;
  return g;
}

// The cam's and the follower's instant centre by Kennedy's rule, written here: on the line of
// a (the origin) and the pivot c, where the cam (omega 1) and the rocker (omega3 = sigma s')
// have the same velocity: I = omega3 c / (omega3 - 1). The common normal passes through it.
struct Rocker {
  Vec2 b, m, I, nu, face;  // the follower's point, its motion, the centre, a flat face's normal
                           // and a point of that face, in the guide's frame
};
Rocker rockerAt(const CamGeometry& g, double t) {
  const Displacement d = g.program.at(t);
  const Vec2 arm0 = g.b0 - g.pivot;
  const double psi = g.sigma * d.s;
  const Vec2 arm = Rot::of(psi) * arm0;
  const double w3 = g.sigma * d.v;
  return {g.pivot + arm, g.sigma * perp(arm.normalized()), w3 * g.pivot / (w3 - 1),
          Rot::of(psi) * g.b0.normalized(), g.pivot + arm};
}

// Roller and knife edge: the pressure angle between b's motion m and the normal through b and
// I (b is on the normal: the roller's centre, or the knife's edge), |atan(m x n / m . n)|.
TEST(CamProfile, AnOscillatingFollowersPressureAngleIsKennedysClosedForm) {
  const CamGeometry followers[] = {
      oscillating(FollowerFace::Roller, 25, 6, Vec2(50, 10), Vec2(0, 31)),
      oscillating(FollowerFace::Knife, 31, 0, Vec2(50, 10), Vec2(0, 31)),
      oscillating(FollowerFace::Roller, 22, 8, Vec2(-40, 25), Vec2(18, 24)),  // |b0| = 30
  };
  for (const CamGeometry& g : followers) {
    ASSERT_EQ(checkCamGeometry(g), "");
    auto closed = [&](double t) {
      const Rocker r = rockerAt(g, t);
      const Vec2 n = r.b - r.I;
      return std::abs(std::atan(cross(r.m, n) / r.m.dot(n))) / kDeg;
    };
    for (int i = 0; i < 720; ++i) {
      const double t = i * 0.5 * kDeg;
      EXPECT_NEAR(std::abs(camPointAt(g, t).pressureDeg), closed(t), 1e-9)
          << g.pivot.x() << " " << i * 0.5;
    }
    const CamChecks c = camChecks(g);
    const Max want = searchMax(closed);
    ASSERT_TRUE(c.pressureMax.found);
    EXPECT_NEAR(c.pressureMax.value, want.value, 1e-9) << g.pivot.x();
    EXPECT_NEAR(c.pressureMax.atDeg, want.deg, 1e-4) << g.pivot.x();
    EXPECT_GT(want.value, 10) << g.pivot.x();  // a real rise
  }
}

// A flat face: the contact is the foot of the perpendicular from I to the face's line (the
// normal to the face through the centre); on the cam, R(-theta) of it. Its radius of curvature
// by central differences of those points (the curve runs clockwise on the cam: convex positive
// is -|p'|^3 / (p' x p'')).
TEST(CamProfile, AnOscillatingFlatFacesContactAndRadiusAreKennedys) {
  const CamGeometry g = oscillating(FollowerFace::Flat, 30, 0, Vec2(50, 30), Vec2(0, 30));
  ASSERT_EQ(checkCamGeometry(g), "");
  auto contact = [&](double t) {
    const Rocker r = rockerAt(g, t);
    return Vec2(Rot::of(-t) * (r.I + (r.face - r.I).dot(r.nu) * r.nu));
  };
  const double h = 1e-4;
  double least = INFINITY;
  for (double deg = 0.25; deg < 360; deg += 0.5) {
    const double t = deg * kDeg;
    const CamPoint p = camPointAt(g, t);
    const Vec2 c = contact(t);
    EXPECT_NEAR((p.surface - c).norm(), 0, 1e-9) << deg;
    const Vec2 a = contact(t - h), b = contact(t + h);
    const Vec2 d1 = (b - a) / (2 * h), d2 = (b - 2 * c + a) / (h * h);
    const double rho = -std::pow(d1.norm(), 3) / cross(d1, d2);
    EXPECT_NEAR(p.radiusMm, rho, 1e-4 * std::max(1.0, std::abs(rho))) << deg;
    least = std::min(least, rho);
  }
  const CamChecks c = camChecks(g);
  ASSERT_TRUE(c.surfaceRadiusMin.found);
  EXPECT_LE(c.surfaceRadiusMin.value, least + 1e-3);  // the checks' extreme is the least
  EXPECT_GT(c.surfaceRadiusMin.value, least - 0.1);   // and near the sampled one
}

TEST(CamProfile, BadGeometryIsNamed) {
  CamGeometry g = offsetRoller(30, 8, 40);
  EXPECT_NE(checkCamGeometry(g).find("offset"), std::string::npos);
  g = offsetRoller(0, 8, 0);
  EXPECT_NE(checkCamGeometry(g).find("base"), std::string::npos);
}

// The smallest base for a pressure-angle limit: the closed form's largest angle at that base is
// the limit (to rounding), and a hair less base exceeds it.
TEST(CamProfile, TheSmallestBaseForAPressureAngleLimitMeetsItExactly) {
  const CamGeometry g = offsetRoller(30, 8, 6);
  const std::optional<double> base = smallestBaseFor(g, 30);
  ASSERT_TRUE(base);
  EXPECT_LT(*base, 30);  // the drawn 30 mm is more than the limit needs
  auto largest = [&](double b) {
    const double d0 = std::sqrt((b + 8) * (b + 8) - 36);
    return searchMax([&](double t) {
             const Displacement d = g.program.at(t);
             return std::abs(std::atan((d.v - 6) / (d0 + d.s))) / kDeg;
           })
        .value;
  };
  EXPECT_NEAR(largest(*base), 30, 1e-6);
  EXPECT_GT(largest(*base - 1e-3), 30);
  EXPECT_FALSE(smallestBaseFor(g, 0));  // no limit to meet
  // An oscillating follower: the limit met at the base found (its own checks).
  CamGeometry o = offsetRoller();
  o.motion = FollowerMotion::Oscillating;
  o.program = Program({{120, 15, Law::Cycloidal}, {360, -15, Law::Cycloidal}}, kDeg);
  o.pivot = Vec2(55, 38);  // the arm square to the radius as drawn
  o.b0 = Vec2(0, 38);
  o.sigma = o.b0.dot(perp(o.b0 - o.pivot)) > 0 ? 1 : -1;
  const std::optional<double> ob = smallestBaseFor(o, 35);
  ASSERT_TRUE(ob);
  EXPECT_NEAR(camChecks(withBase(o, *ob)).pressureMax.value, 35, 1e-6);
  EXPECT_GT(camChecks(withBase(o, *ob - 1e-3)).pressureMax.value, 35);
  EXPECT_NEAR((withBase(o, *ob).b0 - o.pivot).norm(), (o.b0 - o.pivot).norm(), 1e-12);
}

// The largest roller without undercut, the pitch curve kept: at it the check says no undercut
// a hair below and undercut a hair above.
TEST(CamProfile, TheLargestRollerIsThePitchCurvesSmallestConvexRadius) {
  const CamGeometry g = offsetRoller(30, 8, 6);
  const std::optional<double> r = largestRoller(g);
  ASSERT_TRUE(r);
  for (double d : {-1e-6, 1e-6}) {
    CamGeometry h = offsetRoller(38 - (*r + d), *r + d, 6);
    EXPECT_EQ(camChecks(h).undercut, d > 0) << d;
  }
}

}  // namespace
}  // namespace linkage::cam
