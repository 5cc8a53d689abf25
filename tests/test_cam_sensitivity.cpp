// A cam's dimensions in the sensitivities (linkage/sensitivity.h, issue 29): its rises and its
// base, and every other dimension through the cam's rows, against the followers' closed forms
// differentiated by complex step (each dimension stepped by i 1e-30; tests/test_sensitivity.cpp).
// A translating roller follower rides at s(theta) above where its slot's line meets the circle
// of base + roller about the cam's centre; an oscillating one is turned about its pivot from
// where its roller touches that circle by s(theta). The displacement s is written here from the
// laws' normalised shapes, linear in the rises, a rise typed taking the difference from the
// next segment moving the other way (the Cam dock's rule).
#include <gtest/gtest.h>

#include <algorithm>
#include <complex>
#include <map>

#include "cam_closed_form.h"
#include "cam_fixtures.h"
#include "complex_step.h"
#include "linkage/cam.h"
#include "linkage/cam_edits.h"
#include "linkage/cam_joint.h"
#include "linkage/dimension_change.h"
#include "linkage/guide.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "linkage/optimize.h"
#include "linkage/sensitivity.h"

namespace linkage {
namespace {

using test::C;
using test::CVec;
using test::kH;
using test::Law;
using test::law;
using test::parsed;
using test::PV;
using test::rot;
using test::segmentsOf;
using test::Values;
using test::withRises;
constexpr double kDeg = M_PI / 180;

// The dimension d stepped by i kH in the values (a rise with its partner, as the dimension's
// camRises say), and the closed form's imaginary parts: d(point), d(rate), d(second rate).
template <class F>
std::array<Vec2, 3> stepped(Values v, const Dimension& d, const std::string& pre, F closedForm) {
  if (!d.camRises.empty()) {
    for (size_t k = 0; k < d.camRises.size(); ++k)
      v[pre + "h" + std::to_string(k)] += C(0, kH * d.camRises[k]);
  } else {
    EXPECT_TRUE(v.count(d.name)) << d.name;
    v[d.name] += C(0, kH);
  }
  const PV x = closedForm(v);
  auto im = [](const CVec& c) -> Vec2 { return Vec2(c.x.imag(), c.y.imag()) / kH; };
  return {im(x.p), im(x.v), im(x.a)};
}

// Each dimension's derivative of the follower's point from the solver against the closed form's,
// every 5 degrees, to 1e-9 of the dimension's peak (each of the three).
template <class F>
void expectMatches(const Mechanism& m, const char* point, const Values& values,
                   const std::string& pre, F closedForm, size_t dimensionsExpected) {
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const std::vector<Dimension> dims = dimensions(m);
  ASSERT_EQ(dims.size(), dimensionsExpected);
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dims).ok());
  const PointId R = *m.findPoint(point);
  const double w = k.omega();
  std::vector<std::array<double, 3>> peak(dims.size()), worst(dims.size());
  for (int deg = 0; deg < 360; deg += 5) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    ASSERT_TRUE(s.at(k).ok()) << deg;
    Values v = values;
    v["theta"] = deg * kDeg;
    for (size_t d = 0; d < dims.size(); ++d) {
      const std::array<Vec2, 3> want = stepped(v, dims[d], pre, closedForm);
      const int i = static_cast<int>(d);
      const Vec2 got[3] = {s.point(k, R, i), s.velocity(k, R, i) / w,
                           s.acceleration(k, R, i) / (w * w)};
      for (int o = 0; o < 3; ++o) {
        peak[d][o] = std::max(peak[d][o], want[o].norm());
        worst[d][o] = std::max(worst[d][o], (got[o] - want[o]).norm());
      }
    }
  }
  for (size_t d = 0; d < dims.size(); ++d)
    for (int o = 0; o < 3; ++o) {
      std::printf("  %-32s %d: worst %.2e of peak %.4g\n", dims[d].name.c_str(), o, worst[d][o],
                  peak[d][o]);
      EXPECT_LE(worst[d][o], 1e-9 * std::max(peak[d][o], 1e-12)) << dims[d].name << " " << o;
    }
}

// A translating follower (tests/cam_fixtures.h), offset, its slot turned about its first end
// (angle) and moved along its normal (offset): R where the slot's line meets the circle of
// base + roller about O (a flat face: at base along the slot from the foot of O), then s along
// the line.
void expectTranslating(const test::TranslatingCam& spec, size_t dimensionsExpected) {
  const Mechanism m = parsed(spec.text());
  const test::TranslatingForm form = test::translatingForm(m, spec);
  // The offset and angle are the slot's values as drawn, not 0: only their steps matter here.
  expectMatches(m, "follower.R", form.values, form.pre, form.at, dimensionsExpected);
}

// Roller (8 dimensions: its roller one), knife edge (offset the other way) and flat face.
TEST(CamSensitivity, TranslatingFollowerMatchesItsClosedForm) {
  expectTranslating(test::TranslatingCam{}, 8);
  test::TranslatingCam knife;
  knife.roller = 0;
  knife.e = -7;
  expectTranslating(knife, 7);
  test::TranslatingCam flat;
  flat.flat = true;
  flat.roller = 0;
  expectTranslating(flat, 7);
}

// An oscillating follower (tests/cam_fixtures.h): the rocker's arm P->R of length l as drawn,
// turned by t0 onto the circle of base + roller (a flat face: base) about O (Newton's method over
// the complex numbers from 0, the drawing's own turn) and by sign s(theta) beyond.
void expectOscillating(const test::OscillatingCam& spec, size_t dimensionsExpected) {
  const Mechanism m = parsed(spec.text());
  const std::vector<cam::Segment> segs = segmentsOf(m);
  const Vec2 R0 = m.point(*m.findPoint("rocker.R"))->pos, P = Vec2(spec.px, spec.py);
  const double sign = cross(R0 - P, R0) > 0 ? 1 : -1;
  const Vec2 e = (R0 - P).normalized();
  const std::string pre = "cam:rocker.R.";
  Values v = withRises({{"ground.O.x", 0},
                        {"ground.O.y", 0},
                        {"ground.P.x", P.x()},
                        {"ground.P.y", P.y()},
                        {"rocker.P-R", (R0 - P).norm()},
                        {pre + "base", spec.base},
                        {pre + "roller", spec.roller}},
                       segs, pre);
  auto closedForm = [&](const Values& x) -> PV {
    const CVec O{x.at("ground.O.x"), x.at("ground.O.y")};
    const CVec Pc{x.at("ground.P.x"), x.at("ground.P.y")};
    const CVec q = x.at("rocker.P-R") * CVec{e.x(), e.y()};
    const C r = x.at(pre + "base") + x.at(pre + "roller");
    C t = 0;
    for (int it = 0; it < 8; ++it) {
      const CVec b = Pc + rot(t, q) - O;
      t -= (dot(b, b) - r * r) / (2.0 * dot(b, perp(rot(t, q))));
    }
    std::vector<C> h(segs.size());
    for (size_t k = 0; k < h.size(); ++k) h[k] = x.at(pre + "h" + std::to_string(k));
    const Law s = law(segs, h, kDeg, x.at("theta").real());
    const CVec arm = rot(t + sign * s.s, q);
    return {Pc + arm, sign * s.v * perp(arm), sign * s.a * perp(arm) - s.v * s.v * arm};
  };
  expectMatches(m, "rocker.R", v, pre, closedForm, dimensionsExpected);
}

// Roller (9 dimensions: its roller one) and flat face.
TEST(CamSensitivity, OscillatingFollowerMatchesItsClosedForm) {
  expectOscillating(test::OscillatingCam{}, 9);
  test::OscillatingCam flat;
  flat.flat = true;
  flat.roller = 0;
  expectOscillating(flat, 8);
}

// Finite changes (linkage/dimension_change.h): the translating follower with its first rise
// 0.5 mm higher (its fall 0.5 mm deeper), its base 2 mm and its roller 1 mm larger rides at
// sqrt((base + roller)^2 - e^2) + s(theta) of the new programme, exactly; the file says so.
TEST(CamSensitivity, ChangedRisesBaseAndRollerAreTheClosedForm) {
  test::TranslatingCam spec;
  Mechanism m = parsed(spec.text());
  const std::vector<Dimension> dims = dimensions(m);
  std::vector<double> delta(dims.size(), 0.0);
  for (size_t d = 0; d < dims.size(); ++d) {
    if (dims[d].name == "cam:follower.R.segment1.rise") delta[d] = 0.5;
    if (dims[d].name == "cam:follower.R.base") delta[d] = 2;
    if (dims[d].name == "cam:follower.R.roller") delta[d] = 1;
  }
  ASSERT_TRUE(changeDimensions(m, dims, delta).ok());
  const std::optional<CamJoint> c = camJoint(m, m.joints.back());
  ASSERT_TRUE(c);
  EXPECT_EQ(c->kind.base, 32);
  EXPECT_EQ(c->kind.roller, 9);
  const std::vector<cam::Segment> segs = c->program.segments();
  ASSERT_EQ(segs.size(), 4u);
  EXPECT_EQ(segs[0].rise, 10.5);
  EXPECT_EQ(segs[2].rise, -10.5);
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const PointId R = *m.findPoint("follower.R");
  const double by = std::sqrt(41.0 * 41.0 - spec.e * spec.e);
  const std::vector<C> h = {10.5, 0, -10.5, 0};
  for (int deg = 0; deg < 360; deg += 5) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    const double s = law(segs, h, 1, deg * kDeg).s.real();
    EXPECT_NEAR(k.position(R).x(), spec.e, 1e-9 * 50) << deg;
    EXPECT_NEAR(k.position(R).y(), by + s, 1e-9 * 50) << deg;
  }
}

// Each dimension of m changed by h (changeDimensions) and solved: the point's move over h
// against its derivative, every 30 degrees.
void expectFiniteChangesAgree(const Mechanism& m, const char* point) {
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const std::vector<Dimension> dims = dimensions(m);
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dims).ok());
  const PointId R = *m.findPoint(point);
  const double h = 1e-4;
  for (size_t d = 0; d < dims.size(); ++d) {
    Mechanism changed = m;
    std::vector<double> delta(dims.size(), 0.0);
    delta[d] = h;
    ASSERT_TRUE(changeDimensions(changed, dims, delta).ok()) << dims[d].name;
    Kinematics kc;
    ASSERT_TRUE(kc.load(changed).ok()) << dims[d].name;
    for (int deg = 0; deg < 360; deg += 30) {
      ASSERT_TRUE(k.moveTo(deg).ok() && kc.moveTo(deg).ok() && s.at(k).ok());
      const Vec2 moved = (kc.position(R) - k.position(R)) / h;
      EXPECT_LT((moved - s.point(k, R, static_cast<int>(d))).norm(), 1e-3) << dims[d].name;
    }
  }
}

// setDimension of a rise is the rise typed in the Cam dock (withCamRise: the next segment
// moving the other way takes the difference), for the translating and the oscillating
// follower's first rise.
TEST(CamSensitivity, SetDimensionOfARiseIsTheRiseTypedInTheDock) {
  for (bool oscillating : {false, true}) {
    Mechanism m =
        parsed(oscillating ? test::OscillatingCam{}.text() : test::TranslatingCam{}.text());
    const std::string name =
        std::string("cam:") + (oscillating ? "rocker.R" : "follower.R") + ".segment1.rise";
    std::vector<cam::Segment> typed = camJoint(m, m.joints.back())->program.segments();
    const double rise = typed[0].rise + 1.5;
    ASSERT_TRUE(withCamRise(typed, 0, rise));
    ASSERT_TRUE(setDimension(m, name, rise).ok()) << name;
    EXPECT_EQ(camJoint(m, m.joints.back())->program.segments(), typed) << name;
    EXPECT_EQ(typed[2].rise, -rise) << name;  // the fall, by hand
    // A fall is a negative rise: set as one (optimize's setDimension takes it, not as a length
    // that must stay positive).
    bool fell = false;
    for (const Dimension& d : dimensions(m))
      if (d.camOf && d.value < 0) {
        Mechanism again = m;
        ASSERT_TRUE(setDimension(again, d.name, d.value - 0.5).ok()) << d.name;
        for (const Dimension& e : dimensions(again))
          if (e.name == d.name) EXPECT_NEAR(e.value, d.value - 0.5, 1e-12) << d.name;
        fell = true;
      }
    EXPECT_TRUE(fell) << "a fall among the dimensions";
  }
}

// A finite change of each dimension of both followers (the cam's own and the others, which put
// the follower back on its lowest position) moves the roller as its derivative says, to O(h).
TEST(CamSensitivity, FiniteChangesMoveTheFollowerAsTheDerivativesSay) {
  for (bool oscillating : {false, true}) {
    const Mechanism m =
        parsed(oscillating ? test::OscillatingCam{}.text() : test::TranslatingCam{}.text());
    expectFiniteChangesAgree(m, oscillating ? "rocker.R" : "follower.R");
  }
}

}  // namespace
}  // namespace linkage
