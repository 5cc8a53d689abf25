// Mechanism files: every refusal the format promises (shared/specs/model-format.md), each with a
// message that names the place. Nothing may be half-loaded.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "linkage/io/model_file.h"

namespace linkage {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

// Text of a valid file; tests edit one detail with replaceOnce() to provoke one error.
const std::string kValid = R"({
  "format": "linkage",
  "version": 1,
  "bodies": [
    {"name": "ground", "ground": true, "points": {"A": [0, 0], "Q": [50, 0]}, "slots": {"D": [[0, 0], [0, -100]]}},
    {"name": "disk", "points": {"A": [0, 0], "P": [10, 0]}, "slots": {"B": [[10, -31], [10, 31]]}},
    {"name": "block", "points": {"E": [10, 5]}},
    {"name": "rod", "points": {"P": [10, 0], "G": [0, -40]}}
  ],
  "joints": [
    {"type": "pin", "a": "ground.A", "b": "disk.A"},
    {"type": "slider", "a": "block.E", "slot": "disk.B"},
    {"type": "pin", "a": "disk.P", "b": "rod.P"},
    {"type": "pin-in-slot", "a": "rod.G", "slot": "ground.D"}
  ],
  "driver": {"joint": 0, "rpm": 240, "direction": "cw"},
  "outputs": {"points": ["rod.G"]}
})";

std::string replaceOnce(std::string text, const std::string& from, const std::string& to) {
  size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "test bug: no " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// The error when `text` is refused; fails the test when it loads or is half-loaded.
std::string errorOf(const std::string& text) {
  LoadResult r = parseMechanism(text);
  EXPECT_FALSE(r.mechanism.has_value()) << "unexpectedly loaded:\n" << text;
  EXPECT_FALSE(r.error.empty());
  return r.error;
}

std::string refusedEdit(const std::string& from, const std::string& to) {
  return errorOf(replaceOnce(kValid, from, to));
}

TEST(ModelFileErrors, SyntaxErrorsGiveLineAndColumn) {
  std::string e = errorOf("{\n  \"format\": \"linkage\",\n    \"version\": 1 1\n}");
  EXPECT_THAT(e, StartsWith("line 3, column "));
  EXPECT_THAT(e, HasSubstr("syntax error"));
  EXPECT_THAT(errorOf(""), StartsWith("line 1, column 1: "));
  EXPECT_THAT(errorOf(kValid + " x"), HasSubstr("expected end of input"));
  EXPECT_THAT(errorOf("{\"format\": \"linkage\", // comment\n}"), StartsWith("line 1, column "));
}

TEST(ModelFileErrors, TopLevelMustBeAnObject) {
  EXPECT_EQ(errorOf("[1, 2]"), "top level: expected a JSON object {...}, got [1, 2]");
  EXPECT_EQ(errorOf("\"linkage\""), "top level: expected a JSON object {...}, got \"linkage\"");
}

TEST(ModelFileErrors, DuplicateKeysAreRefusedWherever) {
  EXPECT_EQ(refusedEdit(R"("E": [10, 5])", R"("E": [10, 5], "E": [1, 1])"),
            "bodies[2].points: duplicate key \"E\"");
  EXPECT_EQ(refusedEdit(R"("version": 1,)", R"("version": 1, "version": 1,)"),
            "top level: duplicate key \"version\"");
  EXPECT_EQ(refusedEdit(R"("rpm": 240)", R"("rpm": 240, "x": {"k": 1, "k": 2})"),
            "driver.x: duplicate key \"k\"");
}

TEST(ModelFileErrors, FormatAndVersion) {
  EXPECT_EQ(refusedEdit(R"("format": "linkage",)", ""),
            "top level: missing required field \"format\"");
  EXPECT_EQ(refusedEdit(R"("linkage")", R"("linkage2")"),
            "format: expected \"linkage\", got \"linkage2\"");
  EXPECT_EQ(refusedEdit(R"("version": 1)", R"("version": 2)"),
            "version: this file is version 2, newer than this program reads (version 1); a newer "
            "program wrote it");
  EXPECT_EQ(refusedEdit(R"("version": 1)", R"("version": 0)"),
            "version: expected the integer 1, got 0");
  EXPECT_EQ(refusedEdit(R"("version": 1)", R"("version": "1")"),
            "version: expected the integer 1, got \"1\"");
  EXPECT_EQ(refusedEdit(R"("version": 1)", R"("version": 1.0)"),
            "version: expected the integer 1, got 1.0");
  EXPECT_EQ(refusedEdit(R"("version": 1,)", ""), "top level: missing required field \"version\"");
}

TEST(ModelFileErrors, OptionalTopLevelFields) {
  EXPECT_EQ(refusedEdit(R"("version": 1,)", R"("version": 1, "name": 5,)"),
            "name: expected a string, got 5");
  EXPECT_EQ(refusedEdit(R"("version": 1,)", R"("version": 1, "units": {"length": "in"},)"),
            "units.length: expected \"mm\" (the only length unit), got \"in\"");
  EXPECT_EQ(refusedEdit(R"("version": 1,)", R"("version": 1, "units": "mm",)"),
            "units: expected an object {...}, got \"mm\"");
}

TEST(ModelFileErrors, Bodies) {
  std::string noBodies =
      kValid.substr(0, kValid.find("\"bodies\"")) + R"("bodies": [], "joints": []})";
  EXPECT_EQ(errorOf(noBodies), "bodies: expected a non-empty array of bodies, got an empty array");
  EXPECT_EQ(refusedEdit(R"({"name": "block", )", "{"),
            "bodies[2]: missing required field \"name\"");
  EXPECT_EQ(refusedEdit(R"("name": "block")", R"("name": "")"),
            "bodies[2].name: a body name may not be empty");
  EXPECT_EQ(refusedEdit(R"("name": "block")", R"("name": "bl.ock")"),
            "bodies[2].name: body names may not contain '.' (references are \"body.point\"): "
            "\"bl.ock\"");
  EXPECT_EQ(refusedEdit(R"("name": "block")", R"("name": "disk")"),
            "bodies[2].name: two bodies are named \"disk\"");
  EXPECT_EQ(refusedEdit(R"("name": "block", )", R"("name": "block", "ground": 1, )"),
            "bodies[2].ground: expected true or false, got 1");
  EXPECT_EQ(refusedEdit(R"(, "points": {"E": [10, 5]})", ""),
            "bodies[2]: missing required field \"points\"");
  EXPECT_EQ(refusedEdit(R"({"E": [10, 5]})", "[]"),
            "bodies[2].points: expected an object {...}, got an empty array");
}

TEST(ModelFileErrors, BodyNumbers) {
  EXPECT_EQ(refusedEdit(R"("name": "block", )", R"("name": "block", "number": 0, )"),
            "bodies[2].number: expected an integer >= 1, got 0");
  EXPECT_EQ(refusedEdit(R"("name": "block", )", R"("name": "block", "number": 2.5, )"),
            "bodies[2].number: expected an integer >= 1, got 2.5");
  std::string twice =
      replaceOnce(kValid, R"("name": "disk", )", R"("name": "disk", "number": 3, )");
  EXPECT_EQ(errorOf(replaceOnce(twice, R"("name": "rod", )", R"("name": "rod", "number": 3, )")),
            "bodies[3].number: 3 is already the number of body \"disk\"");
}

TEST(ModelFileErrors, PointsAndSlots) {
  const std::string expectedPair =
      "bodies[2].points.E: expected [x, y] (or [x, y, depth]) with finite numbers";
  EXPECT_EQ(refusedEdit("[10, 5]", "[10]"), expectedPair + ", got [10]");
  EXPECT_EQ(refusedEdit("[10, 5]", "[10, 5, 0, 1]"), expectedPair + ", got [10, 5, 0, 1]");
  EXPECT_EQ(refusedEdit("[10, 5]", R"([10, 5, "0"])"), expectedPair + ", got [10, 5, \"0\"]");
  EXPECT_EQ(refusedEdit("[10, 5]", R"(["10", 5])"), expectedPair + ", got [\"10\", 5]");
  EXPECT_EQ(refusedEdit("[10, 5]", "null"), expectedPair + ", got null");
  EXPECT_EQ(refusedEdit("[10, 5]", "[10, 1e999]"),
            "bodies[2].points.E[1]: 1e999 is not a finite number");
  EXPECT_EQ(refusedEdit(R"("E": [10, 5])", R"("E.1": [10, 5])"),
            "bodies[2].points[\"E.1\"]: point names may not contain '.' (references are "
            "\"body.point\"): \"E.1\"");
  EXPECT_EQ(refusedEdit(R"("E": [10, 5])", R"("": [10, 5])"),
            "bodies[2].points[\"\"]: a point name may not be empty");
  EXPECT_EQ(refusedEdit("[[10, -31], [10, 31]]", "[[10, -31], [10, -31]]"),
            "bodies[1].slots.B: zero-length slot");
  EXPECT_EQ(refusedEdit("[[10, -31], [10, 31]]", "[[1e6, -31], [1e6, -31.0000000000001]]"),
            "bodies[1].slots.B: zero-length slot");
  EXPECT_EQ(refusedEdit("[[10, -31], [10, 31]]", "[[10, -31], 5]"),
            "bodies[1].slots.B: expected [[x0, y0], [x1, y1]] (or an arc [[x0, y0], [xm, ym], [x1, "
            "y1]]) with finite numbers, got [[10, -31], 5]");
  // Tiny but real: well above rounding for coordinates this size.
  EXPECT_TRUE(parseMechanism(replaceOnce(kValid, "[[10, -31], [10, 31]]", "[[0, 0], [0, 1e-9]]"))
                  .mechanism);
}

TEST(ModelFileErrors, ExactlyOneGround) {
  EXPECT_EQ(refusedEdit(R"("ground": true, )", ""),
            "bodies: no body has \"ground\": true; exactly one must");
  std::string two = replaceOnce(kValid, R"("name": "rod", )", R"("name": "rod", "ground": true, )");
  EXPECT_EQ(errorOf(two),
            "bodies: exactly one body may have \"ground\": true, but \"ground\" (bodies[0]) and "
            "\"rod\" (bodies[3]) do");
  EXPECT_TRUE(parseMechanism(
                  replaceOnce(kValid, R"("name": "rod", )", R"("name": "rod", "ground": false, )"))
                  .mechanism);
}

TEST(ModelFileErrors, JointReferences) {
  EXPECT_EQ(refusedEdit(R"("type": "slider")", R"("type": "hinge")"),
            "joints[1].type: expected \"pin\", \"slider\", \"pin-in-slot\", \"gear\", "
            "\"ball-rod\" or \"cam\", got \"hinge\"");
  EXPECT_EQ(refusedEdit(R"("a": "ground.A")", R"("a": "X.A")"), "joints[0].a: no body \"X\"");
  EXPECT_EQ(refusedEdit(R"("b": "disk.A")", R"("b": "disk.Q")"),
            "joints[0].b: no point \"Q\" on body \"disk\"");
  EXPECT_EQ(refusedEdit(R"("a": "ground.A")", R"("a": "groundA")"),
            "joints[0].a: expected \"body.point\", got \"groundA\"");
  EXPECT_EQ(refusedEdit(R"("a": "ground.A")", R"("a": 3)"),
            "joints[0].a: expected a string, got 3");
  EXPECT_EQ(refusedEdit(R"("slot": "disk.B")", R"("slot": "disk.X")"),
            "joints[1].slot: no slot \"X\" on body \"disk\"");
  EXPECT_EQ(refusedEdit(R"("slot": "disk.B")", R"("slot": "disk.P")"),
            "joints[1].slot: no slot \"P\" on body \"disk\"");
  EXPECT_EQ(refusedEdit(R"(, "b": "disk.A")", ""), "joints[0]: missing required field \"b\"");
  EXPECT_EQ(refusedEdit(R"(, "slot": "ground.D")", ""),
            "joints[3]: missing required field \"slot\"");
  EXPECT_EQ(refusedEdit(R"("b": "disk.A")", R"("b": "disk.A", "slot": "disk.B")"),
            "joints[0].slot: a pin joins points \"a\" and \"b\"; it has no slot");
  EXPECT_EQ(refusedEdit(R"("slot": "disk.B")", R"("slot": "disk.B", "b": "disk.A")"),
            "joints[1].b: a slider joins point \"a\" to a \"slot\"; it has no point \"b\"");
  EXPECT_EQ(refusedEdit(R"("a": "disk.P", "b": "rod.P")", R"("a": "disk.P", "b": "disk.A")"),
            "joints[2]: both sides are on body \"disk\"");
  EXPECT_EQ(refusedEdit(R"("a": "block.E")", R"("a": "disk.P")"),
            "joints[1]: both sides are on body \"disk\"");
  EXPECT_EQ(refusedEdit(R"({"type": "pin", "a": "ground.A", "b": "disk.A"})", "[]"),
            "joints[0]: expected an object {...}, got an empty array");
}

TEST(ModelFileErrors, Driver) {
  EXPECT_EQ(refusedEdit(R"("joint": 0)", R"("joint": 1)"),
            "driver.joint: joints[1] is a slider, a driver needs a pin");
  EXPECT_EQ(refusedEdit(R"("joint": 0)", R"("joint": 3)"),
            "driver.joint: joints[3] is a pin-in-slot, a driver needs a pin");
  EXPECT_EQ(refusedEdit(R"("joint": 0)", R"("joint": 4)"),
            "driver.joint: 4 is not a joint index (joints are numbered 0 to 3)");
  EXPECT_EQ(refusedEdit(R"("joint": 0)", R"("joint": -1)"),
            "driver.joint: -1 is not a joint index (joints are numbered 0 to 3)");
  EXPECT_EQ(refusedEdit(R"("joint": 0)", R"("joint": "0")"),
            "driver.joint: expected a joint index (an integer), got \"0\"");
  EXPECT_EQ(refusedEdit(R"("rpm": 240)", R"("rpm": 0)"),
            "driver.rpm: expected a number > 0, got 0");
  EXPECT_EQ(refusedEdit(R"("rpm": 240)", R"("rpm": -5.5)"),
            "driver.rpm: expected a number > 0, got -5.5");
  EXPECT_EQ(refusedEdit(R"("rpm": 240)", R"("rpm": "fast")"),
            "driver.rpm: expected a number > 0, got \"fast\"");
  EXPECT_EQ(refusedEdit(R"("rpm": 240)", R"("rpm": 1e400)"),
            "driver.rpm: 1e400 is not a finite number");
  EXPECT_EQ(refusedEdit(R"(, "direction": "cw")", ""),
            "driver: missing required field \"direction\"");
  EXPECT_EQ(refusedEdit(R"("cw")", R"("left")"),
            "driver.direction: expected \"cw\" or \"ccw\", got \"left\"");
  EXPECT_EQ(refusedEdit(R"("cw")", R"("cw", "start_deg": [])"),
            "driver.start_deg: expected a number, got an empty array");
  EXPECT_EQ(refusedEdit(R"("driver": {)", R"("driver": 0, "x": {)"),
            "driver: expected an object {...}, got 0");
}

TEST(ModelFileErrors, OutputsAndJointsArray) {
  EXPECT_EQ(refusedEdit(R"(["rod.G"])", R"(["rod.G", "rod.Z"])"),
            "outputs.points[1]: no point \"Z\" on body \"rod\"");
  EXPECT_EQ(refusedEdit(R"(["rod.G"])", R"(["rod.G", "rod.G"])"),
            "outputs.points[1]: \"rod.G\" is listed twice");
  EXPECT_EQ(refusedEdit(R"(["rod.G"])", R"("rod.G")"),
            "outputs.points: expected an array of \"body.point\", got \"rod.G\"");
  std::string noJoints = kValid.substr(0, kValid.find("\"joints\"")) + "\"joints\": {}}";
  EXPECT_EQ(errorOf(noJoints), "joints: expected an array of joints, got an empty object");
}

TEST(ModelFileErrors, ExcessiveNestingIsRefusedByPlace) {
  std::string deep = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_THAT(
      errorOf(replaceOnce(kValid, R"("version": 1,)", "\"version\": 1, \"x\": " + deep + ",")),
      StartsWith("x[0][0][0]"));
  EXPECT_THAT(errorOf(deep), HasSubstr("nested deeper than 256 levels"));
}

}  // namespace
}  // namespace linkage
