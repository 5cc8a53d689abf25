// A timing window's ends on a machine in space differentiated with respect to the dimensions
// (linkage/window_sensitivity.h; the world's position along the window's direction, dz included),
// against the lockstitch machine's closed form (tests/test_spatial_timing.cpp): its vertical
// shaft turns `ratio` times the arm shaft about the world's y through the ground's V, so its
// point M is at (V.x + r cos(ratio phi), ., V.z - r sin(ratio phi)), r = vshaft.V-M. Each end is
// found again by Newton's method over std::complex with one dimension stepped by i 1e-30: its
// imaginary part is the end's exact derivative, independent of the solver's implicit-function
// formula. The dimensions the closed form does not hold move no end (0 to 1e-12).
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "complex_step.h"
#include "examples.h"
#include "linkage/dimension_change.h"
#include "linkage/kinematics.h"
#include "linkage/optimize.h"
#include "linkage/timing.h"
#include "linkage/window_sensitivity.h"

namespace linkage {
namespace {

using test::C;
using test::kH;

// The window's output along (ux, 0, uz) at crank phi (radians) and its crank derivative.
struct Along {
  double ux, uz;
  std::pair<C, C> at(const std::map<std::string, C>& v, C phi) const {
    const C r = v.at("vshaft.V-M"), ratio = v.at("armshaft-vshaft.ratio");
    const C x = v.at("ground.V.x") + r * std::cos(ratio * phi);
    const C z = v.at("ground.V.z") - r * std::sin(ratio * phi);
    const C dx = -r * ratio * std::sin(ratio * phi), dz = -r * ratio * std::cos(ratio * phi);
    return {ux * x + uz * z, ux * dx + uz * dz};
  }
  // The crank angle (degrees) where it crosses `level`, from `deg`.
  C end(const std::map<std::string, C>& v, double deg, double level) const {
    C phi = deg * M_PI / 180;
    for (int it = 0; it < 30; ++it) {
      const auto [f, df] = at(v, phi);
      phi -= (f - level) / df;
    }
    return phi * (180 / M_PI);
  }
};

void expectEnds(const char* text, const char* name, const Along& along, double level) {
  const Mechanism m = test::exampleWithWindow("lockstitch-bevel", text);
  ASSERT_EQ(m.timing.windows.size(), 1u);
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const std::vector<Dimension> dims = dimensions(m);
  const WindowSensitivity s = windowSensitivity(k, name, dims);
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  ASSERT_FALSE(s.intervals.empty());
  std::map<std::string, C> base;
  for (const Dimension& d : dims) base[d.name] = d.value;
  double peak = 0, worst = 0;
  for (const WindowEndSensitivity& e : s.intervals)
    for (int end = 0; end < 2; ++end) {
      const double deg = end ? e.toDeg : e.fromDeg;
      EXPECT_NEAR(along.end(base, deg, level).real(), deg, 1e-7) << name;
      for (size_t d = 0; d < dims.size(); ++d) {
        std::map<std::string, C> v = base;
        v.at(dims[d].name) += C(0, kH);
        const double want = along.end(v, deg, level).imag() / kH;
        const double got = end ? e.dTo[d] : e.dFrom[d];
        peak = std::max(peak, std::abs(want));
        worst = std::max(worst, std::abs(got - want));
        EXPECT_NEAR(got, want, 1e-9 * (1 + std::abs(want))) << name << " " << dims[d].name;
      }
    }
  std::printf("  %s: %zu intervals, peak %.4g degrees per unit, worst error %.2e\n", name,
              s.intervals.size(), peak, worst);
  EXPECT_GT(peak, 1);
}

TEST(SpatialWindowSensitivity, EndsOnZAndOnADirectionMatchTheClosedForm) {
  expectEnds("low=vshaft.M:z>6", "low", {0, 1}, 6);
  // The direction is taken of length 1 (tests/test_spatial_timing.cpp): through 0 at 225, 405.
  expectEnds("diag=vshaft.M:1,0,1>14.142135623730951", "diag", {M_SQRT1_2, M_SQRT1_2},
             14.142135623730951);
}

// The distance between two points in the world (the hook's point within 30 mm of the needle's):
// no closed form here, so against the changed designs (changeDimensions, every dimension of the
// machine in space, the window found again): central differences, to 1e-6 degree per unit. (It
// found changeDimensions placing the needle bar's point T, given along and across B->N, by its
// distances when B-N changed: they do not meet on the line.)
TEST(SpatialWindowSensitivity, ADistancesEndsMoveAsChangedDesignsDo) {
  const Mechanism m =
      test::exampleWithWindow("lockstitch-bevel", "near=hook.K:distance:needlebar.N<30");
  ASSERT_EQ(m.timing.windows.size(), 1u);
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const std::vector<Dimension> dims = dimensions(m);
  const WindowSensitivity s = windowSensitivity(k, "near", dims);
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  ASSERT_FALSE(s.intervals.empty());
  const double h = 1e-5;
  double peak = 0;
  for (size_t d = 0; d < dims.size(); ++d) {
    // A bevel's ratio changed, the shafts do not come back together after a turn: the changed
    // window wraps elsewhere (the closed form above holds the ratio's derivative).
    if (dims[d].ratioOf) continue;
    std::vector<CycleDiagram> sides;
    for (double step : {-h, h}) {
      Mechanism changed = m;
      std::vector<double> delta(dims.size(), 0.0);
      delta[d] = step;
      const Status st = changeDimensions(changed, dims, delta);
      ASSERT_TRUE(st.ok()) << dims[d].name << ": " << st.message;
      Kinematics kc;
      ASSERT_TRUE(kc.load(changed).ok()) << dims[d].name;
      sides.push_back(cycleDiagram(kc, changed.timing));
      ASSERT_TRUE(sides.back().status.ok()) << dims[d].name;
    }
    const auto& lo = sides[0].windows.at(0).intervals;
    const auto& hi = sides[1].windows.at(0).intervals;
    ASSERT_EQ(lo.size(), s.intervals.size());
    ASSERT_EQ(hi.size(), s.intervals.size());
    for (size_t i = 0; i < s.intervals.size(); ++i) {
      const double from = (hi[i].fromDeg - lo[i].fromDeg) / (2 * h);
      const double to = (hi[i].toDeg - lo[i].toDeg) / (2 * h);
      peak = std::max({peak, std::abs(from), std::abs(to)});
      EXPECT_NEAR(s.intervals[i].dFrom[d], from, 1e-6 * (1 + std::abs(from))) << dims[d].name;
      EXPECT_NEAR(s.intervals[i].dTo[d], to, 1e-6 * (1 + std::abs(to))) << dims[d].name;
    }
  }
  EXPECT_GT(peak, 0.1);
}

// A window's start on a machine in space as an optimize target: the vertical shaft's radius r
// that opens "z > 6" at 215 degrees, 180 + asin(6 / r) = 215, r = 6 / sin 35 degrees.
TEST(SpatialWindowSensitivity, AWindowsStartMetByTheRadius) {
  const Mechanism m = test::exampleWithWindow("lockstitch-bevel", "low=vshaft.M:z>6");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  OptimizeSpec spec;
  spec.variables = {{"vshaft.V-M", 8, 16}};
  OptTarget t;
  t.kind = OptTarget::Kind::Window;
  t.window = "low";
  t.windowEnd = false;
  t.crankDeg = 215;
  spec.targets = {t};
  spec.starts = 3;
  const OptimizeResult r = optimize(k, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_NEAR(r.after.at(0), 6 / std::sin(35 * M_PI / 180), 1e-7);
  EXPECT_NEAR(r.atAfter.measures.at(0).at(0), 215, 1e-7);
}

}  // namespace
}  // namespace linkage
