// The cam joint in files (../shared/specs/model-format.md, "Cams"): its fields round trip byte
// for byte through the generic structured field (the motion's records as written, a key this
// program does not read included), and every bad input is refused naming its place:
// `joints[k].field` or `joints[k].motion[m].field`; the command line exits 2 with it.
#include <gtest/gtest.h>

#include <string>

#include "cam_fixtures.h"
#include "cli_harness.h"
#include "linkage/cam_joint.h"
#include "linkage/elements.h"
#include "linkage/io/model_file.h"

namespace linkage {
namespace {

std::string replaceOnce(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "test bug: no " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::string refused(const std::string& text) {
  const LoadResult r = parseMechanism(text);
  EXPECT_FALSE(r.mechanism.has_value());
  return r.error;
}

std::string translating(const std::string& from, const std::string& to) {
  return refused(replaceOnce(test::TranslatingCam{}.text(), from, to));
}

void expectRoundTrip(const std::string& text) {
  const LoadResult r = parseMechanism(text);
  ASSERT_TRUE(r.mechanism) << r.error;
  const std::string saved = serializeMechanism(*r.mechanism);
  const LoadResult again = parseMechanism(saved);
  ASSERT_TRUE(again.mechanism) << again.error;
  EXPECT_EQ(mechanismDifference(*r.mechanism, *again.mechanism), "");
  EXPECT_EQ(serializeMechanism(*again.mechanism), saved);
}

TEST(CamFile, FieldsRoundTripByteForByte) {
  test::TranslatingCam roller;
  roller.motion = R"([{"to_deg": 90, "rise_mm": 10, "law": "cycloidal", "note": "lift"},
                      {"to_deg": 150}, {"law": "polynomial-345", "rise_mm": -10, "to_deg": 270},
                      {"to_deg": 360}])";
  expectRoundTrip(roller.text());
  const LoadResult r = parseMechanism(roller.text());
  ASSERT_TRUE(r.mechanism);
  const Joint& cam = r.mechanism->joints[2];
  EXPECT_EQ(toString(cam.type), std::string("cam"));
  // The records as written: members in their order, a key no kind reads kept.
  ASSERT_EQ(cam.recordsAt(0).size(), 4u);
  const Record& first = cam.recordsAt(0)[0];
  ASSERT_EQ(first.size(), 4u);
  EXPECT_EQ(first[3].key, "note");
  EXPECT_EQ(std::get<std::string>(first[3].value), "lift");
  EXPECT_EQ(cam.recordsAt(0)[2][0].key, "law");
  const std::string saved = serializeMechanism(*r.mechanism);
  EXPECT_NE(saved.find(R"("roller_mm": 8,)"), std::string::npos) << saved;
  EXPECT_EQ(saved.find(R"("flat")"), std::string::npos) << saved;
  EXPECT_NE(saved.find(R"("note": "lift")"), std::string::npos) << saved;
  EXPECT_NE(saved.find(R"("law": "polynomial-345",
          "rise_mm": -10,
          "to_deg": 270)"),
            std::string::npos)
      << saved;
  // A flat face: "flat": true, no roller written; an oscillating follower's degrees.
  test::TranslatingCam flat;
  flat.flat = true;
  expectRoundTrip(flat.text());
  const std::string flatSaved = serializeMechanism(*parseMechanism(flat.text()).mechanism);
  EXPECT_NE(flatSaved.find(R"("flat": true,)"), std::string::npos) << flatSaved;
  EXPECT_EQ(flatSaved.find(R"("roller_mm")"), std::string::npos) << flatSaved;
  expectRoundTrip(test::OscillatingCam{}.text());
  // An edit of the motion is a difference between two mechanisms.
  Mechanism edited = *r.mechanism;
  std::get<double>(edited.joints[2].records[0][0][0].value) = 80;
  EXPECT_NE(mechanismDifference(*r.mechanism, edited).find("joints[2].motion: "),
            std::string::npos);
}

TEST(CamFile, BadFieldsAreRefusedNamingThePlace) {
  EXPECT_EQ(translating(R"("base_mm": 30)", R"("base_mm": 0)"),
            "joints[2].base_mm: expected the base circle's radius, a number above 0");
  EXPECT_EQ(translating(R"("roller_mm": 8)", R"("roller_mm": 8, "flat": true)"),
            "joints[2].flat: a flat face has no roller: give \"roller_mm\" or \"flat\": true");
  EXPECT_EQ(translating(R"(, "roller_mm": 8)", ""),
            "joints[2].roller_mm: missing: the roller's radius (0 for a knife edge), or "
            "\"flat\": true");
  EXPECT_EQ(translating(R"("roller_mm": 8)", R"("roller_mm": -1)"),
            "joints[2].roller_mm: expected a radius of 0 (a knife edge) or more");
  EXPECT_EQ(translating(R"("roller_mm": 8)", R"("flat": 1)"),
            "joints[2].flat: expected true or false, got 1");
  EXPECT_EQ(translating(R"("motion": [)", R"("motion": 3, "x": [)"),
            "joints[2].motion: expected an array of objects, got 3");
  EXPECT_EQ(translating(R"({"to_deg": 150})", "150"),
            "joints[2].motion[1]: expected an object {...}, got 150");
  EXPECT_EQ(translating(R"({"to_deg": 150})", R"({"to_deg": true})"),
            "joints[2].motion[1].to_deg: expected a number or a string, got true");
  EXPECT_EQ(translating(R"({"to_deg": 150})", R"({"to_deg": "150"})"),
            "joints[2].motion[1].to_deg: expected a number, got \"150\"");
  EXPECT_EQ(translating(R"({"to_deg": 150})", R"({"to": 150})"),
            "joints[2].motion[1]: missing required field \"to_deg\"");
  EXPECT_EQ(translating(R"("cycloidal")", R"("parabolic")"),
            "joints[2].motion[0].law: unknown law \"parabolic\": \"cycloidal\", \"harmonic\", "
            "\"polynomial-345\", \"polynomial-4567\", \"modified-trapezoid\" or "
            "\"modified-sine\"");
  EXPECT_EQ(translating(R"("law": "cycloidal")", R"("law": 3)"),
            "joints[2].motion[0].law: expected the name of a law: \"cycloidal\", \"harmonic\", "
            "\"polynomial-345\", \"polynomial-4567\", \"modified-trapezoid\" or "
            "\"modified-sine\"");
  EXPECT_EQ(translating(R"(, "law": "cycloidal")", "").substr(0, 45),
            "joints[2].motion[0].law: a rise needs a law: ");
  EXPECT_EQ(translating(R"("rise_mm": 10)", R"("rise_deg": 10)"),
            "joints[2].motion[0].rise_deg: a translating follower rises in mm: \"rise_mm\"");
  EXPECT_EQ(translating(R"({"to_deg": 150})", R"({"to_deg": 60})"),
            "joints[2].motion[1].to_deg: expected an end above the previous segment's (90 "
            "degrees), got 60");
  EXPECT_EQ(translating(R"({"to_deg": 360})", R"({"to_deg": 350})"),
            "joints[2].motion[3].to_deg: the last segment ends at 350 degrees, not at 360");
  EXPECT_EQ(translating(R"("rise_mm": -10)", R"("rise_mm": -9)"),
            "joints[2].motion: the rises sum to 1, not 0: the follower would not come back "
            "where the turn started");
  EXPECT_EQ(translating(R"("rise_mm": 10)", R"("rise_mm": -10)").substr(0, 57),
            "joints[2].motion[0].rise_mm: the follower would go 10 bel");
  EXPECT_EQ(translating(R"(, "motion": )" + std::string(test::kSpecMotion), ""),
            "joints[2]: missing required field \"motion\"");
  EXPECT_EQ(translating(R"("a": "cam.O", "b")", R"("a": "cam.O", "ratio": 2, "b")"),
            "joints[2].ratio: a cam moves the follower of point \"b\" by the cam of point \"a\"; "
            "it has no \"ratio\"");
  EXPECT_EQ(
      refused(replaceOnce(test::OscillatingCam{}.text(), R"("rise_deg": 20)", R"("rise_mm": 20)")),
      "joints[2].motion[0].rise_mm: an oscillating follower rises in degrees: "
      "\"rise_deg\"");
}

// The drawing must be the follower's lowest position, on the base circle; the cam turns on a
// pin at a; the follower has one joint to the cam's guide.
TEST(CamFile, TheDrawingAndTheFollowersJointAreChecked) {
  const std::string text = test::TranslatingCam{}.text();
  // b drawn for base 30 is sqrt(38^2 - 10^2) - sqrt(37.9^2 - 10^2) = 0.1037 mm too high for
  // base 29.9.
  const std::string high = refused(replaceOnce(text, R"("base_mm": 30)", R"("base_mm": 29.9)"));
  EXPECT_EQ(high.substr(0, 29), "joints[2].b: b is 0.103663674") << high;
  EXPECT_NE(high.find("mm from where the follower touches the base circle (on the slot's line, "
                      "36.5569419 mm from the foot of the perpendicular from a): the drawing "
                      "is the follower's lowest position"),
            std::string::npos)
      << high;
  EXPECT_EQ(refused(replaceOnce(text, R"("base_mm": 30)", R"("base_mm": 1)")),
            "joints[2].b: the offset 10 mm is not less than base + roller = 9 mm: the slot's "
            "line misses the base circle");
  EXPECT_EQ(
      refused(replaceOnce(test::OscillatingCam{}.text(), R"("base_mm": 30)", R"("base_mm": 31)")),
      "joints[2].b: b is 38 mm from a, not base + roller = 39 mm: the drawing is the "
      "follower's lowest position, on the base circle");
  EXPECT_EQ(refused(replaceOnce(text, R"({"type": "pin", "a": "ground.O", "b": "cam.O"},)", "")),
            "joints[1].a: \"cam.O\" is not where the cam's body is pinned: a cam turns on a pin "
            "at its centre, on the body that guides its follower");
  EXPECT_EQ(refused(replaceOnce(
                text, R"({"type": "slider", "a": "follower.R", "slot": "ground.guide"},)", "")),
            "joints[1].b: no slider and no pin joins the follower's body and its guide, "
            "\"follower\" and \"ground\" (the body the cam turns on): a follower is a block in a "
            "straight slot or a body pinned to its pivot");
  EXPECT_EQ(refused(replaceOnce(text, "[[10, 0], [10, 100]]", "[[10, 0], [0, 50], [10, 100]]")),
            "joints[2].b: the follower's slider runs in an arc slot: a translating follower runs "
            "in a straight one");
}

class CamFileCli : public test::CliTest {};

#ifdef LINKAGE_CLI
TEST_F(CamFileCli, ABadLawExitsTwoNamingThePlace) {
  const std::string bad = replaceOnce(test::TranslatingCam{}.text(), "cycloidal", "cycloid");
  const test::CliResult r = run("info '" + writeFile("bad.linkage.json", bad) + "'");
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("joints[2].motion[0].law: unknown law \"cycloid\""), std::string::npos)
      << r.err;
  const test::CliResult ok =
      run("info '" + writeFile("good.linkage.json", test::TranslatingCam{}.text()) + "'");
  EXPECT_EQ(ok.exit, 0) << ok.err;
}
#endif

}  // namespace
}  // namespace linkage
