// Sensitivities of machines in space (linkage/sensitivity.h, Space::World; docs/sensitivity.md,
// "In space"): the RSSR crank-rocker's rocker point against its closed form differentiated by
// complex step (the rocker's equation a cos psi + b sin psi = c solved by the half-angle formula
// over std::complex, polished by Newton's steps on it, each dimension stepped by i 1e-30), and
// Euler's theorem on every spatial example: scaling every length, the ground's coordinates and the
// planes' origins scales the machine in the world, so the lengths times their derivatives add up to
// each point's world position, velocity and acceleration.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <complex>
#include <cstdio>
#include <map>

#include "examples.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "linkage/sensitivity.h"
#include "linkage/space.h"
#include "rssr_closed_form.h"
#include "spatial_fixtures.h"

namespace linkage {
namespace {

using test::C3;
using test::im;
using test::re;
using test::RssrClosedForm;
using C = std::complex<double>;
constexpr double kH = test::kRssrH;

Mechanism rssr() {
  LoadResult r = parseMechanism(test::rssrText());
  EXPECT_TRUE(r.mechanism) << r.error;
  return r.mechanism ? *r.mechanism : Mechanism();
}

TEST(SpatialSensitivity, TheRssrsDimensionsAreNamedAsTheFileNamesThem) {
  const Mechanism m = rssr();
  std::vector<std::string> names;
  for (const Dimension& d : dimensions(m)) names.push_back(d.name);
  const std::vector<std::string> want{"ground.O.x",
                                      "ground.O.y",
                                      "ground.H.x",
                                      "ground.H.y",
                                      "crank.O-A",
                                      "rocker.H-C",
                                      "crank.A.depth",
                                      "rocker.C.depth",
                                      "ground.O.z",
                                      "ground.H.z",
                                      "ball-rod:crank.A.length",
                                      "planes.rocker.origin.x",
                                      "planes.rocker.origin.y",
                                      "planes.rocker.origin.z"};
  EXPECT_EQ(names, want);
}

// Every dimension's derivative of the rocker point's world position, velocity and acceleration
// (per radian of crank) over a turn, against the closed form's complex step; each relative to
// its peak over the turn (or, for one that moves nothing, the largest peak).
TEST(SpatialSensitivity, TheRssrRockerPointMatchesItsClosedFormByComplexStep) {
  const Mechanism m = rssr();
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const PointId point = *m.findPoint("rocker.C");
  const std::vector<Dimension> dims = dimensions(m);
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dims, Sensitivity::Space::World).ok());
  RssrClosedForm cf;
  for (const Dimension& d : dims) cf.v[d.name] = d.value;
  const size_t n = dims.size();
  std::vector<std::array<double, 3>> peak(n, {0, 0, 0}), err(n, {0, 0, 0});
  double psi = test::rssr::kPsi0, position = 0;
  for (int deg = 0; deg < 360; deg += 5) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    ASSERT_TRUE(s.at(k).ok()) << deg;
    const double phi = deg * M_PI / 180, w = k.omega();
    // The closed form itself first: its branch is the solver's (the point to 1e-9 mm).
    const std::array<C3, 3> at = cf.rocker(phi, psi);
    position = std::max(position, (re(at[0]) - k.motionInSpace(point).position).norm());
    psi = test::rockerNear(phi, psi, test::rssrRod()).psi;
    for (size_t d = 0; d < n; ++d) {
      RssrClosedForm stepped = cf;
      stepped.v[dims[d].name] += C(0, kH);
      const std::array<C3, 3> x = stepped.rocker(phi, psi);
      const int i = static_cast<int>(d);
      const Vec3 got[3] = {s.point3(k, point, i), s.velocity3(k, point, i) / w,
                           s.acceleration3(k, point, i) / (w * w)};
      for (int o = 0; o < 3; ++o) {
        peak[d][o] = std::max(peak[d][o], im(x[o]).norm());
        err[d][o] = std::max(err[d][o], (got[o] - im(x[o])).norm());
      }
    }
  }
  std::printf("  the closed form's point against the solver's: %.2e mm\n", position);
  EXPECT_LT(position, 1e-12);
  double any[3] = {0, 0, 0}, worst[3] = {0, 0, 0};
  for (size_t d = 0; d < n; ++d)
    for (int o = 0; o < 3; ++o) any[o] = std::max(any[o], peak[d][o]);
  for (size_t d = 0; d < n; ++d) {
    double rel[3];
    for (int o = 0; o < 3; ++o) {
      rel[o] = err[d][o] / (peak[d][o] > 1e-12 ? peak[d][o] : any[o]);
      worst[o] = std::max(worst[o], rel[o]);
    }
    std::printf("  %-26s peak %.3g  error/peak: position %.2e  velocity %.2e  acceleration %.2e\n",
                dims[d].name.c_str(), peak[d][0], rel[0], rel[1], rel[2]);
  }
  std::printf("  worst: position %.2e  velocity %.2e  acceleration %.2e\n", worst[0], worst[1],
              worst[2]);
  for (double e : worst) EXPECT_LT(e, 1e-12);  // the issue asks 1e-9
  // Every dimension moves the point, and so is tested, but four the closed form says move
  // nothing: the pivots' moves along their own shafts (the crank's O along z, the rocker's H
  // along x, its plane's normal) and the rocker plane's origin in the plane (the pin at H holds
  // the rocker where it is); those the solver's derivatives give as nothing too (above).
  const std::vector<std::string> still{"ground.O.z", "ground.H.x", "planes.rocker.origin.y",
                                       "planes.rocker.origin.z"};
  for (size_t d = 0; d < n; ++d) {
    const bool moves = std::find(still.begin(), still.end(), dims[d].name) == still.end();
    if (moves)
      EXPECT_GT(peak[d][0], 1e-3) << dims[d].name;
    else
      EXPECT_LT(peak[d][0], 1e-12) << dims[d].name;
  }
}

// Euler's theorem on the spatial examples: every dimension in mm (lengths, the ground's x, y, z,
// slots' offsets, depths, rods, planes' origins) times its derivative adds up to each point's
// world position, and likewise its velocity and acceleration per radian of crank.
TEST(SpatialSensitivity, ScalingTheWorldScalesEveryPointOfTheSpatialExamples) {
  std::vector<std::pair<std::string, Mechanism>> machines{{"rssr (test)", rssr()}};
  for (const char* name : {"rssr-crank-rocker", "overedge-machine", "lockstitch-bevel"})
    machines.push_back({name, test::example(name)});
  for (const auto& [name, m] : machines) {
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok()) << name;
    const std::vector<Dimension> dims = dimensions(m);
    Sensitivity s;
    ASSERT_TRUE(s.prepare(k, dims, Sensitivity::Space::World).ok()) << name;
    double worst = 0, size = 0;
    for (int deg = 0; deg < 360; deg += 15) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << name << " " << deg;
      ASSERT_TRUE(s.at(k).ok()) << name << " " << deg;
      const double w = k.omega();
      for (const Point& p : m.points) {
        Vec3 sum = Vec3::Zero(), sumV = Vec3::Zero(), sumA = Vec3::Zero();
        for (size_t d = 0; d < dims.size(); ++d)
          if (dims[d].unit == Dimension::Unit::Mm) {
            const int i = static_cast<int>(d);
            sum += dims[d].value * s.point3(k, p.id, i);
            sumV += dims[d].value * s.velocity3(k, p.id, i) / w;
            sumA += dims[d].value * s.acceleration3(k, p.id, i) / (w * w);
          }
        const Kinematics::PointMotion3 x = k.motionInSpace(p.id);
        const Vec3 v = x.velocity / w, a = x.acceleration / (w * w);
        worst = std::max({worst, (sum - x.position).norm(), (sumV - v).norm(), (sumA - a).norm()});
        size = std::max({size, x.position.norm(), v.norm(), a.norm()});
      }
    }
    std::printf("  %-20s scaling: worst error %.2e of %.4g mm (%zu dimensions)\n", name.c_str(),
                worst, size, dims.size());
    EXPECT_LT(worst, 1e-11 * size) << name;
  }
}

// Seed 004's overedge machine (planes, two ball rods, a ground slot in the rocker plane): its
// needle's derivatives at every degree of a turn, finite, none refused; the largest printed.
TEST(SpatialSensitivity, TheOveredgeMachinesNeedleIsDifferentiatedAllTurn) {
  const Mechanism m = test::example("overedge-machine");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const PointId N = *m.findPoint("needlearm.N");
  const std::vector<Dimension> dims = dimensions(m);
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dims, Sensitivity::Space::World).ok());
  std::vector<double> peak(dims.size(), 0);
  for (int deg = 0; deg < 360; ++deg) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    ASSERT_TRUE(s.at(k).ok()) << deg;
    for (size_t d = 0; d < dims.size(); ++d) {
      const int i = static_cast<int>(d);
      const Vec3 x[3] = {s.point3(k, N, i), s.velocity3(k, N, i), s.acceleration3(k, N, i)};
      for (const Vec3& v : x) ASSERT_TRUE(v.allFinite()) << dims[d].name << " " << deg;
      peak[d] = std::max(peak[d], x[0].norm());
    }
  }
  std::vector<size_t> order(dims.size());
  for (size_t d = 0; d < order.size(); ++d) order[d] = d;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return peak[a] > peak[b]; });
  for (size_t r = 0; r < 6; ++r)
    std::printf("  needlearm.N: %-26s largest |d position| %.4g mm per unit\n",
                dims[order[r]].name.c_str(), peak[order[r]]);
  EXPECT_GT(peak[order[0]], 0.1);
}

}  // namespace
}  // namespace linkage
