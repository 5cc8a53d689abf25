// Sensitivities (linkage/sensitivity.h) against closed forms differentiated by complex step: the
// closed form of the point's position written over std::complex, each dimension stepped by i h
// (h = 1e-30), the derivative Im / h, exact to rounding and independent of the solver's rows.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <complex>
#include <cstdio>
#include <map>

#include "complex_step.h"
#include "examples.h"
#include "linkage/guide.h"
#include "linkage/kinematics.h"
#include "linkage/sensitivity.h"
#include "mechanisms.h"

namespace linkage {
namespace {

using test::C;
using test::CVec;
using test::kH;
// A point, its velocity and its acceleration per radian (and radian squared) of crank.
struct PV {
  CVec p, v, a;
};
// d(point), d(velocity), d(acceleration) of a closed form stepped by i kH.
std::array<Vec2, 3> imaginary(const PV& x) {
  auto im = [](const CVec& c) -> Vec2 { return Vec2(c.x.imag(), c.y.imag()) / kH; };
  return {im(x.p), im(x.v), im(x.a)};
}

// The four-bar's coupler point in the dimensions' own terms: the ground pivots, the crank, the
// coupler's A-B, B-P and A-P, the rocker's B-O4; the crank at its drawn angle plus phi.
struct FourBarDims {
  std::map<std::string, C> v;
  double crankRad = 0;
  bool open = true;
  PV P(double phi) const {
    const CVec O2{v.at("ground.O2.x"), v.at("ground.O2.y")};
    const CVec O4{v.at("ground.O4.x"), v.at("ground.O4.y")};
    const C r2 = v.at("crank.O2-A"), r3 = v.at("coupler.A-B"), r4 = v.at("rocker.B-O4");
    const C ap = v.at("coupler.A-P"), bp = v.at("coupler.B-P");
    const double t = crankRad + phi;
    const CVec A = O2 + CVec{r2 * std::cos(t), r2 * std::sin(t)};
    const CVec D = O4 - A;
    const C d2 = dot(D, D), d = std::sqrt(d2);
    const C m = (r3 * r3 - r4 * r4 + d2) / (2.0 * d);
    const C h = (open ? 1.0 : -1.0) * std::sqrt(r3 * r3 - m * m);
    const CVec B = A + (m / d) * D + (h / d) * perp(D);
    const CVec u = (1.0 / r3) * (B - A);
    const C px = (r3 * r3 + ap * ap - bp * bp) / (2.0 * r3);
    const C py = std::sqrt(ap * ap - px * px);  // P drawn to the left of A->B
    const CVec q = px * u + py * perp(u);       // A -> P
    // The loop's rates (reference/four_bar.h): the coupler's and rocker's by Cramer's rule.
    const CVec a = A - O2, b = B - A, c = B - O4;
    const C det = b.y * c.x - c.y * b.x;
    auto solve = [&](C r0, C r1, C& u3, C& u4) {
      u3 = (r0 * (-c.x) - c.y * r1) / det;
      u4 = ((-b.y) * r1 - b.x * r0) / det;
    };
    C w3, w4, al3, al4;
    solve(a.y, -a.x, w3, w4);
    solve(a.x + b.x * w3 * w3 - c.x * w4 * w4, a.y + b.y * w3 * w3 - c.y * w4 * w4, al3, al4);
    return {A + q, perp(a) + w3 * perp(q), (-1.0) * a + al3 * perp(q) - (w3 * w3) * q};
  }
};

// Largest error of every dimension's derivatives of the point's position, velocity and
// acceleration over a turn, each relative to its peak over the turn; `exact(name, phi)` gives the
// independent three (per radian and radian squared of crank).
template <class Exact>
double worstRelative(Kinematics& k, PointId p, const std::vector<Dimension>& dims, Exact exact,
                     std::vector<std::string>& compared, const std::string& still = "") {
  Sensitivity s;
  EXPECT_TRUE(s.prepare(k, dims).ok());
  const size_t n = dims.size();
  std::vector<std::array<double, 3>> peak(n, {0, 0, 0}), err(n, {0, 0, 0});
  for (int deg = 0; deg < 360; deg += 5) {
    EXPECT_TRUE(k.moveTo(deg).ok()) << deg;
    EXPECT_TRUE(s.at(k).ok()) << deg;
    const double w = k.omega();
    for (size_t d = 0; d < n; ++d) {
      const int i = static_cast<int>(d);
      const std::array<Vec2, 3> want = exact(dims[d].name, deg * M_PI / 180);
      const Vec2 got[3] = {s.point(k, p, i), s.velocity(k, p, i) / w,
                           s.acceleration(k, p, i) / (w * w)};
      for (int o = 0; o < 3; ++o) {
        peak[d][o] = std::max(peak[d][o], want[o].norm());
        err[d][o] = std::max(err[d][o], (got[o] - want[o]).norm());
      }
    }
  }
  // A rate a dimension does not change (moving a slider-crank's pivot along its slot) is
  // measured against the largest peak of that rate.
  double any[3] = {0, 0, 0}, worst = 0;
  for (size_t d = 0; d < n; ++d)
    for (int o = 0; o < 3; ++o) any[o] = std::max(any[o], peak[d][o]);
  for (size_t d = 0; d < n; ++d) {
    compared.push_back(dims[d].name);
    if (dims[d].name != still)  // `still`: the closed form says it does not move the point
      EXPECT_GT(peak[d][0], 1e-3) << dims[d].name
                                  << ": a dimension that moves nothing tests nothing";
    double rel[3];
    for (int o = 0; o < 3; ++o) {
      rel[o] = err[d][o] / (peak[d][o] > 1e-12 ? peak[d][o] : any[o]);
      worst = std::max(worst, rel[o]);
    }
    std::printf("  %-20s error/peak: position %.2e  velocity %.2e  acceleration %.2e\n",
                dims[d].name.c_str(), rel[0], rel[1], rel[2]);
  }
  return worst;
}

TEST(Sensitivity, FourBarDimensionsNamedAsTheEditorNamesThem) {
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  std::vector<std::string> names;
  for (const Dimension& d : dimensions(f.m)) names.push_back(d.name);
  const std::vector<std::string> want = {"ground.O2.x", "ground.O2.y", "ground.O4.x",
                                         "ground.O4.y", "crank.O2-A",  "coupler.A-B",
                                         "coupler.B-P", "coupler.A-P", "rocker.B-O4"};
  EXPECT_EQ(names, want);
}

// Issue 29's test: a four-bar's coupler point against the closed form's derivatives with
// respect to each link length and the ground pivots, to 1e-10 of peak, open and crossed.
TEST(Sensitivity, FourBarCouplerPointMatchesClosedFormToTenDigits) {
  for (bool open : {true, false}) {
    const test::FourBar f = test::fourBar(60, 20, 70, 50, 60, open, 35, 25);
    Kinematics k;
    ASSERT_TRUE(k.load(f.m).ok());
    const std::vector<Dimension> dims = dimensions(f.m);
    FourBarDims base;
    for (const Dimension& d : dims) base.v[d.name] = d.value;
    base.crankRad = 60 * M_PI / 180;
    base.open = open;
    auto exact = [&](const std::string& name, double phi) {
      FourBarDims stepped = base;
      stepped.v[name] += C(0, kH);
      return imaginary(stepped.P(phi));
    };
    ASSERT_NEAR(base.P(0).p.x.real(), k.position(f.P).x(), 1e-9);
    ASSERT_NEAR(base.P(0).v.y.real() * k.omega(), k.velocity(f.P).y(), 1e-9);
    ASSERT_NEAR(base.P(0).a.y.real() * k.omega() * k.omega(), k.acceleration(f.P).y(),
                1e-8);  // the same point
    std::vector<std::string> compared;
    std::printf("four-bar, %s:\n", open ? "open" : "crossed");
    const double worst = worstRelative(k, f.P, dims, exact, compared);
    EXPECT_EQ(compared.size(), 9u);
    EXPECT_LT(worst, 1e-10) << (open ? "open" : "crossed");
  }
}

// A slider-crank, block in a ground slot and pin in the slot: the slot's offset and angle too.
TEST(Sensitivity, SliderCrankMatchesClosedFormWithTheSlotsOffsetAndAngle) {
  const double r = 20, l = 70, e = 8, crankDeg = 30;
  for (bool pinInSlot : {false, true}) {
    const test::SliderCrank sc =
        test::sliderCrank(r, l, e, crankDeg, Direction::Ccw, 60, pinInSlot);
    Kinematics k;
    ASSERT_TRUE(k.load(sc.m).ok());
    const std::vector<Dimension> dims = dimensions(sc.m);
    std::map<std::string, C> base;
    for (const Dimension& d : dims) base[d.name] = 0;
    auto B = [&](const std::map<std::string, C>& v, double phi) {
      const CVec O{v.at("ground.O.x"), v.at("ground.O.y")};
      const C cr = r + v.at("crank.O-A"), rl = l + v.at("rod.A-B");
      const C alpha = M_PI / 2 + v.at("ground.guide.angle") * (M_PI / 180);
      // The slot's normal is perp of its direction (0, 1): (-1, 0) per mm of offset.
      const CVec p0{e - v.at("ground.guide.offset"), C(0)};
      const CVec dir{std::cos(alpha), std::sin(alpha)};
      const double t = crankDeg * M_PI / 180 + phi;
      const CVec A = O + CVec{cr * std::cos(t), cr * std::sin(t)};
      const CVec w = A - p0, vA = perp(A - O), aA = O - A;
      // B = p0 + t dir, t = dir . w + root, root = sqrt(l^2 - c^2), c = dir x w.
      const C c = cross(dir, w), c1 = cross(dir, vA), c2 = cross(dir, aA);
      const C root = std::sqrt(rl * rl - c * c);
      const C t1 = dot(dir, vA) - c * c1 / root;
      const C t2 =
          dot(dir, aA) - (c1 * c1 + c * c2) / root - c * c * c1 * c1 / (root * root * root);
      return PV{p0 + (dot(dir, w) + root) * dir, t1 * dir, t2 * dir};
    };
    for (const Dimension& d : dims)  // the closed form above counts from the drawn values
      if (d.name == "ground.O.x" || d.name == "ground.O.y") base[d.name] = d.value;
    auto exact = [&](const std::string& name, double phi) {
      std::map<std::string, C> v = base;
      v.at(name) += C(0, kH);
      return imaginary(B(v, phi));
    };
    ASSERT_NEAR(B(base, 0).p.y.real(), k.position(sc.B).y(), 1e-9);
    ASSERT_NEAR(B(base, 0).v.y.real() * k.omega(), k.velocity(sc.B).y(), 1e-9);
    ASSERT_NEAR(B(base, 0).a.y.real() * k.omega() * k.omega(), k.acceleration(sc.B).y(), 1e-8);
    std::vector<std::string> compared;
    std::printf("slider-crank, %s:\n", pinInSlot ? "pin in slot" : "block");
    const double worst = worstRelative(k, sc.B, dims, exact, compared);
    EXPECT_EQ(compared.size(), 6u);
    EXPECT_LT(worst, 1e-10) << (pinInSlot ? "pin in slot" : "block");
  }
}

// A gear's ratio: the planet on a fixed sun (resources/examples/planet-epicycloid), arm 30 from
// the sun's centre, P 10 from the planet's; the gear row gives the planet's angle (1 - ratio) phi.
TEST(Sensitivity, PlanetGearsRatioAndLengthsMatchTheEpicycloid) {
  const Mechanism m = test::example("planet-epicycloid");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const std::vector<Dimension> dims = dimensions(m);
  std::map<std::string, C> base;
  for (const Dimension& d : dims) base[d.name] = d.value;
  ASSERT_EQ(base.count("ground-planet.ratio"), 1u);
  ASSERT_EQ(base.at("ground-planet.ratio").real(), -2);
  auto P = [](const std::map<std::string, C>& v, double phi) {
    const C a = v.at("arm.S-B"), b = v.at("planet.B-P"),
            t = (1.0 - v.at("ground-planet.ratio")) * phi;
    const C wt = 1.0 - v.at("ground-planet.ratio");
    return PV{{v.at("ground.S.x") + a * std::cos(phi) + b * std::cos(t),
               v.at("ground.S.y") + a * std::sin(phi) + b * std::sin(t)},
              {-a * std::sin(phi) - b * wt * std::sin(t), a * std::cos(phi) + b * wt * std::cos(t)},
              {-a * std::cos(phi) - b * wt * wt * std::cos(t),
               -a * std::sin(phi) - b * wt * wt * std::sin(t)}};
  };
  auto exact = [&](const std::string& name, double phi) {
    std::map<std::string, C> v = base;
    v.at(name) += C(0, kH);
    return imaginary(P(v, phi));
  };
  const PointId out = *m.findPoint("planet.P");
  std::vector<std::string> compared;
  std::printf("planet gear:\n");
  const double worst = worstRelative(k, out, dims, exact, compared);
  EXPECT_EQ(compared.size(), 5u);
  EXPECT_LT(worst, 1e-10);
}

// Machines no closed form covers: moving the whole ground (its points and its straight slots)
// by a vector moves every point of the mechanism by that vector and changes no velocity or
// acceleration, so at
// every pose the ground's x derivatives (a slot's offset counted by its normal's x, an arc's
// centre by its own) add up to (1,
// 0) and the y ones to (0, 1), for every point of every body: every row kind and every slot,
// exactly.
TEST(Sensitivity, MovingTheGroundMovesEveryPointOfTheMachines) {
  for (const char* name : {"wanzer-inversion-2", "drop-feed", "lockstitch-machine",
                           "overedge-needle-arm", "needle-876-alpha-35", "gear-four-bar",
                           "lockstitch-arm-shaft", "slider-crank-22a-lambda-0.3", "lockstitch-cams",
                           "chainstitch-looper-cam", "curved-guide"}) {
    const Mechanism m = test::example(name);
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok()) << name;
    const BodyId ground = m.ground()->id;
    const std::vector<Dimension> dims = dimensions(m);
    std::vector<Vec2> weight(dims.size(), Vec2::Zero());  // (x, y) share of each dimension
    for (size_t d = 0; d < dims.size(); ++d) {
      const Dimension& dim = dims[d];
      for (const auto& [p, move] : dim.points)
        if (m.point(p)->body == ground) weight[d] = move;
      for (const Dimension::SlotMove& sm : dim.slots)
        if (m.slot(sm.slot)->body == ground && sm.p0 == sm.p1) weight[d] = sm.p0;  // offset
    }
    Sensitivity s;
    ASSERT_TRUE(s.prepare(k, dims).ok()) << name;
    double worst = 0;
    for (int deg = 0; deg < 360; deg += 15) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << name << " " << deg;
      ASSERT_TRUE(s.at(k).ok()) << name << " " << deg;
      for (const Point& p : m.points) {
        Vec2 x = Vec2::Zero(), y = Vec2::Zero(), vx = Vec2::Zero(), vy = Vec2::Zero(),
             ax = Vec2::Zero(), ay = Vec2::Zero();
        for (size_t d = 0; d < dims.size(); ++d) {
          const int i = static_cast<int>(d);
          x += weight[d].x() * s.point(k, p.id, i);
          y += weight[d].y() * s.point(k, p.id, i);
          vx += weight[d].x() * s.velocity(k, p.id, i) / k.omega();  // velocities do not change
          vy += weight[d].y() * s.velocity(k, p.id, i) / k.omega();
          ax += weight[d].x() * s.acceleration(k, p.id, i) / (k.omega() * k.omega());
          ay += weight[d].y() * s.acceleration(k, p.id, i) / (k.omega() * k.omega());
        }
        worst = std::max({worst, (x - Vec2(1, 0)).norm(), (y - Vec2(0, 1)).norm(), vx.norm(),
                          vy.norm(), ax.norm(), ay.norm()});
      }
    }
    std::printf("  %-28s moving the ground: worst error %.2e\n", name, worst);
    EXPECT_LT(worst, 1e-10) << name;
  }
}

// The drawing scaled about the origin scales the motion: each point's position at a crank angle
// (and its velocity and acceleration) is homogeneous of degree one in the lengths (angles and
// ratios kept), so by Euler's theorem sum over the lengths of length * d(position)/d(length) is the
// position itself. Every body's dimensions of the machines, exactly (a cam's base, roller and
// a translating follower's rises among them, an arc slot's centre and radius).
TEST(Sensitivity, ScalingTheDrawingScalesEveryPointOfTheMachines) {
  for (const char* name : {"wanzer-inversion-2", "drop-feed", "lockstitch-machine",
                           "overedge-needle-arm", "needle-876-alpha-35", "gear-four-bar",
                           "lockstitch-arm-shaft", "slider-crank-22a-lambda-0.3", "lockstitch-cams",
                           "chainstitch-looper-cam", "curved-guide"}) {
    const Mechanism m = test::example(name);
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok()) << name;
    const std::vector<Dimension> dims = dimensions(m);
    Sensitivity s;
    ASSERT_TRUE(s.prepare(k, dims).ok()) << name;
    double worst = 0, size = 0;
    for (int deg = 0; deg < 360; deg += 15) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << name << " " << deg;
      ASSERT_TRUE(s.at(k).ok()) << name << " " << deg;
      for (const Point& p : m.points) {
        Vec2 sum = Vec2::Zero(), sumV = Vec2::Zero(), sumA = Vec2::Zero();
        for (size_t d = 0; d < dims.size(); ++d)
          if (dims[d].unit == Dimension::Unit::Mm) {
            const int i = static_cast<int>(d);
            sum += dims[d].value * s.point(k, p.id, i);
            sumV += dims[d].value * s.velocity(k, p.id, i) / k.omega();
            sumA += dims[d].value * s.acceleration(k, p.id, i) / (k.omega() * k.omega());
          }
        // Velocities and accelerations per radian of crank (mm), homogeneous of degree one too.
        const Vec2 v = k.velocity(p.id) / k.omega();
        const Vec2 a = k.acceleration(p.id) / (k.omega() * k.omega());
        worst = std::max(
            {worst, (sum - k.position(p.id)).norm(), (sumV - v).norm(), (sumA - a).norm()});
        size = std::max({size, k.position(p.id).norm(), v.norm(), a.norm()});
      }
    }
    std::printf("  %-28s scaling: worst error %.2e of %.4g mm\n", name, worst, size);
    EXPECT_LT(worst, 1e-10 * size) << name;
  }
}

// Arc slots (resources/examples/curved-guide): the rod's end B where the rod's circle about the
// crank pin A meets the guide's arc (centre c, radius R), its rates from (B - c) . B' = 0 and
// (B - A) . (B' - A') = 0 and their derivatives. A pin in the arc (an OnCircle row), and the
// example's block made a body of two points C, B (C first: block.C-B moves B in the block, the
// row at the arc's centre with it): the rod's end does not move with the block's shape, exactly.
// The curved guide: a crank, a rod whose end B runs in the arc, by itself or pinned to a block
// of two points (C, B) in it.
const Vec2 kGuideA0(0, 15), kGuideB0(-1.1292513648949634, 59.98582878368345);
Mechanism curvedGuide(bool pinInSlot) {
  Mechanism m;
  const BodyId g = m.addBody("ground", true), crank = m.addBody("crank"), rod = m.addBody("rod");
  const Vec2 A0 = kGuideA0, B0 = kGuideB0;
  const SlotId guide = m.addSlot(g, "guide", Vec2(-4, 17), Vec2(-4, 73));
  m.slots.back().mid = Vec2(0, 45);
  const JointId drive =
      m.addPin(m.addPoint(g, "O", Vec2(0, 0)), m.addPoint(crank, "O", Vec2(0, 0)));
  m.addPin(m.addPoint(crank, "A", A0), m.addPoint(rod, "A", A0));
  const PointId rodB = m.addPoint(rod, "B", B0);
  if (pinInSlot) {
    m.addPinInSlot(rodB, guide);
  } else {
    const BodyId block = m.addBody("block");
    m.addPoint(block, "C", B0 + Vec2(6, -4));
    const PointId blockB = m.addPoint(block, "B", B0);
    m.addPin(rodB, blockB);
    m.addSlider(blockB, guide);
  }
  m.driver = Driver{drive, 60, Direction::Ccw, 0, ""};
  return m;
}

// The guide's centre and radius (its dimensions: concentric, its three points along their radii).
std::pair<CVec, C> arcOf(const std::map<std::string, C>& v) {
  return {CVec{v.at("ground.guide.centre.x"), v.at("ground.guide.centre.y")},
          v.at("ground.guide.radius")};
}

TEST(Sensitivity, CurvedGuideMatchesTheCirclesIntersection) {
  for (bool pinInSlot : {true, false}) {
    const Mechanism m = curvedGuide(pinInSlot);
    const Vec2 A0 = kGuideA0, B0 = kGuideB0;
    const PointId rodB = *m.findPoint("rod.B");
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok());
    const std::optional<Guide> arc = guideOf(m.slots.front());
    ASSERT_TRUE(arc && arc->arc);
    const std::vector<Dimension> dims = dimensions(m);
    std::map<std::string, C> base;
    for (const Dimension& d : dims) base[d.name] = d.value;
    const double side = linkage::cross(Vec2(arc->centre - A0), Vec2(B0 - A0)) > 0 ? 1 : -1;
    auto B = [&](const std::map<std::string, C>& v, double phi) {
      const auto [c, R] = arcOf(v);
      const CVec O{v.at("ground.O.x"), v.at("ground.O.y")};
      const C r = v.at("crank.O-A"), l = v.at("rod.A-B");
      const double t = M_PI / 2 + phi;
      const CVec a = CVec{r * std::cos(t), r * std::sin(t)}, A = O + a, A1 = perp(a);
      const CVec e = c - A;
      const C d = std::sqrt(dot(e, e)), mm = (l * l - R * R + d * d) / (2.0 * d);
      const CVec b = A + (mm / d) * e + (side * std::sqrt(l * l - mm * mm) / d) * perp(e);
      const CVec u = b - c, w = b - A;  // [u; w] x = rhs
      auto solve = [&](C r0, C r1) {
        const C det = u.x * w.y - u.y * w.x;
        return CVec{(r0 * w.y - u.y * r1) / det, (u.x * r1 - r0 * w.x) / det};
      };
      const CVec b1 = solve(0.0, dot(w, A1)), rel = b1 - A1;
      const CVec b2 = solve(-dot(b1, b1), dot(w, (-1.0) * a) - dot(rel, rel));
      return PV{b, b1, b2};
    };
    auto exact = [&](const std::string& name, double phi) {
      std::map<std::string, C> v = base;
      v.at(name) += C(0, kH);
      return imaginary(B(v, phi));
    };
    ASSERT_NEAR(B(base, 0).p.y.real(), k.position(rodB).y(), 1e-9);
    ASSERT_NEAR(B(base, 0).v.y.real() * k.omega(), k.velocity(rodB).y(), 1e-9);
    for (const Dimension& d : dims)
      if (d.name.rfind("block.", 0) == 0) base[d.name] = 0;  // the closed form does not read it
    std::vector<std::string> compared;
    std::printf("curved guide, %s:\n", pinInSlot ? "pin in the arc" : "two-point block");
    const double worst = worstRelative(k, rodB, dims, exact, compared, "block.C-B");
    EXPECT_EQ(compared.size(), pinInSlot ? 7u : 8u);
    EXPECT_LT(worst, 1e-10);
    if (pinInSlot) continue;
    // The block's C: the block turns about the arc's centre c with B, its point at c being
    // B - R (B - c) / |B - c| as drawn, so C = c + Rot(the angle from B's drawn direction about
    // c to its direction now) (C - B + R q), q = (B - c) / |B - c| as drawn (block.C-B moves
    // the drawn B along C->B).
    const Vec2 C0 = B0 + Vec2(6, -4), e = (B0 - C0).normalized();
    auto blockC = [&](const std::map<std::string, C>& v, double phi) {
      const PV b = B(v, phi);
      const auto [c, R] = arcOf(v);
      const C t = v.at("block.C-B");
      const CVec Bd{B0.x() + t * e.x(), B0.y() + t * e.y()}, fromC = Bd - c;
      const CVec q = (1.0 / std::sqrt(dot(fromC, fromC))) * fromC;
      const CVec p = (1.0 / R) * (b.p - c);
      const C cs = dot(p, q), sn = cross(q, p);
      const CVec kk = CVec{C0.x() - Bd.x, C0.y() - Bd.y} + R * q;
      const CVec rk{cs * kk.x - sn * kk.y, sn * kk.x + cs * kk.y};
      const C w = cross(b.p - c, b.v) / (R * R), al = cross(b.p - c, b.a) / (R * R);
      return PV{c + rk, w * perp(rk), al * perp(rk) - (w * w) * rk};
    };
    auto exactC = [&](const std::string& name, double phi) {
      std::map<std::string, C> v = base;
      v.at(name) += C(0, kH);
      return imaginary(blockC(v, phi));
    };
    const PointId outC = *m.findPoint("block.C");
    ASSERT_TRUE(k.moveTo(0).ok());
    ASSERT_NEAR(blockC(base, 0).p.x.real(), k.position(outC).x(), 1e-9);
    ASSERT_NEAR(blockC(base, 0).v.y.real() * k.omega(), k.velocity(outC).y(), 1e-9);
    std::vector<std::string> comparedC;
    std::printf("curved guide, the block's C:\n");
    EXPECT_LT(worstRelative(k, outC, dims, exactC, comparedC), 1e-10);
  }
}

}  // namespace
}  // namespace linkage
