// The design checks on mechanisms nobody drew on purpose: random four-bars, slider-cranks and
// six-bars of any proportions. Every check ends in finite results that agree with each other and
// with the motion, or in a failure with a message; and Grashof's class says whether the crank
// turns fully, as the tracker finds.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "linkage/grashof.h"
#include "linkage/limits.h"
#include "linkage/transmission.h"
#include "mechanisms.h"
#include "slow_build.h"

namespace linkage {
namespace {

constexpr int kCases = test::kSlowBuild ? 60 : 240;

// Local extremes of a continuous periodic quantity alternate.
template <class E>
void expectAlternating(const std::vector<E>& x, const std::string& what) {
  for (size_t i = 1; i < x.size(); ++i) EXPECT_NE(x[i].max, x[i - 1].max) << what << " #" << i;
  if (x.size() > 1) EXPECT_NE(x.front().max, x.back().max) << what << " (around the turn)";
}

// Returns whether the crank turned fully.
bool check(const Mechanism& m, const std::string& what) {
  Kinematics k;
  if (!k.load(m).ok()) return false;
  const TransmissionSweep t = sweepTransmission(k);
  if (!t.status.ok()) {
    EXPECT_FALSE(t.status.message.empty()) << what;
    EXPECT_EQ(t.status.code, StatusCode::Unreachable) << what << ": " << t.status.message;
    return false;
  }
  for (size_t j = 0; j < t.joints.size(); ++j) {
    const TransmissionSummary& s = t.summaries[j];
    EXPECT_TRUE(std::isfinite(s.min) && std::isfinite(s.max)) << what;
    EXPECT_GE(s.min, 0) << what;
    EXPECT_LE(s.max, 180) << what;
    for (double v : t.values[j]) {
      EXPECT_GE(v, s.min - 1e-12) << what << " " << t.joints[j].label;
      EXPECT_LE(v, s.max + 1e-12) << what << " " << t.joints[j].label;
    }
    expectAlternating(s.extremes, what + " " + t.joints[j].label);
  }
  std::vector<LimitMeasure> measures;
  for (const Point& p : m.points) measures.push_back(LimitMeasure::along(p.id, Vec2(0.6, 0.8)));
  for (const Body& b : m.bodies)
    if (!b.ground) measures.push_back(LimitMeasure::angleOf(b.id));
  for (const LimitMeasure& w : measures) {
    const Limits l = findLimits(k, w);
    EXPECT_TRUE(l.status.ok()) << what << ": " << l.status.message;
    EXPECT_TRUE(std::isfinite(l.min) && std::isfinite(l.max) && l.stroke >= 0) << what;
    if (l.moves) expectAlternating(l.extremes, what);
    // Every sample lies between the exact extremes.
    Kinematics s = k;
    for (int deg = 0; deg <= 360; deg += 3) {
      EXPECT_TRUE(s.moveTo(deg).ok()) << what;
      const double v =
          w.body ? s.bodyAngle(w.body) * 180 / M_PI : s.position(w.point).dot(w.direction);
      EXPECT_GE(v, l.min - 1e-9) << what << " at " << deg;
      EXPECT_LE(v, l.max + 1e-9) << what << " at " << deg;
    }
  }
  return true;
}

TEST(DesignRandom, ChecksOfAnyProportionsAgreeOrSayWhyNot) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> len(5, 120), ang(0, 360), off(-30, 30);
  int turned = 0, stopped = 0, grashofCompared = 0;
  for (int i = 0; i < kCases; ++i) {
    const Direction dir = rng() % 2 ? Direction::Cw : Direction::Ccw;
    const std::string what = std::to_string(i);
    switch (i % 3) {
      case 0: {
        const double d = len(rng), r2 = len(rng), r3 = len(rng), r4 = len(rng);
        auto f = test::fourBar(d, r2, r3, r4, ang(rng), rng() % 2, off(rng), off(rng), dir);
        Kinematics k;
        if (!k.load(f.m).ok()) continue;  // drawn where it cannot close
        const bool turns = check(f.m, "four-bar #" + what);
        (turns ? turned : stopped) += 1;
        // Grashof: the crank turns fully exactly when the loop is a crank-rocker or a
        // double-crank (away from a change point, where either can happen).
        const std::vector<FourBarLoop> loops = fourBarLoops(f.m);
        ASSERT_EQ(loops.size(), 1u);
        if (std::abs(loops[0].margin) > 1e-6 * (d + r2 + r3 + r4) && ++grashofCompared)
          EXPECT_EQ(turns, loops[0].kind == GrashofClass::CrankRocker ||
                               loops[0].kind == GrashofClass::DoubleCrank)
              << "four-bar #" << what << ": " << toString(loops[0].kind);
        break;
      }
      case 1: {
        auto s = test::sliderCrank(len(rng), len(rng), off(rng), ang(rng), dir, 100, rng() % 2);
        Kinematics k;
        if (!k.load(s.m).ok()) continue;
        (check(s.m, "slider-crank #" + what) ? turned : stopped) += 1;
        break;
      }
      default: {
        // A four-bar with a second dyad on its coupler: six bodies, two dyads.
        auto f = test::fourBar(len(rng), len(rng), len(rng), len(rng), ang(rng), true, off(rng),
                               off(rng), dir);
        Mechanism& m = f.m;
        const Vec2 P = m.point(f.P)->pos, Q(len(rng), -len(rng));
        const Vec2 C = (P + Q) / 2 + Vec2(off(rng), off(rng));
        const BodyId a = m.addBody("a"), b = m.addBody("b");
        m.addPin(*m.findPoint("coupler.P"), m.addPoint(a, "P", P));
        m.addPin(m.addPoint(a, "C", C), m.addPoint(b, "C", C));
        m.addPin(m.addPoint(b, "Q", Q), m.addPoint(m.ground()->id, "Q", Q));
        Kinematics k;
        if (!k.load(m).ok()) continue;
        EXPECT_EQ(transmissionJoints(m).size(), 2u);
        (check(m, "six-bar #" + what) ? turned : stopped) += 1;
      }
    }
  }
  // Both outcomes happen, or the proportions test nothing.
  EXPECT_GT(turned, kCases / 20);
  EXPECT_GT(stopped, kCases / 20);
  EXPECT_GT(grashofCompared, kCases / 10);
}

}  // namespace
}  // namespace linkage
