// The solver against independent references (tests/reference, computed in __float128 from
// closed forms or a reduced one-unknown formulation): positions within 1e-9 mm, velocities and
// accelerations within 1e-9 of the cycle's peak magnitude, over whole revolutions.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "examples.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"
#include "reference/four_bar.h"
#include "reference/slider_crank.h"
#include "reference/wanzer.h"

namespace linkage {
namespace {

using Q = __float128;

using test::example;

// Samples of one coordinate of a point: solver and reference side by side.
struct Series {
  std::vector<double> x, v, a;     // solver
  std::vector<double> xr, vr, ar;  // reference
  void add(double x0, double v0, double a0, Q x1, Q v1, Q a1) {
    x.push_back(x0), v.push_back(v0), a.push_back(a0);
    xr.push_back(double(x1)), vr.push_back(double(v1)), ar.push_back(double(a1));
  }
  static double peak(const std::vector<double>& s) {
    double m = 0;
    for (double e : s) m = std::max(m, std::abs(e));
    return m;
  }
  static double worst(const std::vector<double>& s, const std::vector<double>& r) {
    double m = 0;
    for (size_t i = 0; i < s.size(); ++i) m = std::max(m, std::abs(s[i] - r[i]));
    return m;
  }
  void expectWithin(double posMm, double relPeak, const std::string& what) const {
    ASSERT_FALSE(x.empty());
    EXPECT_LT(worst(x, xr), posMm) << what << " position";
    EXPECT_LT(worst(v, vr), relPeak * peak(vr)) << what << " velocity, peak " << peak(vr);
    EXPECT_LT(worst(a, ar), relPeak * peak(ar)) << what << " acceleration, peak " << peak(ar);
  }
};

TEST(Accuracy, SliderCrank22aAgainstExactClosedFormAndPaper) {
  for (double rod : {30.0, 50.0}) {
    const std::string name =
        rod == 30 ? "slider-crank-22a-lambda-0.5" : "slider-crank-22a-lambda-0.3";
    Mechanism m = example(name);
    const PointId B = *m.findPoint("needlebar.B");
    const auto p = linkref::slider_crank_22a<Q>(Q(rod));
    const Q lambda = Q(15) / Q(rod);
    for (bool closedForm : {true, false}) {
      KinematicsOptions opt;
      opt.closedForm = closedForm;
      Kinematics k(opt);
      ASSERT_TRUE(k.load(m).ok());
      EXPECT_EQ(k.closedForm(), closedForm);
      Series s, paper;
      for (int i = 0; i <= 360; ++i) {
        ASSERT_TRUE(k.moveTo(i).ok()) << i;
        const Q phi = linkref::deg2rad(Q(i));
        const auto r = linkref::slider_crank(p, phi);
        s.add(k.position(B).y(), k.velocity(B).y(), k.acceleration(B).y(), r.y, r.vy, r.ay);
        // The paper's exact form (2): S_B = y - (l - r) at phi_B = phi + pi (reference/README.md).
        const auto pp = linkref::paper_slider_crank(Q(15), lambda, p.omega, phi + linkref::pi<Q>());
        paper.add(k.position(B).y() - (rod - 15), k.velocity(B).y(), k.acceleration(B).y(), pp.S,
                  pp.v, pp.a);
        EXPECT_EQ(k.position(B).x(), 0.0);
      }
      const std::string path = closedForm ? " closed form" : " general";
      s.expectWithin(1e-9, 1e-9, name + path);
      paper.expectWithin(1e-9, 1e-9, name + path + " (paper's exact form)");
    }
  }
}

TEST(Accuracy, OffsetSliderCrankEitherDirectionBlockOrPinInSlot) {
  for (Direction dir : {Direction::Ccw, Direction::Cw})
    for (bool pinInSlot : {false, true}) {
      auto sc = test::sliderCrank(12, 41, 5, 70, dir, 1500, pinInSlot);
      linkref::SliderCrankParams<Q> p;
      p.r = 12, p.l = 41, p.e = 5;
      p.a0 = linkref::deg2rad(Q(70));
      p.s = dir == Direction::Ccw ? 1 : -1;
      p.omega = linkref::rpm_to_rad_s(Q(1500));
      for (bool closedForm : {true, false}) {
        KinematicsOptions opt;
        opt.closedForm = closedForm;
        Kinematics k(opt);
        ASSERT_TRUE(k.load(sc.m).ok());
        EXPECT_EQ(k.closedForm(), closedForm);
        Series s, rodAngle;
        for (int i = 0; i <= 720; i += 3) {
          ASSERT_TRUE(k.moveTo(i).ok()) << i;
          const auto r = linkref::slider_crank(p, linkref::deg2rad(Q(i)));
          s.add(k.position(sc.B).y(), k.velocity(sc.B).y(), k.acceleration(sc.B).y(), r.y, r.vy,
                r.ay);
          const double psi0 = double(linkref::slider_crank(p, Q(0)).psi);
          rodAngle.add(k.bodyAngle(sc.rod) + psi0, k.bodyOmega(sc.rod), k.bodyAlpha(sc.rod), r.psi,
                       r.dpsi, r.ddpsi);
        }
        const std::string what = std::string(dir == Direction::Cw ? "cw" : "ccw") +
                                 (pinInSlot ? " pin-in-slot" : " slider block") +
                                 (closedForm ? " closed form" : " general");
        s.expectWithin(1e-9, 1e-9, what);
        rodAngle.expectWithin(1e-11, 1e-9, what + " rod angle");
      }
    }
}

// Quick-return (crank and slotted lever): a block pinned to the crank pin slides in a slot of
// a lever pivoted at O4 = (0, -d). Closed form, with theta2 the crank angle from +x:
//   theta4 = atan2(r sin theta2 + d, r cos theta2)
//   omega4 = w r (r + d sin theta2) / D,   D = r^2 + d^2 + 2 r d sin theta2
//   alpha4 = w^2 r d cos theta2 (d^2 - r^2) / D^2
TEST(Accuracy, QuickReturnSlotOnAMovingLever) {
  const double r = 20, d = 50, rpm = 90, w = rpm * 2 * M_PI / 60, t0 = 30 * M_PI / 180;
  for (Direction dir : {Direction::Ccw, Direction::Cw}) {
    Mechanism m;
    const BodyId g = m.addBody("ground", true), crank = m.addBody("crank"),
                 block = m.addBody("block"), lever = m.addBody("lever");
    const Vec2 O2(0, 0), O4(0, -d), A(r * std::cos(t0), r * std::sin(t0));
    const Vec2 u = (A - O4).normalized();
    const PointId gO2 = m.addPoint(g, "O2", O2), gO4 = m.addPoint(g, "O4", O4);
    const PointId cO2 = m.addPoint(crank, "O2", O2), cA = m.addPoint(crank, "A", A);
    const PointId bA = m.addPoint(block, "A", A);
    const PointId lO4 = m.addPoint(lever, "O4", O4), tip = m.addPoint(lever, "T", O4 + 90 * u);
    const SlotId slot = m.addSlot(lever, "slot", O4, O4 + 90 * u);
    const JointId drive = m.addPin(gO2, cO2);
    m.addPin(cA, bA);
    m.addSlider(bA, slot);
    m.addPin(lO4, gO4);
    m.driver = Driver{drive, rpm, dir, 0, ""};
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok());
    const double s = dir == Direction::Ccw ? 1 : -1;
    const double th40 = std::atan2(A.y() + d, A.x());
    Series lev, tipY;
    for (int i = 0; i <= 360; i += 2) {
      ASSERT_TRUE(k.moveTo(i).ok());
      const double th2 = t0 + s * i * M_PI / 180;
      const double D = r * r + d * d + 2 * r * d * std::sin(th2);
      const double th4 = std::atan2(r * std::sin(th2) + d, r * std::cos(th2));
      const double w4 = s * w * r * (r + d * std::sin(th2)) / D;
      const double a4 = w * w * r * d * std::cos(th2) * (d * d - r * r) / (D * D);
      // Unwrap the closed form's angle onto the lever's continuous one (it swings, < pi).
      double rel = th4 - th40;
      rel -= 2 * M_PI * std::round((rel - k.bodyAngle(lever)) / (2 * M_PI));
      lev.add(k.bodyAngle(lever), k.bodyOmega(lever), k.bodyAlpha(lever), rel, w4, a4);
      // The tip, 90 mm from O4 along the lever: y, vy, ay from theta4 and its derivatives.
      tipY.add(k.position(tip).y(), k.velocity(tip).y(), k.acceleration(tip).y(),
               -d + 90 * std::sin(th4), 90 * std::cos(th4) * w4,
               90 * (std::cos(th4) * a4 - std::sin(th4) * w4 * w4));
      // The block keeps the lever's angle and stays on the crank pin.
      EXPECT_NEAR(k.bodyAngle(block), k.bodyAngle(lever), 1e-12);
      EXPECT_LT((k.position(bA) - k.position(cA)).norm(), 1e-10);
    }
    // The closed form is evaluated in double here: 1e-12 relative is its own rounding.
    lev.expectWithin(1e-11, 1e-9, "quick-return lever");
    tipY.expectWithin(1e-9, 1e-9, "quick-return lever tip");
  }
}

linkref::FourBarParams<Q> params(double d, double r2, double r3, double r4, double crankDeg,
                                 bool open, double px, double py, Direction dir, double rpm) {
  linkref::FourBarParams<Q> p;
  p.O2 = {Q(0), Q(0)};
  p.O4 = {Q(d), Q(0)};
  p.r2 = r2, p.r3 = r3, p.r4 = r4;
  p.theta20 = linkref::deg2rad(Q(crankDeg));
  p.s = dir == Direction::Ccw ? 1 : -1;
  p.omega = linkref::rpm_to_rad_s(Q(rpm));
  p.branch = open ? linkref::FourBarBranch::kOpen : linkref::FourBarBranch::kCrossed;
  p.px = px, p.py = py;
  return p;
}

void checkFourBar(const Mechanism& m, PointId P, PointId B, const linkref::FourBarParams<Q>& p,
                  int revs, const std::string& what) {
  for (bool closedForm : {true, false}) {
    KinematicsOptions opt;
    opt.closedForm = closedForm;
    Kinematics k(opt);
    ASSERT_TRUE(k.load(m).ok()) << what;
    EXPECT_EQ(k.closedForm(), closedForm) << what;
    Series px, py, bx, by;
    for (int i = 0; i <= 360 * revs; ++i) {
      ASSERT_TRUE(k.moveTo(i).ok()) << what << " at " << i;
      const auto r = linkref::four_bar(p, linkref::deg2rad(Q(i)));
      px.add(k.position(P).x(), k.velocity(P).x(), k.acceleration(P).x(), r.P.x, r.vP.x, r.aP.x);
      py.add(k.position(P).y(), k.velocity(P).y(), k.acceleration(P).y(), r.P.y, r.vP.y, r.aP.y);
      bx.add(k.position(B).x(), k.velocity(B).x(), k.acceleration(B).x(), r.B.x, r.vB.x, r.aB.x);
      by.add(k.position(B).y(), k.velocity(B).y(), k.acceleration(B).y(), r.B.y, r.vB.y, r.aB.y);
    }
    const std::string path = closedForm ? " closed form" : " general";
    px.expectWithin(1e-9, 1e-9, what + path + " P.x");
    py.expectWithin(1e-9, 1e-9, what + path + " P.y");
    bx.expectWithin(1e-9, 1e-9, what + path + " B.x");
    by.expectWithin(1e-9, 1e-9, what + path + " B.y");
  }
}

TEST(Accuracy, FourBarExampleAgainstClosedForm) {
  Mechanism m = example("four-bar-crank-rocker");
  checkFourBar(m, *m.findPoint("coupler.P"), *m.findPoint("coupler.B"),
               linkref::four_bar_crank_rocker_example<Q>(), 2, "example");
}

TEST(Accuracy, FourBarsOfOtherShapesBranchesAndDirections) {
  struct Case {
    double d, r2, r3, r4, crank;
    bool open;
    Direction dir;
  };
  // Crank-rockers and a double-crank (drag link), open and crossed, both directions.
  const Case cases[] = {{60, 20, 70, 50, 60, true, Direction::Ccw},
                        {60, 20, 70, 50, 200, false, Direction::Cw},
                        {100, 35, 90, 70, 10, true, Direction::Cw},
                        {20, 60, 55, 70, 45, true, Direction::Ccw},
                        {20, 60, 55, 70, 120, false, Direction::Cw}};
  for (const Case& c : cases) {
    auto f = test::fourBar(c.d, c.r2, c.r3, c.r4, c.crank, c.open, -12, 30, c.dir, 300);
    const std::string what = "four-bar " + std::to_string(int(c.d)) + "/" +
                             std::to_string(int(c.r2)) + "/" + std::to_string(int(c.r3)) + "/" +
                             std::to_string(int(c.r4)) + (c.open ? " open" : " crossed");
    checkFourBar(f.m, f.P, f.B, params(c.d, c.r2, c.r3, c.r4, c.crank, c.open, -12, 30, c.dir, 300),
                 1, what);
  }
}

void checkWanzer(linkref::WanzerInversion inv, const std::string& name) {
  Mechanism m = example(name);
  const PointId G = *m.findPoint("needlebar.G");
  const PointId E = *m.findPoint("triangle.E");
  const BodyId tri = m.bodyNamed("triangle")->id;
  for (bool closedForm : {true, false}) {
    linkref::Wanzer<Q> w(linkref::wanzer_homework_params<Q>(inv));
    KinematicsOptions opt;
    opt.closedForm = closedForm;
    Kinematics k(opt);
    ASSERT_TRUE(k.load(m).ok());
    EXPECT_EQ(k.closedForm(), closedForm);
    Series g, ex, ey, ang;
    const double tri0 = double(w.at(Q(0)).tri_angle);
    for (int i = 0; i <= 720; ++i) {
      ASSERT_TRUE(k.moveTo(i).ok()) << name << " at " << i;
      const auto r = w.at_deg(Q(i));
      g.add(k.position(G).y(), k.velocity(G).y(), k.acceleration(G).y(), r.G.y, r.vG.y, r.aG.y);
      ex.add(k.position(E).x(), k.velocity(E).x(), k.acceleration(E).x(), r.E.x, r.vE.x, r.aE.x);
      ey.add(k.position(E).y(), k.velocity(E).y(), k.acceleration(E).y(), r.E.y, r.vE.y, r.aE.y);
      ang.add(k.bodyAngle(tri) + tri0, k.bodyOmega(tri), k.bodyAlpha(tri), r.tri_angle, r.tri_omega,
              r.tri_alpha);
      EXPECT_LT(std::abs(k.position(G).x()), 1e-9);
    }
    const std::string what = name + (closedForm ? " (core group)" : " (general)");
    g.expectWithin(1e-9, 1e-9, what + " needle G");
    ex.expectWithin(1e-9, 1e-9, what + " E.x");
    ey.expectWithin(1e-9, 1e-9, what + " E.y");
    // Angles are periodic only modulo 2 pi; the triangle swings and never turns a whole turn.
    ang.expectWithin(1e-11, 1e-9, what + " triangle angle");
  }
}

TEST(Accuracy, WanzerInversion1AgainstReducedFormulation) {
  checkWanzer(linkref::WanzerInversion::k1, "wanzer-inversion-1");
}

TEST(Accuracy, WanzerInversion2AgainstReducedFormulation) {
  checkWanzer(linkref::WanzerInversion::k2, "wanzer-inversion-2");
}

TEST(Wanzer, NeedleVelocityAtTheHomeworkPosition) {
  Mechanism m = example("wanzer-inversion-2");
  const PointId G = *m.findPoint("needlebar.G");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  // Independent derivation: the trammel formulation, implicit differentiation, __float128.
  const auto r = linkref::wanzer_state(linkref::WanzerInversion::k2, Q(0));
  EXPECT_NEAR(k.velocity(G).y(), double(r.vG.y), 1e-9 * std::abs(double(r.vG.y)));
  EXPECT_NEAR(k.velocity(G).x(), 0.0, 1e-9);
  // The homework: 365 mm/s down from Working Model, 370 mm/s by instant centres measured with a
  // ruler on its own drawing. Exact for this geometry: 382.12 mm/s down, 4.7 % more; assert
  // the direction and agreement to 5 %, no tighter (hand measurement, unstated drawing).
  EXPECT_LT(k.velocity(G).y(), 0);
  EXPECT_NEAR(-k.velocity(G).y(), 365.0, 0.05 * 365.0);
}

TEST(Wanzer, MotionStaysInTheHomeworkPlotRangesAndRepeats) {
  for (const char* name : {"wanzer-inversion-1", "wanzer-inversion-2"}) {
    Mechanism m = example(name);
    const PointId G = *m.findPoint("needlebar.G");
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok());
    const Vec2 start = k.position(G);
    for (int i = 0; i <= 4 * 360; ++i) {
      ASSERT_TRUE(k.moveTo(i).ok());
      // The homework's axes: needle -80..-30 mm, velocity +-1000 mm/s, acceleration -2..6 g.
      EXPECT_GT(k.position(G).y(), -81);
      EXPECT_LT(k.position(G).y(), -30);
      EXPECT_LT(std::abs(k.velocity(G).y()), 1000);
      EXPECT_GT(k.acceleration(G).y() / 9810, -2);
      EXPECT_LT(k.acceleration(G).y() / 9810, 6);
    }
    EXPECT_LT((k.position(G) - start).norm(), 1e-10) << name << ": not periodic";
  }
}

}  // namespace
}  // namespace linkage
