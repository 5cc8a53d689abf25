// The two new element kinds against closed forms: gear and belt couplings (a planet's
// epicycloid, a gear pair's exact ratio, a gear pair cranking a four-bar) and arc slots (a pin
// in an arc equals a four-bar with a link of the arc's radius; a block in a curved guide equals
// a rocker about the arc's centre), on the closed-form path and on the general Newton path;
// their instant centres; the element table itself.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "linkage/elements.h"
#include "linkage/instant_centres.h"
#include "linkage/kinematics.h"
#include "linkage/transmission.h"
#include "mechanisms.h"
#include "structure/decomposition.h"
#include "system/system.h"

namespace linkage {
namespace {

constexpr double kDeg = M_PI / 180;
using C = std::complex<double>;

Vec2 v2(C z) {
  return Vec2(z.real(), z.imag());
}

Kinematics loaded(const Mechanism& m, bool closedForm = true) {
  KinematicsOptions opt;
  opt.closedForm = closedForm;
  Kinematics k(opt);
  const Status s = k.load(m);
  EXPECT_TRUE(s.ok()) << s.message;
  return k;
}

// A planet of radius rp on an arm (the driven crank) around a fixed sun of radius rs: the
// planet's rim point P starts on the line of centres, outside.
struct Planet {
  Mechanism m;
  BodyId arm, planet;
  PointId P;
};

Planet planet(double rs, double rp) {
  Planet p;
  Mechanism& m = p.m;
  const BodyId ground = m.addBody("ground", true);
  p.arm = m.addBody("arm");
  p.planet = m.addBody("planet");
  const double d = rs + rp;
  const PointId gS = m.addPoint(ground, "S", Vec2(0, 0));
  const PointId aS = m.addPoint(p.arm, "S", Vec2(0, 0));
  const PointId aB = m.addPoint(p.arm, "B", Vec2(d, 0));
  const PointId pB = m.addPoint(p.planet, "B", Vec2(d, 0));
  p.P = m.addPoint(p.planet, "P", Vec2(d + rp, 0));
  const JointId drive = m.addPin(gS, aS);
  m.addPin(aB, pB);
  m.addGear(gS, pB, -rs / rp, p.arm);  // external pair: turns opposite ways, as rs / rp
  m.driver = Driver{drive, 60, Direction::Ccw, 0, ""};
  m.outputs = {p.P};
  return p;
}

double relative(const Vec2& got, const Vec2& want, double scale) {
  return (got - want).norm() / scale;
}

TEST(Elements, PlanetPointTracesTheEpicycloid) {
  // Sun 20, planet 10: P = 30 e^{it} + 10 e^{3it} at crank angle t (the planet turns three
  // times as fast as the arm), its derivatives in t times omega and omega^2.
  const Planet p = planet(20, 10);
  for (bool closedForm : {true, false}) {
    Kinematics k = loaded(p.m, closedForm);
    EXPECT_EQ(k.closedForm(), closedForm);
    const double w = k.omega();
    for (double deg = 0; deg <= 720; deg += 7.5) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
      const double t = deg * kDeg;
      const C i(0, 1), e1 = std::exp(i * t), e3 = std::exp(3.0 * i * t);
      const Kinematics::PointMotion got = k.motion(p.P);
      EXPECT_LT(relative(got.position, v2(30.0 * e1 + 10.0 * e3), 40), 1e-12) << deg;
      EXPECT_LT(relative(got.velocity, v2(w * (30.0 * i * e1 + 30.0 * i * e3)), 60 * w), 1e-12)
          << deg << " closed form " << closedForm;
      EXPECT_LT(relative(got.acceleration, v2(w * w * (-30.0 * e1 - 90.0 * e3)), 120 * w * w),
                1e-12)
          << deg << " closed form " << closedForm;
      EXPECT_NEAR(k.bodyAngle(p.planet), 3 * t, 1e-12 * (1 + 3 * t));
    }
  }
}

// Two gear bodies on ground pivots A = (0, 0) and B = (50, 0), the first driven.
struct GearPair {
  Mechanism m;
  BodyId a, b;
  PointId bPin;  // b's pivot, on b
};

GearPair gearPair(double ratio, Direction dir = Direction::Ccw) {
  GearPair g;
  Mechanism& m = g.m;
  const BodyId ground = m.addBody("ground", true);
  g.a = m.addBody("input");
  g.b = m.addBody("output");
  const PointId gA = m.addPoint(ground, "A", Vec2(0, 0)), gB = m.addPoint(ground, "B", Vec2(50, 0));
  const PointId aA = m.addPoint(g.a, "A", Vec2(0, 0));
  m.addPoint(g.a, "U", Vec2(0, 12));
  g.bPin = m.addPoint(g.b, "B", Vec2(50, 0));
  m.addPoint(g.b, "V", Vec2(50, 20));
  const JointId drive = m.addPin(gA, aA);
  m.addPin(gB, g.bPin);
  m.addGear(aA, g.bPin, ratio);
  m.driver = Driver{drive, 120, dir, 0, ""};
  return g;
}

TEST(Elements, GearPairTurnsExactlyRatioTimesTheInput) {
  for (double ratio : {-2.0, -0.5, 3.0, 1.0, -1.0 / 3}) {
    for (Direction dir : {Direction::Ccw, Direction::Cw}) {
      const GearPair g = gearPair(ratio, dir);
      for (bool closedForm : {true, false}) {
        Kinematics k = loaded(g.m, closedForm);
        for (double deg = 0; deg <= 1080; deg += 13) {
          ASSERT_TRUE(k.moveTo(deg).ok()) << ratio << " " << deg;
          const double in = k.bodyAngle(g.a);
          EXPECT_NEAR(std::abs(in), deg * kDeg, 1e-12 * (1 + deg * kDeg));
          EXPECT_NEAR(k.bodyAngle(g.b), ratio * in, 1e-12 * (1 + std::abs(ratio * in)));
          EXPECT_NEAR(k.bodyOmega(g.b), ratio * k.bodyOmega(g.a),
                      1e-12 * std::abs(ratio) * k.omega());
          EXPECT_NEAR(k.bodyAlpha(g.b), 0, 1e-12 * k.omega() * k.omega());
        }
      }
    }
  }
}

TEST(Elements, GearPairCrankingAFourBarIsTheFourBarAtRatioTimesTheAngle) {
  // The output gear is the crank of a four-bar: its coupler point at crank angle t of the
  // input is the directly driven four-bar's at -t / 2 (ratio -1/2, the four-bar's crank turns
  // the other way at half the speed).
  const double ratio = -0.5;
  test::FourBar direct = test::fourBar(60, 20, 70, 50, 0, true, 30, 15);
  Mechanism geared = direct.m;
  const BodyId input = geared.addBody("input");
  const Body* ground = geared.ground();
  const PointId gI = geared.addPoint(ground->id, "I", Vec2(-45, 0));
  const PointId iI = geared.addPoint(input, "I", Vec2(-45, 0));
  const JointId drive = geared.addPin(gI, iI);
  geared.addGear(iI, direct.O2, ratio);
  geared.driver = Driver{drive, 60, Direction::Ccw, 0, ""};
  for (bool closedForm : {true, false}) {
    Kinematics g = loaded(geared, closedForm), d = loaded(direct.m);
    EXPECT_EQ(g.closedForm(), closedForm);
    for (double deg = 0; deg <= 720; deg += 10) {
      ASSERT_TRUE(g.moveTo(deg).ok());
      ASSERT_TRUE(d.moveTo(ratio * deg).ok());
      const Kinematics::PointMotion a = g.motion(direct.P), b = d.motion(direct.P);
      EXPECT_LT(relative(a.position, b.position, 100), 1e-12) << deg;
      // d/dt of the input's angle is omega; of the four-bar crank's, ratio omega.
      EXPECT_LT(relative(a.velocity, ratio * b.velocity, b.velocity.norm() + 1), 1e-11) << deg;
      EXPECT_LT(relative(a.acceleration, ratio * ratio * b.acceleration, b.acceleration.norm() + 1),
                1e-11)
          << deg;
    }
  }
}

// A four-bar whose rocker is replaced by an arc slot in the ground: the coupler's point B runs
// on the circle of radius r4 about O4, as the rocker's end does.
Mechanism fourBarWithArc(const test::FourBar& f, double r4) {
  Mechanism m = f.m;
  const Vec2 O4 = m.point(f.O4)->pos, B = m.point(f.B)->pos;
  const double t = std::atan2(B.y() - O4.y(), B.x() - O4.x());
  auto on = [&](double a) { return Vec2(O4 + r4 * Vec2(std::cos(a), std::sin(a))); };
  m.remove(f.rocker);
  const SlotId arc = m.addArcSlot(m.ground()->id, "arc", on(t - 1.2), on(t + 0.3), on(t + 1.4));
  m.addPinInSlot(f.B, arc);
  return m;
}

TEST(Elements, PinInAnArcSlotIsTheFourBarWithALinkOfItsRadius) {
  for (const double r4 : {50.0, 45.0}) {
    const test::FourBar f = test::fourBar(60, 20, 70, r4, 30, true, 25, -10);
    const Mechanism arc = fourBarWithArc(f, r4);
    for (bool closedForm : {true, false}) {
      Kinematics a = loaded(arc, closedForm), b = loaded(f.m);
      EXPECT_EQ(a.closedForm(), closedForm);
      for (double deg = 0; deg <= 360; deg += 6) {
        ASSERT_TRUE(a.moveTo(deg).ok()) << deg;
        ASSERT_TRUE(b.moveTo(deg).ok()) << deg;
        for (PointId p : {f.P, f.B}) {
          const Kinematics::PointMotion x = a.motion(p), y = b.motion(p);
          EXPECT_LT(relative(x.position, y.position, 100), 1e-12) << deg;
          EXPECT_LT(relative(x.velocity, y.velocity, y.velocity.norm() + b.omega()), 1e-12) << deg;
          EXPECT_LT(relative(x.acceleration, y.acceleration, y.acceleration.norm() + 1), 1e-12)
              << deg;
        }
      }
    }
  }
}

// A slider-crank whose block runs in a curved guide (centre C, radius R), and the same with a
// rocker of length R about C in place of the guide.
struct CurvedGuide {
  Mechanism guide, rocker;
  BodyId block, arm;  // the block (guide) and the rocker
  PointId B;          // the rod's end, in both
};

CurvedGuide curvedGuide() {
  CurvedGuide c;
  const Vec2 O(0, 0), A(15, 0), Cc(40, -60);
  const double l = 50;
  // B on the circle of radius R about C, at distance l from A.
  const double R = 70;
  const Vec2 e = Cc - A;
  const double d = e.norm(), a = (l * l - R * R + d * d) / (2 * d);
  const Vec2 u = e / d, B = A + a * u - std::sqrt(l * l - a * a) * perp(u);
  for (int variant = 0; variant < 2; ++variant) {
    Mechanism& m = variant ? c.rocker : c.guide;
    const BodyId ground = m.addBody("ground", true), crank = m.addBody("crank"),
                 rod = m.addBody("rod"), body = m.addBody(variant ? "rocker" : "block");
    const PointId gO = m.addPoint(ground, "O", O);
    const JointId drive = m.addPin(gO, m.addPoint(crank, "O", O));
    m.addPin(m.addPoint(crank, "A", A), m.addPoint(rod, "A", A));
    const PointId rB = m.addPoint(rod, "B", B);
    c.B = rB;
    const PointId bB = m.addPoint(body, "B", B);
    m.addPoint(body, "Q", B + Vec2(5, 2));  // a point of the block off its pin
    m.addPin(rB, bB);
    if (variant) {
      m.addPin(m.addPoint(body, "C", Cc), m.addPoint(ground, "C", Cc));
      c.arm = body;
    } else {
      const double t = std::atan2(B.y() - Cc.y(), B.x() - Cc.x());
      auto on = [&](double s) { return Vec2(Cc + R * Vec2(std::cos(s), std::sin(s))); };
      m.addSlider(bB, m.addArcSlot(ground, "guide", on(t - 0.9), on(t), on(t + 0.9)));
      c.block = body;
    }
    m.driver = Driver{drive, 90, Direction::Cw, 0, ""};
  }
  return c;
}

TEST(Elements, BlockInACurvedGuideIsARockerAboutTheArcsCentre) {
  const CurvedGuide c = curvedGuide();
  for (bool closedForm : {true, false}) {
    Kinematics g = loaded(c.guide, closedForm), r = loaded(c.rocker);
    EXPECT_EQ(g.closedForm(), closedForm);
    for (double deg = 0; deg <= 360; deg += 5) {
      ASSERT_TRUE(g.moveTo(deg).ok()) << deg;
      ASSERT_TRUE(r.moveTo(deg).ok()) << deg;
      EXPECT_NEAR(g.bodyAngle(c.block), r.bodyAngle(c.arm), 1e-12) << deg;
      EXPECT_NEAR(g.bodyOmega(c.block), r.bodyOmega(c.arm), 1e-12 * g.omega()) << deg;
      EXPECT_NEAR(g.bodyAlpha(c.block), r.bodyAlpha(c.arm), 1e-12 * g.omega() * g.omega()) << deg;
      for (const char* name : {"B", "Q"}) {
        const PointId pg = *c.guide.findPoint(std::string("block.") + name);
        const PointId pr = *c.rocker.findPoint(std::string("rocker.") + name);
        const Kinematics::PointMotion x = g.motion(pg), y = r.motion(pr);
        EXPECT_LT(relative(x.position, y.position, 100), 1e-12) << deg;
        EXPECT_LT(relative(x.velocity, y.velocity, y.velocity.norm() + 1), 1e-12) << deg;
        EXPECT_LT(relative(x.acceleration, y.acceleration, y.acceleration.norm() + 1), 1e-12);
      }
    }
  }
}

TEST(Elements, GearPairsCentreIsThePitchPointAndKennedyAgrees) {
  // External pair, ratio -2: the pitch point divides AB as 2 : 1, at (A + 2 B) / 3.
  const GearPair g = gearPair(-2);
  Kinematics k = loaded(g.m);
  for (double deg : {0.0, 37.0, 211.0}) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    const InstantCentres ics = computeInstantCentres(k);
    ASSERT_TRUE(ics.status.ok()) << ics.status.message;
    const InstantCentre* c = ics.find(ics.numberOf(g.a), ics.numberOf(g.b));
    ASSERT_TRUE(c && c->determined);
    EXPECT_EQ(c->status, CentreStatus::Primary);
    EXPECT_LT((c->point() - Vec2(100.0 / 3, 0)).norm(), 1e-12 * 50);
    EXPECT_TRUE(ics.disagreements.empty());
  }
  // A belt at ratio 2: where the velocities are equal, beyond B: (A - 2 B) / (1 - 2) = 2B - A.
  const GearPair belt = gearPair(2);
  Kinematics kb = loaded(belt.m);
  ASSERT_TRUE(kb.moveTo(25).ok());
  const InstantCentres ib = computeInstantCentres(kb);
  const InstantCentre* cb = ib.find(ib.numberOf(belt.a), ib.numberOf(belt.b));
  ASSERT_TRUE(cb && cb->determined);
  EXPECT_LT((cb->point() - Vec2(100, 0)).norm(), 1e-12 * 50);
  EXPECT_TRUE(ib.disagreements.empty());
  // The planet: IC(ground, planet) is the pitch point on the sun (a primary of the gear), and
  // every centre Kennedy finds agrees with the velocities.
  const Planet p = planet(20, 10);
  Kinematics kp = loaded(p.m);
  for (double deg : {0.0, 50.0, 133.0}) {
    ASSERT_TRUE(kp.moveTo(deg).ok());
    const InstantCentres ip = computeInstantCentres(kp);
    const InstantCentre* c = ip.find(1, ip.numberOf(p.planet));
    ASSERT_TRUE(c && c->determined);
    const double t = deg * kDeg;
    EXPECT_LT((c->point() - 20 * Vec2(std::cos(t), std::sin(t))).norm(), 1e-12 * 40) << deg;
    EXPECT_TRUE(ip.disagreements.empty()) << deg;
  }
}

TEST(Elements, ArcSlotCentresAreOnTheRadiusAndAtTheCentre) {
  // A pin in an arc: IC(coupler, ground) on the line through the pin and the arc's centre (a
  // Kennedy centre through it equals the four-bar's). A block in a curved guide: IC(block,
  // ground) at the arc's centre.
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 30, true, 25, -10);
  Kinematics a = loaded(fourBarWithArc(f, 50)), b = loaded(f.m);
  const CurvedGuide c = curvedGuide();
  Kinematics g = loaded(c.guide);
  for (double deg : {10.0, 100.0, 250.0}) {
    ASSERT_TRUE(a.moveTo(deg).ok() && b.moveTo(deg).ok() && g.moveTo(deg).ok());
    const InstantCentres ia = computeInstantCentres(a), ibar = computeInstantCentres(b);
    const InstantCentre* x = ia.find(1, ia.numberOf(f.coupler));
    const InstantCentre* y = ibar.find(1, ibar.numberOf(f.coupler));
    ASSERT_TRUE(x && y && x->determined && y->determined);
    EXPECT_LT((x->point() - y->point()).norm(), 1e-9 * 100) << deg;
    EXPECT_TRUE(ia.disagreements.empty());
    const InstantCentres ig = computeInstantCentres(g);
    const InstantCentre* z = ig.find(1, ig.numberOf(c.block));
    ASSERT_TRUE(z && z->determined);
    EXPECT_EQ(z->status, CentreStatus::Primary);
    EXPECT_LT((z->point() - Vec2(40, -60)).norm(), 1e-12 * 100);
    EXPECT_TRUE(ig.disagreements.empty());
  }
}

// The transmission angle of a block in a curved guide is the rocker's, of a pin in an arc slot
// the four-bar's: the same angle and rates at every pose (the radius is the rocker).
TEST(Elements, ArcTransmissionAnglesAreTheEquivalentLinkages) {
  const CurvedGuide c = curvedGuide();
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 30, true, 25, -10);
  const Mechanism arcFourBar = fourBarWithArc(f, 50);
  for (const auto& [a, b] : {std::pair{&c.guide, &c.rocker}, std::pair{&arcFourBar, &f.m}}) {
    const std::vector<TransmissionJoint> ta = transmissionJoints(*a), tb = transmissionJoints(*b);
    ASSERT_EQ(ta.size(), 1u);
    ASSERT_EQ(tb.size(), 1u);
    EXPECT_EQ(ta[0].kind, TransmissionKind::Dyad);
    Kinematics ka = loaded(*a), kb = loaded(*b);
    for (double deg = 0; deg < 360; deg += 9) {
      ASSERT_TRUE(ka.moveTo(deg).ok() && kb.moveTo(deg).ok());
      const TransmissionReading x = transmissionAngle(ka, ta[0]), y = transmissionAngle(kb, tb[0]);
      EXPECT_NEAR(x.deg, y.deg, 1e-10) << deg;
      EXPECT_NEAR(x.perDeg, y.perDeg, 1e-12) << deg;
      EXPECT_NEAR(x.perDeg2, y.perDeg2, 1e-12) << deg;
    }
  }
}

std::vector<Group::Kind> kinds(const Mechanism& m) {
  Status s;
  const std::optional<System> sys = compile(m, s);
  EXPECT_TRUE(sys) << s.message;
  std::vector<Group::Kind> out;
  for (const Group& g : decompose(*sys).groups) out.push_back(g.kind);
  return out;
}

TEST(Elements, TheDecompositionNamesTheNewGroups) {
  using K = Group::Kind;
  EXPECT_EQ(kinds(planet(20, 10).m), (std::vector<K>{K::Crank, K::Geared}));
  EXPECT_EQ(kinds(gearPair(-2).m), (std::vector<K>{K::Crank, K::Geared}));
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 30);
  EXPECT_EQ(kinds(fourBarWithArc(f, 50)), (std::vector<K>{K::Crank, K::RP}));
  // The block in a curved guide is pinned at the arc's centre: a dyad of two pins and that.
  EXPECT_EQ(kinds(curvedGuide().guide), (std::vector<K>{K::Crank, K::RRR}));
}

TEST(Elements, EachKindCompilesToItsEquationsAndSitsInItsPlace) {
  const auto all = elementKinds();
  ASSERT_GE(all.size(), 4u);
  for (size_t i = 0; i < all.size(); ++i) {
    EXPECT_EQ(all[i].type.index, i);
    EXPECT_EQ(elementKindNamed(all[i].name), &all[i]);
  }
  // The constants name the table's first entries.
  EXPECT_STREQ(elementKind(JointType::Pin).name, "pin");
  EXPECT_STREQ(elementKind(JointType::Slider).name, "slider");
  EXPECT_STREQ(elementKind(JointType::PinInSlot).name, "pin-in-slot");
  EXPECT_STREQ(elementKind(JointType::Gear).name, "gear");
  // Every joint of these compiles to rows adding up to its kind's equation count.
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 30);
  for (const Mechanism& m : {planet(20, 10).m, fourBarWithArc(f, 50), curvedGuide().guide,
                             test::sliderCrank(15, 50, 5, 30).m}) {
    Status s;
    const std::optional<System> sys = compile(m, s);
    ASSERT_TRUE(sys) << s.message;
    std::vector<int> rows(m.joints.size(), 0);
    for (const Row& r : sys->cons)
      if (r.joint >= 0 && !r.isDriver()) rows[r.joint] += r.rows();
    for (size_t j = 0; j < m.joints.size(); ++j)
      EXPECT_EQ(rows[j], kindOf(m.joints[j]).equations) << jointLabel(m, m.joints[j].id);
  }
}

}  // namespace
}  // namespace linkage
