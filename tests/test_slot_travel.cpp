// Slot travel (linkage/slot_travel.h) against closed forms: an offset slider-crank's block (or
// its rod's pin in the slot) runs between sqrt((l - r)^2 - e^2) and sqrt((l + r)^2 - e^2) above
// the crank pivot, at the crank angles where crank and rod are collinear; a block in an arc slot
// (a crank-rocker whose rocker is the arc's radius) turns between the angles where crank and
// rod are collinear, the circles' intersections.
#include <gtest/gtest.h>

#include <cmath>

#include "linkage/guide.h"
#include "linkage/slot_travel.h"
#include "mechanisms.h"

namespace linkage {
namespace {

double crankOf(double theta, double theta0) {
  double d = (theta - theta0) * 180 / M_PI;
  d -= 360 * std::floor(d / 360);
  return d;
}

double gapDeg(double a, double b) {
  const double d = std::abs(a - b);
  return std::min(d, 360 - d);
}

struct Case {
  double r, l, e, drawnDeg;
  bool pinInSlot;
};

class SliderCrankTravel : public ::testing::TestWithParam<Case> {};

TEST_P(SliderCrankTravel, MatchesClosedForm) {
  const Case c = GetParam();
  test::SliderCrank s =
      test::sliderCrank(c.r, c.l, c.e, c.drawnDeg, Direction::Ccw, 60, c.pinInSlot);
  Kinematics k;
  ASSERT_TRUE(k.load(s.m).ok());
  const SlotTravels t = slotTravel(k);
  ASSERT_TRUE(t.status.ok()) << t.status.message;
  ASSERT_EQ(t.joints.size(), 1u);
  const SlotTravel& j = t.joints[0];
  const double yMax = std::sqrt((c.r + c.l) * (c.r + c.l) - c.e * c.e);
  const double yMin = std::sqrt((c.l - c.r) * (c.l - c.r) - c.e * c.e);
  const double t0 = c.drawnDeg * M_PI / 180;
  EXPECT_NEAR(j.max, yMax, 1e-9 * yMax);
  EXPECT_NEAR(j.min, yMin, 1e-9 * yMax);
  EXPECT_LT(gapDeg(j.maxDeg, crankOf(std::atan2(yMax, c.e), t0)), 1e-9);
  EXPECT_LT(gapDeg(j.minDeg, crankOf(std::atan2(-yMin, -c.e), t0)), 1e-9);
  EXPECT_EQ(j.slotFrom, 0);
  EXPECT_NEAR(j.slotTo, c.r + c.l, 1e-12);
  EXPECT_TRUE(j.inside);
  EXPECT_TRUE(t.allInside());
  EXPECT_EQ(j.joint, s.m.joints.back().id);
}

INSTANTIATE_TEST_SUITE_P(Cases, SliderCrankTravel,
                         ::testing::Values(Case{20, 60, 0, 30, false}, Case{20, 60, 8, 30, false},
                                           Case{15, 50, -6, 200, true},
                                           Case{30, 60, 5, 123, false}));

// The slot cut short at both ends: the block leaves it by the closed form's amounts.
TEST(SlotTravel, BlockLeavingItsSlot) {
  test::SliderCrank s = test::sliderCrank(20, 60, 0, 30);
  Slot& slot = s.m.slots.front();
  slot.p0 = Vec2(0, 41);  // the block comes down to 40
  slot.p1 = Vec2(0, 78);  // and goes up to 80
  Kinematics k;
  ASSERT_TRUE(k.load(s.m).ok());
  const SlotTravels t = slotTravel(k);
  ASSERT_TRUE(t.status.ok());
  const SlotTravel& j = t.joints[0];
  EXPECT_NEAR(j.min, -1, 1e-12 * 80);
  EXPECT_NEAR(j.max, 39, 1e-12 * 80);
  EXPECT_NEAR(j.slotTo, 37, 1e-12);
  EXPECT_NEAR(j.before, 1, 1e-9);
  EXPECT_NEAR(j.past, 2, 1e-9);
  EXPECT_FALSE(j.inside);
  EXPECT_FALSE(t.allInside());
}

// A crank O-A (r), a rod A-B (l), the block B in a ground arc slot of radius rho about C: B's
// extremes on the arc are where |OB| = l + r and l - r, the intersections of the circles.
TEST(SlotTravel, ArcSlotAgainstCircleIntersections) {
  const double r = 10, l = 50, rho = 30;
  const Vec2 O(0, 0), C(45, 0);
  // B on the arc where |OB| = l + r (the extended position), the branch above the x axis.
  auto meet = [&](double d) {  // circle(O, d) with circle(C, rho), y > 0
    const double x = (d * d - rho * rho + C.x() * C.x()) / (2 * C.x());
    return Vec2(x, std::sqrt(d * d - x * x));
  };
  const Vec2 far = meet(l + r), near = meet(l - r);
  Mechanism m;
  const BodyId g = m.addBody("ground", true), crank = m.addBody("crank"), rod = m.addBody("rod"),
               block = m.addBody("block");
  const double th = 80 * M_PI / 180;
  const Vec2 A(r * std::cos(th), r * std::sin(th));
  const Vec2 mid = meet(std::sqrt(l * l + r * r));  // a point of the arc between them
  // B: on the arc at distance l from A (upper branch).
  const double dAC = (C - A).norm();
  const double along = (dAC * dAC + rho * rho - l * l) / (2 * dAC);  // from C towards A
  const Vec2 u = (A - C) / dAC;
  const Vec2 B = C + along * u + std::sqrt(rho * rho - along * along) * Vec2(u.y(), -u.x());
  ASSERT_GT(B.y(), 0);
  const SlotId slot = m.addArcSlot(g, "arc", C + rho * Vec2(-1, 0.2).normalized(), mid,
                                   C + rho * Vec2(0.3, 1).normalized());
  const JointId drive = m.addPin(m.addPoint(g, "O", O), m.addPoint(crank, "O", O));
  m.addPin(m.addPoint(crank, "A", A), m.addPoint(rod, "A", A));
  const PointId bRod = m.addPoint(rod, "B", B), bBlock = m.addPoint(block, "B", B);
  m.addPin(bRod, bBlock);
  m.addSlider(bBlock, slot);
  m.driver = Driver{drive, 60, Direction::Ccw, 0, ""};
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const SlotTravels t = slotTravel(k);
  ASSERT_TRUE(t.status.ok()) << t.status.message;
  ASSERT_EQ(t.joints.size(), 1u);
  const Guide gd = *guideOf(*m.slot(slot));
  const double sFar = gd.along(far), sNear = gd.along(near);
  const SlotTravel& j = t.joints[0];
  EXPECT_NEAR(j.min, std::min(sFar, sNear), 1e-9 * rho);
  EXPECT_NEAR(j.max, std::max(sFar, sNear), 1e-9 * rho);
  EXPECT_NEAR(j.slotTo, gd.length(), 1e-12);
  // The crank angles: A on the line O-B (extended) or opposite (folded).
  const double degFar = crankOf(std::atan2(far.y(), far.x()), th);
  const double degNear = crankOf(std::atan2(-near.y(), -near.x()), th);
  EXPECT_LT(gapDeg(sFar > sNear ? j.maxDeg : j.minDeg, degFar), 1e-9);
  EXPECT_LT(gapDeg(sFar > sNear ? j.minDeg : j.maxDeg, degNear), 1e-9);
  EXPECT_EQ(j.inside, j.min >= 0 && j.max <= gd.length());
}

// The same swing with the arc drawn on the far side of its circle, so that the pin passes the
// place opposite the arc's middle, where a position along the arc jumps by the circle's length:
// the travel is continuous all the same, the swing's length between the extended and folded
// positions, a whole number of turns of the circle from the positions along the arc there.
TEST(SlotTravel, ArcSlotOppositeTheSwingDoesNotJump) {
  const double r = 10, l = 50, rho = 30;
  const Vec2 O(0, 0), C(45, 0);
  auto meet = [&](double d) {
    const double x = (d * d - rho * rho + C.x() * C.x()) / (2 * C.x());
    return Vec2(x, std::sqrt(d * d - x * x));
  };
  const Vec2 far = meet(l + r), near = meet(l - r);
  Mechanism m;
  const BodyId g = m.addBody("ground", true), crank = m.addBody("crank"), rod = m.addBody("rod");
  const double th = 80 * M_PI / 180;
  const Vec2 A(r * std::cos(th), r * std::sin(th));
  const double dAC = (C - A).norm();
  const double along = (dAC * dAC + rho * rho - l * l) / (2 * dAC);
  const Vec2 u = (A - C) / dAC;
  const Vec2 B = C + along * u + std::sqrt(rho * rho - along * along) * Vec2(u.y(), -u.x());
  // The arc below the circle's centre, its middle straight down: opposite the swing above.
  const Vec2 mid = C + rho * Vec2(0, -1);
  const SlotId slot = m.addArcSlot(g, "arc", C + rho * Vec2(-1, -1).normalized(), mid,
                                   C + rho * Vec2(1, -1).normalized());
  const JointId drive = m.addPin(m.addPoint(g, "O", O), m.addPoint(crank, "O", O));
  m.addPin(m.addPoint(crank, "A", A), m.addPoint(rod, "A", A));
  m.addPinInSlot(m.addPoint(rod, "B", B), slot);
  m.driver = Driver{drive, 60, Direction::Ccw, 0, ""};
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const SlotTravels t = slotTravel(k);
  ASSERT_TRUE(t.status.ok()) << t.status.message;
  ASSERT_EQ(t.joints.size(), 1u);
  const Guide gd = *guideOf(*m.slot(slot));
  const double turn = 2 * M_PI * rho;
  const double sFar = gd.along(far);
  double sNear = gd.along(near);
  sNear += turn * std::round((sFar - sNear) / turn);  // the same side of the jump as sFar
  const SlotTravel& j = t.joints[0];
  EXPECT_NEAR(j.max - j.min, std::abs(sFar - sNear), 1e-9 * rho);
  const double shift = j.min - std::min(sFar, sNear);
  EXPECT_NEAR(shift, turn * std::round(shift / turn), 1e-9 * rho);
  EXPECT_LT(j.max - j.min, turn / 2);  // (before: nearly a whole turn, across the jump)
  EXPECT_FALSE(j.inside);
}

TEST(SlotTravel, NothingLoaded) {
  EXPECT_EQ(slotTravel(Kinematics()).status.code, StatusCode::BadModel);
}

}  // namespace
}  // namespace linkage
