// The 876-class needle mechanism of seed 001 (resources/examples/needle-876-alpha-*.linkage.json):
// its dimensions are the paper's, it assembles as drawn, turns fully, and its needle is at its
// lowest position in the drawing at every alpha.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include "examples.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "linkage/limits.h"
#include "reference/needle876.h"

namespace linkage {
namespace {

Mechanism needle(int alpha) {
  return test::example("needle-876-alpha-" + std::to_string(alpha));
}

Vec2 at(const Mechanism& m, const std::string& dotted) {
  const std::optional<PointId> p = m.findPoint(dotted);
  EXPECT_TRUE(p.has_value()) << dotted;
  return p ? m.point(*p)->pos : Vec2(NAN, NAN);
}

double length(const Mechanism& m, const std::string& a, const std::string& b) {
  return (at(m, a) - at(m, b)).norm();
}

TEST(Needle876, DimensionsAreThePapers) {
  for (int alpha : {0, 35}) {
    const Mechanism m = needle(alpha);
    EXPECT_NEAR(length(m, "crank.O", "crank.A"), 15, 1e-12);
    EXPECT_NEAR(length(m, "coupler.A", "coupler.B"), 175, 1e-12);
    EXPECT_NEAR(length(m, "lever.B", "lever.C"), 25, 1e-12);
    EXPECT_NEAR(length(m, "lever.C", "lever.D"), 17, 1e-12);
    EXPECT_NEAR(length(m, "lever.B", "lever.D"), 42, 1e-12);  // a straight lever
    EXPECT_NEAR(length(m, "link.D", "link.E"), 30, 1e-12);
    EXPECT_NEAR(length(m, "rocker.E", "rocker.F"), 25, 1e-12);
    EXPECT_NEAR(length(m, "rod.E", "rod.G"), 30, 1e-12);
    // b = 20: the guide is the vertical 20 mm to the right of C.
    const Slot* guide = m.slotNamed(m.ground()->id, "guide");
    ASSERT_NE(guide, nullptr);
    EXPECT_EQ(guide->p0.x(), at(m, "ground.C").x() + 20);
    EXPECT_EQ(guide->p1.x(), guide->p0.x());
    // Formula (8): F on the arc of radius EF about E, turned clockwise by alpha from straight
    // below C, where x_OF = 18 and CF is the paper's 37.945 rounded from 37.9446.
    const Vec2 F = at(m, "ground.F"), E = at(m, "rocker.E"), C = at(m, "ground.C");
    const double a = alpha * M_PI / 180;
    EXPECT_NEAR(F.x(), C.x() + 25 - 25 * std::cos(a), 1e-12);
    EXPECT_NEAR(F.y(), E.y() + 25 * std::sin(a), 1e-12);
    EXPECT_NEAR(C.y() - E.y(), 37.945, 5e-4);
    EXPECT_EQ(at(m, "ground.O").x() + 18, C.x());
  }
}

TEST(Needle876, FilesAreAsTheProgramSavesThem) {
  for (int alpha : {0, 35}) {
    const std::string path = std::string(LINKAGE_EXAMPLES_DIR) + "/needle-876-alpha-" +
                             std::to_string(alpha) + ".linkage.json";
    std::ifstream f(path);
    const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    EXPECT_EQ(serializeMechanism(needle(alpha)), text) << path;
  }
}

TEST(Needle876, AssemblesAsDrawnTurnsFullyAndStartsAtTheLowestPosition) {
  for (int alpha : {0, 35}) {
    const Mechanism m = needle(alpha);
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok());
    EXPECT_FALSE(k.assembly().moved);
    EXPECT_EQ(k.structure().mobility, 1);
    EXPECT_TRUE(k.closedForm());
    const PointId G = m.outputs.at(0);
    const double lowest = k.position(G).y();
    EXPECT_NEAR(lowest, 107.4750004009442, 1e-12);
    // At the drawing the crank and the coupler are stretched: D, E and G stand still.
    EXPECT_NEAR(k.velocity(G).y(), 0, 1e-10 * k.omega() * k.size());
    for (int deg = 1; deg < 360; ++deg) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << "alpha " << alpha << " at " << deg;
      EXPECT_GT(k.position(G).y(), lowest) << deg;
    }
    ASSERT_TRUE(k.moveTo(360).ok());
    EXPECT_NEAR(k.position(G).y(), lowest, 1e-12);
  }
}

TEST(Needle876, NeedleStrokeIsBetweenTheTwoStretchedAndFoldedPositions) {
  // The needle stands still where crank and coupler are collinear: stretched (the drawing,
  // crank angle 0: the bottom) and folded (|OB| = AB - OA = 160: the top). Closed form of the
  // folded position in __float128: B on the circles (O, 160) and (C, 25), on the side where the
  // reference's B passes, the crank pointing away from B.
  using Q = __float128;
  for (int alpha : {0, 35}) {
    const Mechanism m = needle(alpha);
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok());
    const Limits lim = findLimits(
        k, LimitMeasure::along(*m.findPoint("needlebar.G"), defaultDirection(m, m.outputs[0])));
    ASSERT_TRUE(lim.status.ok()) << lim.status.message;
    ASSERT_EQ(lim.extremes.size(), 2u);
    const linkref::Needle876<Q> ref(alpha);
    EXPECT_FALSE(lim.extremes[0].max);
    EXPECT_NEAR(lim.extremes[0].crankDeg, 0, 1e-9);
    EXPECT_NEAR(lim.extremes[0].value, static_cast<double>(ref.at(Q(0)).G.y), 1e-9);
    const linkref::Vec2<Q> C = ref.C;
    const Q d = linkref::norm(C), r = 160, x = (r * r - Q(625) + d * d) / (2 * d),
            h = linkref::sqrt(r * r - x * x);
    double best = 1e300, top = 0;
    for (const Q side : {h, -h}) {
      const linkref::Vec2<Q> B = (x / d) * C + (side / d) * linkref::perp(C);
      Q deg = (linkref::atan2(-B.y, -B.x) - linkref::atan2(ref.at(Q(0)).A.y, ref.at(Q(0)).A.x)) *
              180 / linkref::pi<Q>();
      while (deg < 0) deg += 360;
      const double miss = static_cast<double>(linkref::norm(ref.at(deg).B - B));
      if (miss < best) best = miss, top = static_cast<double>(deg);
    }
    ASSERT_LT(best, 1e-9);
    EXPECT_TRUE(lim.extremes[1].max);
    EXPECT_NEAR(lim.extremes[1].crankDeg, top, 1e-9);
    EXPECT_NEAR(lim.extremes[1].value, static_cast<double>(ref.at(Q(top)).G.y), 1e-9);
    // The paper: 18 to 23 mm for alpha 0 to 35.
    EXPECT_NEAR(lim.stroke, alpha == 0 ? 18 : 23, 0.5);
  }
}

}  // namespace
}  // namespace linkage
