// A cam's reaction differentiated with respect to the dimensions (linkage/force_sensitivity.h):
// a translating follower (roller, knife edge) loaded by gravity and a load at its point, against
// its closed form (tests/cam_closed_form.h) over std::complex by the complex step. The cam
// pushes along the common normal, which runs through the follower's point R and the instant
// centre I of cam and follower (Aronhold-Kennedy; I on the line through the cam's centre O normal
// to the slot, where the cam's point moves as the follower: I - O = -perp(dR/dtheta)); the
// follower's balance along its slot fixes the push N. The reaction on the cam: -N n at O, its
// moment about O, and the contact force N.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "cam_closed_form.h"
#include "linkage/dynamics.h"
#include "linkage/force_sensitivity.h"
#include "reaction_checks.h"

namespace linkage {
namespace {

using test::C;
using test::CVec;
using test::kH;
using test::PV;
using test::Values;

constexpr double kKg = 0.2, kLoadY = -30, kGy = -9.81;

struct CamReaction {
  CVec force;  // on the cam, N
  C coupleNm, contactN;
};

CamReaction closedForm(const test::TranslatingForm& f, const Values& x, double omega) {
  const PV r = f.at(x);
  const CVec O{x.at("ground.O.x"), x.at("ground.O.y")}, d = f.along(x);
  const CVec I = O - perp(r.v), n0 = r.p - I;
  const CVec n = (C(1) / std::sqrt(dot(n0, n0))) * n0;
  // The follower does not turn: its centre of mass accelerates as R does (mm/s^2).
  const CVec a = C(omega * omega) * r.a, g{C(0), C(kGy * 1000)}, load{C(0), C(kLoadY)};
  const C N = dot(C(kKg / 1000) * (a - g) - load, d) / dot(n, d);
  const CVec F = C(-1) * N * n;
  return {F, cross(r.p - O, F) / C(1000), N};
}

void expectCamReaction(const test::TranslatingCam& spec) {
  test::TranslatingCam t = spec;
  t.followerMass = R"("mass": {"kg": 0.2, "com": [)" + test::num(t.e) + ", " +
                   test::num(t.by() + 20) + R"(], "j_kg_mm2": 30},)";
  t.extra = R"(, "gravity": [0, -9.81], "loads": [{"point": "follower.R", "force_N": [0, -30]}])";
  const Mechanism m = test::parsed(t.text());
  const test::TranslatingForm form = test::translatingForm(m, t);
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const std::vector<Dimension> dims = dimensions(m);
  const JointId cam = m.joints.back().id;
  std::vector<double> peak(dims.size(), 0), worst(dims.size(), 0);
  for (int deg = 0; deg < 360; deg += 5) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    const JointForceSensitivity s = jointForceSensitivity(k, cam, dims);
    ASSERT_TRUE(s.status.ok()) << s.status.message;
    Values v = form.values;
    v["theta"] = deg * test::kCamDeg;
    const CamReaction exact = closedForm(form, v, k.omega());
    const double size = 1 + std::abs(exact.contactN);
    ASSERT_NEAR(s.reaction.contactN, exact.contactN.real(), 1e-9 * size) << deg;
    ASSERT_NEAR(s.force.x(), exact.force.x.real(), 1e-9 * size) << deg;
    ASSERT_NEAR(s.force.y(), exact.force.y.real(), 1e-9 * size) << deg;
    ASSERT_NEAR(s.reaction.coupleNm, exact.coupleNm.real(), 1e-9 * size) << deg;
    for (size_t d = 0; d < dims.size(); ++d) {
      Values x = v;
      if (!dims[d].camRises.empty()) {
        for (size_t r = 0; r < dims[d].camRises.size(); ++r)
          x[form.pre + "h" + std::to_string(r)] += C(0, kH * dims[d].camRises[r]);
      } else {
        x.at(dims[d].name) += C(0, kH);
      }
      const CamReaction st = closedForm(form, x, k.omega());
      // The couple in N mm, to weigh as much as the forces.
      const Eigen::Vector4d want(st.force.x.imag(), st.force.y.imag(), 1000 * st.coupleNm.imag(),
                                 st.contactN.imag());
      const JointReaction& c = s.change[d];
      const Eigen::Vector4d got(c.force.x(), c.force.y(), 1000 * c.coupleNm, c.contactN);
      peak[d] = std::max(peak[d], want.norm() / kH);
      worst[d] = std::max(worst[d], (got - want / kH).norm());
    }
  }
  for (size_t d = 0; d < dims.size(); ++d) {
    std::printf("  %-32s worst %.2e of peak %.4g\n", dims[d].name.c_str(), worst[d], peak[d]);
    EXPECT_LE(worst[d], 1e-9 * std::max(peak[d], 1e-6)) << dims[d].name;
  }
}

// A roller follower offset to the right, and a knife edge offset to the left.
TEST(CamForceSensitivity, TranslatingFollowerMatchesItsClosedForm) {
  expectCamReaction(test::TranslatingCam{});
  test::TranslatingCam knife;
  knife.roller = 0;
  knife.e = -7;
  expectCamReaction(knife);
}

// The contact's change (cam::contactChange, derived by hand) against contact()'s central
// difference, for every follower kind, at a few random places and moves (a check of the
// derivation; the reactions' derivatives themselves are checked exactly above).
TEST(CamForceSensitivity, ContactChangeIsTheContactsDerivative) {
  std::srand(7);
  auto rnd = [] { return Vec2::Random(); };
  for (int kind = 0; kind < 5; ++kind) {
    cam::Follower f;
    f.oscillating = kind >= 3;
    f.flat = kind == 2 || kind == 4;
    f.sign = kind == 3 ? -1 : 1;
    for (int trial = 0; trial < 20; ++trial) {
      cam::Place at, move;
      at.centre = 10 * rnd(), at.b = at.centre + Vec2(5, 40) + 10 * rnd();
      at.pivot = at.b + Vec2(30, -5) + 5 * rnd();
      at.along = Vec2(0.2, 1).normalized() + 0.1 * rnd(), at.along.normalize();
      at.face = Vec2(-0.1, 1).normalized() + 0.1 * rnd(), at.face.normalize();
      move.centre = rnd(), move.b = rnd(), move.pivot = rnd();
      move.along = rnd().dot(perp(at.along)) * perp(at.along);  // unit vectors turn
      move.face = rnd().dot(perp(at.face)) * perp(at.face);
      const double sp = 4 * rnd().x(), dsp = rnd().x(), h = 1e-6;
      auto moved = [&](double t) {
        cam::Place p = at;
        p.centre += t * move.centre, p.b += t * move.b, p.pivot += t * move.pivot;
        p.along = (at.along + t * move.along).normalized();
        p.face = (at.face + t * move.face).normalized();
        return cam::contact(f, p, sp + t * dsp);
      };
      const cam::Contact plus = moved(h), minus = moved(-h);
      const cam::Contact d = cam::contactChange(f, at, move, sp, dsp);
      const Vec2 dp = (plus.point - minus.point) / (2 * h);
      const Vec2 dn = (plus.normal - minus.normal) / (2 * h);
      EXPECT_LT((d.point - dp).norm(), 1e-6 * (1 + dp.norm())) << kind << " " << trial;
      EXPECT_LT((d.normal - dn).norm(), 1e-6 * (1 + dn.norm())) << kind << " " << trial;
    }
  }
}

// Every joint's reaction on the followers without a closed form here (a flat face, an
// oscillating roller and flat face) against the changed designs' forces (tests/reaction_checks.h).
TEST(CamForceSensitivity, FlatAndOscillatingFollowersMoveAsChangedDesignsDo) {
  test::TranslatingCam roller;
  roller.followerMass = R"("mass": {"kg": 0.2, "com": [10, 50], "j_kg_mm2": 30},)";
  roller.extra =
      R"(, "gravity": [0, -9.81], "loads": [{"point": "follower.R", "force_N": [0, -30]}])";
  test::expectReactionsMoveAsChangedDesignsDo(test::parsed(roller.text()));
  test::TranslatingCam flat;
  flat.flat = true;
  flat.roller = 0;
  flat.followerMass = R"("mass": {"kg": 0.2, "com": [10, 50], "j_kg_mm2": 30},)";
  flat.extra =
      R"(, "gravity": [0, -9.81], "loads": [{"point": "follower.R", "force_N": [0, -30]}])";
  test::expectReactionsMoveAsChangedDesignsDo(test::parsed(flat.text()));
  for (const bool face : {false, true}) {
    test::OscillatingCam osc;
    osc.flat = face;
    if (face) osc.roller = 0;
    osc.extra = R"(, "loads": [{"point": "rocker.R", "force_N": [0, -30]}])";
    test::expectReactionsMoveAsChangedDesignsDo(test::parsed(osc.text()));
  }
}

}  // namespace
}  // namespace linkage
