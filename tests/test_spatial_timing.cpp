// Limits and timing windows on a machine in space: a point's world x, y, z or its position along
// a direction in space, and the distance between two points, against the lockstitch machine's
// closed form (derived from its drawing alone: spatial_fixtures.h). The vertical
// shaft turns with the arm shaft (a bevel pair of ratio 1) about the world's y; its point M,
// drawn 12 mm out at depth 100 in the plane x (1, 0, 0), y (0, 0, -1) through (20, 0, 0), is at
// (20 + 12 cos phi, 100, -12 sin phi).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "analysis/measure_track.h"
#include "examples.h"
#include "linkage/kinematics.h"
#include "linkage/limits.h"
#include "linkage/timing.h"
#include "linkage/timing_text.h"
#include "spatial_fixtures.h"

namespace linkage {
namespace {

constexpr double kDeg = M_PI / 180;

using test::lockstitch_bevel::hookK;
Vec3 needleN(double phi) {
  return test::lockstitch_bevel::needleAt(phi, 131);
}

// Where f crosses 0 over a turn, by bisection in brackets of 0.1-degree samples.
std::vector<double> rootsOf(const std::function<double(double)>& f) {
  std::vector<double> out;
  for (int i = 0; i < 3600; ++i) {
    double lo = i * 0.1, hi = lo + 0.1;
    if ((f(lo * kDeg) > 0) == (f(hi * kDeg) > 0)) continue;
    for (int it = 0; it < 100; ++it) {
      const double mid = (lo + hi) / 2;
      ((f(mid * kDeg) > 0) == (f(lo * kDeg) > 0) ? lo : hi) = mid;
    }
    out.push_back((lo + hi) / 2);
  }
  return out;
}

std::vector<AngleInterval> windowOf(const Kinematics& k, const std::string& text) {
  std::string why;
  const std::optional<CycleWindow> w = parseWindow(k.mechanism(), text, &why);
  EXPECT_TRUE(w) << why;
  if (!w) return {};
  const CycleDiagram d = cycleDiagram(k, {}, {*w}, {});
  EXPECT_TRUE(d.status.ok()) << d.status.message;
  return d.windows.empty() ? std::vector<AngleInterval>{} : d.windows[0].intervals;
}

TEST(SpatialTiming, WindowsOnZOnADirectionInSpaceAndOnADistance) {
  const Mechanism m = test::example("lockstitch-bevel");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  // z > 6 where sin(phi) < -1/2.
  std::vector<AngleInterval> low = windowOf(k, "low=vshaft.M:z>6");
  ASSERT_EQ(low.size(), 1u);
  EXPECT_NEAR(low[0].fromDeg, 210, 1e-9);
  EXPECT_NEAR(low[0].toDeg, 330, 1e-9);
  // Along (1, 0, 1) / sqrt 2 above 20 / sqrt 2 where cos(phi) > sin(phi): through 0.
  std::vector<AngleInterval> diag = windowOf(k, "diag=vshaft.M:1,0,1>14.142135623730951");
  ASSERT_EQ(diag.size(), 1u);
  EXPECT_NEAR(diag[0].fromDeg, 225, 1e-9);
  EXPECT_NEAR(diag[0].toDeg, 405, 1e-9);
  // The hook point within 30 mm of the needle's point: the closed form's crossings.
  auto f = [](double phi) { return (hookK(phi) - needleN(phi)).norm() - 30; };
  const std::vector<double> roots = rootsOf(f);
  std::vector<AngleInterval> near = windowOf(k, "near=hook.K:distance:needlebar.N<30");
  ASSERT_EQ(2 * near.size(), roots.size());
  ASSERT_FALSE(roots.empty());
  std::vector<double> ends;
  for (const AngleInterval& i : near) {
    ends.push_back(i.fromDeg);
    ends.push_back(std::fmod(i.toDeg, 360));
  }
  std::sort(ends.begin(), ends.end());
  for (size_t i = 0; i < roots.size(); ++i) EXPECT_NEAR(ends[i], roots[i], 1e-7) << i;
}

TEST(SpatialTiming, LimitsOfAWorldCoordinateAndTheTextComesBack) {
  const Mechanism m = test::example("lockstitch-bevel");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  std::string why;
  const std::optional<LimitMeasure> z = parseMeasure(m, "vshaft.M:z", &why);
  ASSERT_TRUE(z) << why;
  const Limits lim = findLimits(k, *z);
  ASSERT_TRUE(lim.status.ok()) << lim.status.message;
  EXPECT_NEAR(lim.min, -12, 1e-9);
  EXPECT_NEAR(lim.minDeg, 90, 1e-7);
  EXPECT_NEAR(lim.max, 12, 1e-9);
  EXPECT_NEAR(lim.maxDeg, 270, 1e-7);
  for (const char* text :
       {"vshaft.M:z", "hook.K:distance:needlebar.N", "vshaft.M:0.6,0,0.8", "needlebar.N:y"}) {
    const std::optional<LimitMeasure> x = parseMeasure(m, text, &why);
    ASSERT_TRUE(x) << text << ": " << why;
    EXPECT_EQ(measureText(m, *x), text);
  }
  // The world's y of the needle's point: the slider-crank's, 131 mm below its block.
  ASSERT_TRUE(k.moveTo(40).ok());
  EXPECT_NEAR(readMeasure(k, *parseMeasure(m, "needlebar.N:y", &why)).value, needleN(40 * kDeg).y(),
              1e-9);
}

TEST(SpatialTiming, ZIsRefusedOnAPlanarMachine) {
  const Mechanism m = test::example("lockstitch-machine");
  std::string why;
  EXPECT_FALSE(parseMeasure(m, "needlebar.N:z", &why));
  EXPECT_EQ(why,
            "\"z\" after \"needlebar.N:\" is not x, y, angle or a direction DX,DY other than 0,0");
  // A distance between two points is a measure of a planar machine too.
  EXPECT_TRUE(parseMeasure(m, "needlebar.N:distance:hook.K", &why)) << why;
}

}  // namespace
}  // namespace linkage
