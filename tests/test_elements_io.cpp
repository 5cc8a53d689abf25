// The gear and the arc slot in files: round trips of the new fields, and every bad input refused
// with a message that names the place; what the editor makes is checked by the same rules.
#include <gtest/gtest.h>

#include <string>

#include "linkage/edits.h"
#include "linkage/elements.h"
#include "linkage/gear.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"

namespace linkage {
namespace {

// Two shafts on the ground coupled 2:1 by a belt, a planet on an arm around a fixed sun
// (carrier: the arm), and a block in an arc slot of the ground.
const std::string kGears = R"({
  "format": "linkage",
  "version": 1,
  "name": "gears and arcs",
  "bodies": [
    {"name": "ground", "ground": true, "points": {"U": [0, 0], "L": [0, -80], "S": [100, 0]},
     "slots": {"arc": [[30, -80], [60, -50], [90, -80]]}},
    {"name": "armshaft", "points": {"U": [0, 0], "K": [10, 0]}},
    {"name": "hook", "points": {"L": [0, -80], "H": [12, -80]}},
    {"name": "arm", "points": {"S": [100, 0], "B": [130, 0]}},
    {"name": "planet", "points": {"B": [130, 0], "P": [140, 0]}},
    {"name": "rod", "points": {"H": [12, -80], "Q": [60, -50]}},
    {"name": "block", "points": {"Q": [60, -50]}}
  ],
  "joints": [
    {"type": "pin", "a": "ground.U", "b": "armshaft.U"},
    {"type": "pin", "a": "ground.L", "b": "hook.L"},
    {"type": "gear", "a": "armshaft.U", "b": "hook.L", "ratio": 2},
    {"type": "gear", "a": "armshaft.U", "b": "arm.S", "ratio": -1},
    {"type": "pin", "a": "ground.S", "b": "arm.S"},
    {"type": "pin", "a": "arm.B", "b": "planet.B"},
    {"type": "gear", "a": "ground.S", "b": "planet.B", "ratio": -2, "carrier": "arm"},
    {"type": "pin", "a": "hook.H", "b": "rod.H"},
    {"type": "pin", "a": "rod.Q", "b": "block.Q"},
    {"type": "slider", "a": "block.Q", "slot": "ground.arc"}
  ],
  "driver": {"joint": 0, "rpm": 240, "direction": "ccw"},
  "outputs": {"points": ["block.Q"]}
})";

std::string replaceOnce(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "test bug: no " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::string refusedEdit(const std::string& from, const std::string& to) {
  const LoadResult r = parseMechanism(replaceOnce(kGears, from, to));
  EXPECT_FALSE(r.mechanism.has_value());
  return r.error;
}

TEST(ElementFiles, GearsAndArcsRoundTripAndSolve) {
  const LoadResult r = parseMechanism(kGears);
  ASSERT_TRUE(r.mechanism) << r.error;
  const Mechanism& m = *r.mechanism;
  ASSERT_EQ(m.joints[2].type, JointType::Gear);
  EXPECT_EQ(gearRatio(m.joints[2]), 2);
  EXPECT_FALSE(m.joints[2].carrier);  // the ground
  EXPECT_EQ(m.joints[6].carrier, m.bodyNamed("arm")->id);
  const Slot* arc = m.slotNamed(m.ground()->id, "arc");
  ASSERT_TRUE(arc && arc->mid);
  EXPECT_EQ(*arc->mid, Vec2(60, -50));
  const std::string text = serializeMechanism(m);
  const LoadResult again = parseMechanism(text);
  ASSERT_TRUE(again.mechanism) << again.error;
  EXPECT_EQ(mechanismDifference(m, *again.mechanism), "");
  EXPECT_EQ(serializeMechanism(*again.mechanism), text);
  EXPECT_NE(text.find(R"("carrier": "arm")"), std::string::npos) << text;
  EXPECT_NE(text.find(R"([[30, -80], [60, -50], [90, -80]])"), std::string::npos) << text;
  Kinematics k;
  const Status s = k.load(m);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_TRUE(k.closedForm());
  ASSERT_TRUE(k.moveTo(90).ok());
  EXPECT_NEAR(k.bodyAngle(m.bodyNamed("hook")->id), M_PI, 1e-12);
  EXPECT_NEAR(k.bodyAngle(m.bodyNamed("arm")->id), -M_PI / 2, 1e-12);
}

TEST(ElementFiles, BadGearsAndArcsAreRefusedNamingThePlace) {
  EXPECT_EQ(refusedEdit(R"("ratio": 2})", R"("ratio": 0})"),
            "joints[2].ratio: expected a finite number other than 0 (the speed of b relative to "
            "a)");
  EXPECT_EQ(refusedEdit(R"("ratio": 2})", R"("ratio": "2"})"),
            "joints[2].ratio: expected a number, got \"2\"");
  EXPECT_EQ(refusedEdit(R"("ratio": 2})", R"("ratio": 1e7})").substr(0, 47),
            "joints[2].ratio: a ratio beyond 1e6 (or below 1");
  EXPECT_EQ(refusedEdit(R"(, "ratio": 2})", "}"), "joints[2]: missing required field \"ratio\"");
  EXPECT_EQ(refusedEdit(R"("carrier": "arm")", R"("carrier": "arms")"),
            "joints[6].carrier: no body \"arms\"");
  EXPECT_EQ(refusedEdit(R"("carrier": "arm")", R"("carrier": "planet")"),
            "joints[6].a: \"ground.S\" is not where body \"ground\" is pinned to the carrier "
            "\"planet\": a gear's centres are its bodies' pivots on the carrier");
  // Without its carrier the planet's gear would turn the sun relative to the ground it is on.
  EXPECT_EQ(refusedEdit(R"(, "carrier": "arm")", ""),
            "joints[6].a: \"ground.S\" is on the carrier \"ground\" itself: a gear turns "
            "relative to its carrier");
  EXPECT_EQ(
      refusedEdit(R"("a": "armshaft.U", "b": "hook.L")", R"("a": "armshaft.K", "b": "hook.L")"),
      "joints[2].a: \"armshaft.K\" is not where body \"armshaft\" is pinned to the carrier "
      "\"ground\": a gear's centres are its bodies' pivots on the carrier");
  EXPECT_EQ(refusedEdit(R"("a": "armshaft.U", "b": "hook.L")", R"("a": "hook.H", "b": "hook.L")"),
            "joints[2]: both sides are on body \"hook\"");
  EXPECT_EQ(refusedEdit(R"("ratio": 2})", R"("ratio": 2, "slot": "ground.arc"})"),
            "joints[2].slot: a gear couples the bodies of points \"a\" and \"b\"; it has no slot");
  EXPECT_EQ(refusedEdit(R"({"type": "pin", "a": "ground.U", "b": "armshaft.U"})",
                        R"({"type": "pin", "a": "ground.U", "b": "armshaft.U", "ratio": 1})"),
            "joints[0].ratio: a pin joins points \"a\" and \"b\"; it has no \"ratio\"");
  EXPECT_EQ(refusedEdit("[[30, -80], [60, -50], [90, -80]]", "[[30, -80], [60, -80], [90, -80]]"),
            "bodies[0].slots.arc: its three points lie on one line: an arc needs them off it");
  EXPECT_EQ(refusedEdit("[[30, -80], [60, -50], [90, -80]]", "[[30, -80], [60, -50], [60, -50]]"),
            "bodies[0].slots.arc: two of the arc's three points coincide");
  EXPECT_EQ(refusedEdit(R"("driver": {"joint": 0)", R"("driver": {"joint": 2)"),
            "driver.joint: joints[2] is a gear, a driver needs a pin");
}

TEST(ElementFiles, TheEditorsCouplingsAndArcsFollowTheSameRules) {
  Mechanism m = *parseMechanism(kGears).mechanism;
  const BodyId armshaft = m.bodyNamed("armshaft")->id, hook = m.bodyNamed("hook")->id,
               rod = m.bodyNamed("rod")->id;
  std::string why;
  const JointId j = addCoupling(m, armshaft, hook, -3, &why);
  ASSERT_TRUE(j) << why;
  EXPECT_EQ(m.pointLabel(m.joint(j)->a), "armshaft.U");
  EXPECT_EQ(m.pointLabel(m.joint(j)->b), "hook.L");
  EXPECT_FALSE(m.joint(j)->carrier);
  EXPECT_EQ(checkJoints(m), "");
  // The rod turns about no pivot on a body the hook is pivoted on.
  EXPECT_FALSE(addCoupling(m, hook, rod, 2, &why));
  EXPECT_NE(why.find("not pivoted on one body"), std::string::npos) << why;
  // An arc slot from three points, none from three on a line.
  EXPECT_TRUE(addBodyArcSlot(m, rod, Vec2(0, 0), Vec2(5, 1), Vec2(10, 0)));
  EXPECT_FALSE(addBodyArcSlot(m, rod, Vec2(0, 0), Vec2(5, 0), Vec2(10, 0)));
  // A gear's ratio set to 0 in the editor is refused by compile with the place.
  setGearRatio(*m.joint(j), 0);
  EXPECT_EQ(checkJoints(m).substr(0, 16), "joints[10].ratio");
  Kinematics k;
  const Status s = k.load(m);
  EXPECT_EQ(s.code, StatusCode::BadModel);
  EXPECT_EQ(s.message.substr(0, 16), "joints[10].ratio") << s.message;
}

}  // namespace
}  // namespace linkage
