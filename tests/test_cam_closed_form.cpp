// A cam's follower in the closed-form plan (kinematics/closed_form.h, group "cam"): placed from
// its guide and its cam with no iteration. Checked step for step over two turns against the
// general Newton solve of the same rows, and against the programme itself (s, omega s',
// omega^2 s'' of linkage/cam.h), for the cam example and every follower of tests/cam_fixtures.h
// (roller, knife edge and flat face; translating and oscillating; either driver direction),
// and with a further dyad driven by the follower.
#include <gtest/gtest.h>

#include <cmath>

#include "cam_fixtures.h"
#include "examples.h"
#include "linkage/cam_joint.h"
#include "linkage/elements.h"
#include "linkage/groups.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"

namespace linkage {
namespace {

constexpr double kDeg = M_PI / 180;

Mechanism parsed(const std::string& text) {
  LoadResult r = parseMechanism(text);
  EXPECT_TRUE(r.mechanism) << r.error;
  return r.mechanism ? std::move(*r.mechanism) : Mechanism{};
}

Kinematics make(const Mechanism& m, bool closedForm) {
  KinematicsOptions o;
  o.closedForm = closedForm;
  Kinematics k(o);
  const Status s = k.load(m);
  EXPECT_TRUE(s.ok()) << s.message;
  return k;
}

int groupsOfKind(const Mechanism& m, GroupKind kind) {
  int n = 0;
  for (const AssurGroup& g : decomposeAssur(m).groups) n += g.kind == kind;
  return n;
}

// The follower's displacement and its rates by time as the programme gives them at driver
// angle deg: translating, along the slot from the drawn b (and nothing across it); oscillating,
// the rocker's turn.
void expectProgramme(const Mechanism& m, const Kinematics& k, double deg, const char* name) {
  const Joint* cam = nullptr;
  for (const Joint& j : m.joints)
    if (std::string(toString(j.type)) == "cam") cam = &j;
  ASSERT_TRUE(cam) << name;
  const std::optional<CamJoint> c = camJoint(m, *cam);
  ASSERT_TRUE(c) << name;
  const double w = k.omega(), sigma = m.driver->direction == Direction::Cw ? -1 : 1;
  const cam::Displacement d = c->program.at(sigma * deg * kDeg);
  if (c->kind.oscillating) {
    const double sg = c->kind.sign;
    EXPECT_NEAR(k.bodyAngle(c->follower), sg * d.s, 1e-12) << name << " at " << deg;
    EXPECT_NEAR(k.bodyOmega(c->follower), sg * sigma * w * d.v, 1e-10 * w) << name << deg;
    EXPECT_NEAR(k.bodyAlpha(c->follower), sg * w * w * d.a, 1e-10 * w * w) << name << deg;
    return;
  }
  const Kinematics::PointMotion p = k.motion(cam->b);
  const Vec2 u = c->drawn.along, across = perp(u);
  EXPECT_NEAR((p.position - c->drawn.b).dot(u), d.s, 1e-10) << name << " at " << deg;
  EXPECT_NEAR((p.position - c->drawn.b).dot(across), 0, 1e-10) << name << " at " << deg;
  EXPECT_NEAR(p.velocity.dot(u), sigma * w * d.v, 1e-10 * w) << name << " at " << deg;
  EXPECT_NEAR(p.velocity.dot(across), 0, 1e-10 * w) << name << " at " << deg;
  EXPECT_NEAR(p.acceleration.dot(u), w * w * d.a, 1e-10 * w * w) << name << " at " << deg;
  EXPECT_NEAR(p.acceleration.dot(across), 0, 1e-10 * w * w) << name << " at " << deg;
}

// Two turns a degree a step by the plan and by the general solve: the same coordinates to
// 1e-10 mm (and radian), rates to 1e-9 of their size, and (a cam turned by the driver on a
// guide at rest) the programme's motion.
void expectSameAsGeneral(const Mechanism& m, const char* name, bool programme = true) {
  EXPECT_EQ(groupsOfKind(m, GroupKind::Cam), 1) << name;
  EXPECT_EQ(groupsOfKind(m, GroupKind::Other), 0) << name;
  Kinematics fast = make(m, true), slow = make(m, false);
  ASSERT_TRUE(fast.closedForm()) << name;
  ASSERT_FALSE(slow.closedForm()) << name;
  for (double deg = 0; deg <= 720; deg += 1) {
    ASSERT_TRUE(fast.moveTo(deg).ok()) << name << " at " << deg;
    ASSERT_TRUE(slow.moveTo(deg).ok()) << name << " at " << deg;
    EXPECT_LT((fast.q() - slow.q()).cwiseAbs().maxCoeff(), 1e-10) << name << " at " << deg;
    EXPECT_LT((fast.dq() - slow.dq()).cwiseAbs().maxCoeff(), 1e-9 * (1 + slow.dq().norm()))
        << name << " at " << deg;
    EXPECT_LT((fast.ddq() - slow.ddq()).cwiseAbs().maxCoeff(), 1e-9 * (1 + slow.ddq().norm()))
        << name << " at " << deg;
    if (programme) {
      expectProgramme(m, fast, deg, name);
      expectProgramme(m, slow, deg, name);
    }
  }
}

TEST(CamClosedForm, TheCamExampleIsSolvedGroupByGroupAsTheGeneralSolveDoes) {
  expectSameAsGeneral(test::example("cam-translating-roller"), "cam-translating-roller");
}

TEST(CamClosedForm, TranslatingFollowersAreSolvedGroupByGroupAsTheGeneralSolveDoes) {
  test::TranslatingCam roller, knife, flat, cw;
  knife.roller = 0;
  knife.e = -7;
  flat.flat = true;
  flat.e = 4;
  flat.motion = R"([{"to_deg": 100, "rise_mm": 12, "law": "modified-trapezoid"},
                    {"to_deg": 260, "rise_mm": -12, "law": "harmonic"}, {"to_deg": 360}])";
  cw.direction = "cw";
  expectSameAsGeneral(parsed(roller.text()), "roller");
  expectSameAsGeneral(parsed(knife.text()), "knife edge");
  expectSameAsGeneral(parsed(flat.text()), "flat face");
  expectSameAsGeneral(parsed(cw.text()), "clockwise");
}

TEST(CamClosedForm, OscillatingFollowersAreSolvedGroupByGroupAsTheGeneralSolveDoes) {
  // A rise turns the rocker clockwise (pivot at (60, 0)) or counter-clockwise (at (-60, 0)).
  test::OscillatingCam roller, knife, flat, cw;
  knife.roller = 0;
  flat.flat = true;
  cw.px = -60;
  cw.direction = "cw";
  expectSameAsGeneral(parsed(roller.text()), "rocker, roller");
  expectSameAsGeneral(parsed(knife.text()), "rocker, knife edge");
  expectSameAsGeneral(parsed(flat.text()), "rocker, flat face");
  expectSameAsGeneral(parsed(cw.text()), "rocker, clockwise");
}

// Edits of a cam mechanism as the plan follows them: the follower's output point moved (its
// frame moves: solved again in place, group by group), then the programme's rises (8 -> 6 mm),
// each as a fresh load of the edited design has it.
void expectAsLoaded(Kinematics& k, const Mechanism& edited, double deg, const PointId& p) {
  ASSERT_TRUE(k.edit(edited).ok());
  EXPECT_TRUE(k.closedForm());
  Kinematics fresh = make(edited, true);
  ASSERT_TRUE(fresh.moveTo(deg).ok());
  EXPECT_LT((k.position(p) - fresh.position(p)).norm(), 1e-10);
  EXPECT_LT((k.velocity(p) - fresh.velocity(p)).norm(), 1e-9 * fresh.velocity(p).norm());
  EXPECT_LT((k.acceleration(p) - fresh.acceleration(p)).norm(),
            1e-9 * fresh.acceleration(p).norm());
}

TEST(CamClosedForm, EditsAreFollowedAsAFreshLoadHasThem) {
  const Mechanism m = test::example("cam-translating-roller");
  Kinematics k = make(m, true);
  ASSERT_TRUE(k.moveTo(50).ok());
  const PointId T = *m.findPoint("follower.T");
  Mechanism edited = m;
  edited.point(T)->pos += Vec2(5, 10);
  expectAsLoaded(k, edited, 50, T);
  EXPECT_EQ(k.lastEditGroups(), 1);  // the follower alone
  const Vec2 before = k.position(T);
  Joint& cam = edited.joints.back();
  ASSERT_EQ(std::string(toString(cam.type)), "cam");
  for (Record& r : cam.records.at(0))
    for (RecordMember& x : r)
      if (x.key == "rise_mm") x.value = std::get<double>(x.value) * 0.75;
  expectAsLoaded(k, edited, 50, T);
  EXPECT_GT((k.position(T) - before).norm(), 0.5);  // it did move
}

// A cam on a moving guide: the rocker of a crank-rocker four-bar (crank 20 from (0, 0), coupler
// 100, rocker 60 from (100, 0) up to (100, 60)) carries the cam, pinned to it at A = (100, 30)
// and turned by a gear to the ground on the rocker as carrier (theta = 6 times the rocker's
// turn, its rate and acceleration far from constant), and the follower: a block in a slot of
// the rocker (offset 3 mm) or a rocker pinned to it at (130, 30).
std::string camOnRocker(bool oscillating) {
  const double base = 10, roller = 4, e = 3, reach = base + roller;
  const std::string b = oscillating ? "[100, 44]"
                                    : "[" + test::num(100 + std::sqrt(reach * reach - e * e)) +
                                          ", " + test::num(30 + e) + "]";
  const std::string follower =
      oscillating ? R"({"name": "follower", "points": {"P": [130, 30], "R": )" + b + "}}"
                  : R"({"name": "follower", "points": {"R": )" + b + "}}";
  const std::string own = oscillating
                              ? R"({"type": "pin", "a": "rocker.P", "b": "follower.P"})"
                              : R"({"type": "slider", "a": "follower.R", "slot": "rocker.guide"})";
  const std::string motion =
      oscillating ? R"([{"to_deg": 120, "rise_deg": 15, "law": "modified-sine"}, {"to_deg": 180},
               {"to_deg": 300, "rise_deg": -15, "law": "polynomial-4567"}, {"to_deg": 360}])"
                  : R"([{"to_deg": 90, "rise_mm": 5, "law": "cycloidal"}, {"to_deg": 150},
               {"to_deg": 270, "rise_mm": -5, "law": "polynomial-345"}, {"to_deg": 360}])";
  return R"({"format": "linkage", "version": 1, "name": "cam on a rocker",
    "bodies": [
      {"name": "ground", "ground": true, "points": {"O2": [0, 0], "O4": [100, 0]}},
      {"name": "crank", "points": {"O2": [0, 0], "C": [20, 0]}},
      {"name": "coupler", "points": {"C": [20, 0], "B": [100, 60]}},
      {"name": "rocker", "points": {"O4": [100, 0], "B": [100, 60], "A": [100, 30],
                                    "P": [130, 30]},
       "slots": {"guide": [[105, 33], [140, 33]]}},
      {"name": "cam", "points": {"A": [100, 30]}},
      )" +
         follower + R"(
    ],
    "joints": [
      {"type": "pin", "a": "ground.O2", "b": "crank.O2"},
      {"type": "pin", "a": "crank.C", "b": "coupler.C"},
      {"type": "pin", "a": "coupler.B", "b": "rocker.B"},
      {"type": "pin", "a": "ground.O4", "b": "rocker.O4"},
      {"type": "pin", "a": "rocker.A", "b": "cam.A"},
      {"type": "gear", "a": "ground.O4", "b": "cam.A", "ratio": -6, "carrier": "rocker"},
      )" +
         own + R"(,
      {"type": "cam", "a": "cam.A", "b": "follower.R", "base_mm": 10, "roller_mm": 4,
       "motion": )" +
         motion + R"(}
    ],
    "driver": {"joint": 0, "rpm": 100, "direction": "ccw"}})";
}

// The guide turning with a rate and acceleration of its own: the terms in w_G and alpha_G of
// the follower's rates, and the cam's theta'' (not constant here).
TEST(CamClosedForm, ACamOnAMovingGuideIsSolvedGroupByGroupAsTheGeneralSolveDoes) {
  for (bool oscillating : {false, true}) {
    const std::string text = camOnRocker(oscillating);
    const Mechanism m = parsed(text);
    ASSERT_EQ(m.bodies.size(), 6u) << text;
    const AssurDecomposition d = decomposeAssur(m);
    ASSERT_EQ(d.groups.size(), 4u);
    EXPECT_EQ(d.groups[2].kind, GroupKind::Geared);
    EXPECT_EQ(d.groups[3].kind, GroupKind::Cam);
    expectSameAsGeneral(m, oscillating ? "oscillating, on a rocker" : "translating, on a rocker",
                        false);
  }
}

// The rocker follower of cam_fixtures.h driving a link and a block in a horizontal ground slot
// (rocker.Q at (60, 40), the link 50 mm to the block at (110, 40)): crank, cam, RRP.
std::string rockerWithSlider() {
  test::OscillatingCam spec;
  std::string text = spec.text();
  auto replace = [&](const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace(R"("P": [60, 0]}},)",
          R"("P": [60, 0]}, "slots": {"way": [[80, 40], [160, 40]]}},
             {"name": "link", "points": {"Q": [60, 40], "S": [110, 40]}},
             {"name": "block", "points": {"S": [110, 40]}},)");
  replace(R"("R": )", R"("Q": [60, 40], "R": )");
  // After the cam (the driver is joint 0): the end of the joints' list.
  const size_t end = text.rfind(']', text.find("\"driver\""));
  text.insert(end, R"(, {"type": "pin", "a": "rocker.Q", "b": "link.Q"},
             {"type": "pin", "a": "link.S", "b": "block.S"},
             {"type": "slider", "a": "block.S", "slot": "ground.way"})");
  return text;
}

TEST(CamClosedForm, AFollowerDrivingAFurtherDyadStillClosesGroupByGroup) {
  const std::string text = rockerWithSlider();
  const Mechanism m = parsed(text);
  ASSERT_EQ(m.bodies.size(), 5u) << text;
  const AssurDecomposition d = decomposeAssur(m);
  ASSERT_EQ(d.groups.size(), 3u);
  EXPECT_EQ(d.groups[0].kind, GroupKind::Crank);
  EXPECT_EQ(d.groups[1].kind, GroupKind::Cam);
  EXPECT_EQ(d.groups[2].kind, GroupKind::RRP);
  expectSameAsGeneral(m, "rocker driving a slider");
  // The block moves with the rocker: Q swings about P by the rocker's turn.
  Kinematics k = make(m, true);
  const PointId S = *m.findPoint("block.S");
  double low = 1e9, high = -1e9;
  for (double deg = 0; deg < 360; deg += 5) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    low = std::min(low, k.position(S).x());
    high = std::max(high, k.position(S).x());
  }
  EXPECT_GT(high - low, 5.0);
}

}  // namespace
}  // namespace linkage
