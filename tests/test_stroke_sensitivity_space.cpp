// A stroke's derivatives on a machine in space (linkage/stroke_sensitivity.h): the RSSR
// crank-rocker's rocker point C along a world direction, every dimension against the closed form
// (tests/rssr_closed_form.h) differentiated by complex step at the limit positions, the limit
// positions themselves checked as the closed form's extremes over the turn.
#include <gtest/gtest.h>

#include <cstdio>

#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "linkage/space.h"
#include "linkage/stroke_sensitivity.h"
#include "rssr_closed_form.h"
#include "spatial_fixtures.h"

namespace linkage {
namespace {

using test::C;
using test::C3;
using test::RssrClosedForm;

// The rocker's angle at crank angle phi (radians), followed from the drawing in 1 degree steps
// on the closed form alone: the branch the solver keeps.
double rockerAngle(double phi) {
  double psi = test::rssr::kPsi0;
  const int steps = static_cast<int>(std::ceil(std::abs(phi) / (M_PI / 180)));
  for (int i = 1; i <= steps; ++i)
    psi = test::rockerNear(phi * i / steps, psi, test::rssrRod()).psi;
  return psi;
}

C along(const Vec3& u, const C3& r) {
  return test::dot(test::real(u), r);
}

// The stroke's derivative along u by every dimension against the closed form's, each within
// 1e-9 of the largest.
void checkStroke(const Kinematics& k, const Vec3& direction) {
  const Mechanism& m = k.mechanism();
  const PointId point = *m.findPoint("rocker.C");
  const StrokeSensitivity s = strokeSensitivity(k, point, direction, dimensions(m));
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  ASSERT_TRUE(s.limits.moves);
  const Vec3 u = direction.normalized();
  RssrClosedForm cf;
  for (const Dimension& d : s.dims) cf.v[d.name] = d.value;
  const double maxPhi = s.limits.maxDeg * M_PI / 180, minPhi = s.limits.minDeg * M_PI / 180;
  const double maxPsi = rockerAngle(maxPhi), minPsi = rockerAngle(minPhi);
  // The closed form's own extremes: its stroke is the solver's, its rate by the crank vanishes
  // there, and no crank angle of the turn goes beyond them.
  const auto atMax = cf.rocker(maxPhi, maxPsi), atMin = cf.rocker(minPhi, minPsi);
  const double hi = along(u, atMax[0]).real(), lo = along(u, atMin[0]).real();
  EXPECT_NEAR(hi - lo, s.limits.stroke, 1e-12);
  EXPECT_NEAR(along(u, atMax[1]).real(), 0, 1e-9);
  EXPECT_NEAR(along(u, atMin[1]).real(), 0, 1e-9);
  double psi = test::rssr::kPsi0;
  for (int tenth = 0; tenth <= 3600; ++tenth) {
    const double phi = tenth * M_PI / 1800;
    psi = test::rockerNear(phi, psi, test::rssrRod()).psi;
    const double v = along(u, cf.rocker(phi, psi)[0]).real();
    EXPECT_LE(v, hi + 1e-12) << tenth / 10.0;
    EXPECT_GE(v, lo - 1e-12) << tenth / 10.0;
  }
  std::vector<double> want;
  double peak = 0;
  for (const Dimension& d : s.dims) {
    RssrClosedForm stepped = cf;
    stepped.v[d.name] += C(0, test::kRssrH);
    want.push_back((along(u, stepped.rocker(maxPhi, maxPsi)[0]).imag() -
                    along(u, stepped.rocker(minPhi, minPsi)[0]).imag()) /
                   test::kRssrH);
    peak = std::max(peak, std::abs(want.back()));
  }
  ASSERT_GT(peak, 1e-3);
  double worst = 0;
  for (size_t d = 0; d < s.dims.size(); ++d) {
    EXPECT_NEAR(s.derivative[d], want[d], 1e-9 * peak) << s.dims[d].name;
    worst = std::max(worst, std::abs(s.derivative[d] - want[d]) / peak);
  }
  std::printf("  along (%.3g, %.3g, %.3g): stroke %.6g mm, %zu dimensions, worst error/peak %.2e\n",
              u.x(), u.y(), u.z(), s.limits.stroke, s.dims.size(), worst);
}

Kinematics rssr() {
  LoadResult r = parseMechanism(test::rssrText());
  EXPECT_TRUE(r.mechanism) << r.error;
  Kinematics k;
  EXPECT_TRUE(r.mechanism && k.load(*r.mechanism).ok());
  return k;
}

// Along the default direction in space (the world's +y, as `linkage-cli limits` takes it), and
// along a direction with every component, where the rocker point's stroke is its swing's.
TEST(StrokeSensitivitySpace, TheRssrRockersStrokeMatchesItsClosedFormByComplexStep) {
  const Kinematics k = rssr();
  ASSERT_TRUE(k.valid());
  const PointId c = *k.mechanism().findPoint("rocker.C");
  EXPECT_EQ(strokeDirection(k.mechanism(), c), Vec3(0, 1, 0));
  checkStroke(k, strokeDirection(k.mechanism(), c));
  checkStroke(k, Vec3(0.3, -0.5, 0.8));
  checkStroke(k, test::rssr::kY);
}

// A z on a planar machine is refused by name, not measured in a plane it does not have.
TEST(StrokeSensitivitySpace, APlanarMachinesStrokeRefusesADirectionWithZ) {
  LoadResult r = parseMechanism(R"({"format": "linkage", "version": 1,
    "bodies": [{"name": "ground", "ground": true, "points": {"O": [0, 0], "B": [40, 10]}},
               {"name": "crank", "points": {"O": [0, 0], "A": [10, 0]}},
               {"name": "rocker", "points": {"B": [40, 10], "C": [40, 40]}},
               {"name": "coupler", "points": {"A": [10, 0], "C": [40, 40]}}],
    "joints": [{"type": "pin", "a": "ground.O", "b": "crank.O"},
               {"type": "pin", "a": "ground.B", "b": "rocker.B"},
               {"type": "pin", "a": "crank.A", "b": "coupler.A"},
               {"type": "pin", "a": "coupler.C", "b": "rocker.C"}],
    "driver": {"joint": 0, "rpm": 60, "direction": "ccw"}})");
  ASSERT_TRUE(r.mechanism) << r.error;
  Kinematics k;
  ASSERT_TRUE(k.load(*r.mechanism).ok());
  const PointId c = *r.mechanism->findPoint("rocker.C");
  const StrokeSensitivity s = strokeSensitivity(k, c, Vec3(0, 1, 1), dimensions(*r.mechanism));
  EXPECT_EQ(s.status.code, StatusCode::BadModel);
  EXPECT_NE(s.status.message.find("machine in space"), std::string::npos) << s.status.message;
  // Along (0, 1, 0) it is the planar stroke's, to the bit.
  const StrokeSensitivity y = strokeSensitivity(k, c, Vec3(0, 1, 0), dimensions(*r.mechanism));
  const StrokeSensitivity planar = strokeSensitivity(k, c, Vec2(0, 1), dimensions(*r.mechanism));
  ASSERT_TRUE(y.status.ok()) << y.status.message;
  EXPECT_EQ(y.derivative, planar.derivative);
  EXPECT_EQ(y.limits.stroke, planar.limits.stroke);
}

}  // namespace
}  // namespace linkage
