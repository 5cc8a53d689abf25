// `linkage-cli cam` (issue 28): the checks of every follower the spec names (translating roller
// with and without offset, knife edge, flat face; oscillating roller and flat face) the same
// with --steps 8 as with --steps 3600 (the steps set only the profile's points); the pressure
// angle of the offset roller against a search of the spec's closed form; the profile's surface
// and pressure angle against the contact the forces act through (cam::contact, written apart);
// the written profile read back; bad input; the
// sewing machine examples' cams within their limits.
#ifdef LINKAGE_CLI
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "cam_fixtures.h"
#include "cli_harness.h"
#include "linkage/cam_checks.h"
#include "linkage/cam_joint.h"
#include "linkage/io/model_file.h"
#include "linkage/io/numbers.h"

namespace linkage {
namespace {

constexpr double kDeg = M_PI / 180;

class CliCamChecks : public test::CliTest {};

std::vector<std::string> models() {
  test::TranslatingCam offset, central, knife, flat;
  central.e = 0;
  knife.roller = 0;
  flat.flat = true;
  test::OscillatingCam rocker, face;
  face.flat = true;
  return {offset.text(), central.text(), knife.text(), flat.text(), rocker.text(), face.text()};
}

TEST_F(CliCamChecks, EveryFollowersChecksAreTheSameFromEightStepsAsFromThousands) {
  int i = 0;
  for (const std::string& text : models()) {
    const std::string path = writeFile("cam" + std::to_string(i++) + ".json", text);
    const test::CliResult few = run("cam '" + path + "' --steps 8");
    const test::CliResult many = run("cam '" + path + "' --steps 3600");
    ASSERT_EQ(few.exit, 0) << few.err;
    EXPECT_EQ(few.out, many.out);
    EXPECT_EQ(few.lines().front(), "quantity,value,at_cam_deg");
    EXPECT_EQ(few.lines().size(), text.find("\"flat\": true") == std::string::npos ? 4u : 3u)
        << few.out;
  }
}

TEST_F(CliCamChecks, TheOffsetRollersPressureAngleIsTheSpecsClosedFormsLargest) {
  const test::TranslatingCam c;  // base 30, roller 8, offset 10
  const test::CliResult r = run("cam '" + writeFile("c.json", c.text()) + "'");
  ASSERT_EQ(r.exit, 0) << r.err;
  const LoadResult l = parseMechanism(c.text());
  ASSERT_TRUE(l.mechanism) << l.error;
  const std::optional<CamJoint> joint = camJoint(*l.mechanism, l.mechanism->joints[2]);
  ASSERT_TRUE(joint);
  const double d0 = std::sqrt(38.0 * 38.0 - 100.0);
  auto angle = [&](double t) {
    const cam::Displacement d = joint->program.at(t);
    return std::abs(std::atan((d.v - 10) / (d0 + d.s))) / kDeg;
  };
  double best = 0, at = 0;
  for (int i = 0; i < 36000; ++i)
    if (angle(i * 0.01 * kDeg) > best) best = angle(i * 0.01 * kDeg), at = i * 0.01;
  for (double h = 0.01; h > 1e-12; h /= 2)  // climb to the peak from the grid's best
    for (double step : {-h, h})
      while (angle((at + step) * kDeg) > best) at += step, best = angle(at * kDeg);
  const std::string row = r.lines()[1];
  ASSERT_EQ(row.rfind("pressure_angle_max_deg,", 0), 0u) << row;
  std::istringstream cells(row.substr(row.find(',') + 1));
  std::string v, deg;
  std::getline(cells, v, ',');
  std::getline(cells, deg, ',');
  EXPECT_NEAR(*parseNumber(v), best, 1e-9);
  EXPECT_NEAR(*parseNumber(deg), at, 1e-4);
}

TEST_F(CliCamChecks, TheProfileIsWhereTheContactIsAndReadsBack) {
  for (const std::string& text : models()) {
    const LoadResult l = parseMechanism(text);
    ASSERT_TRUE(l.mechanism) << l.error;
    const std::optional<CamJoint> c = camJoint(*l.mechanism, l.mechanism->joints[2]);
    ASSERT_TRUE(c);
    const cam::CamGeometry g = cam::geometryOf(*c);
    for (double deg = 0; deg < 360; deg += 17) {
      // The follower where the programme puts it, the contact there (the guide's frame), seen
      // from the cam turned by theta.
      const double theta = deg * kDeg;
      const cam::Displacement s = c->program.at(theta);
      cam::Place at = c->drawn;
      Vec2 dbds = at.along;
      if (c->kind.oscillating) {
        at.b = at.pivot + Rot::of(c->kind.sign * s.s) * (at.b - at.pivot);
        at.face = Rot::of(c->kind.sign * s.s) * at.face;
        dbds = c->kind.sign * perp(at.b - at.pivot);
      } else {
        at.b = at.b + s.s * at.along;
      }
      const cam::Contact k = cam::contact(c->kind, at, s.v);
      const Vec2 surface = c->kind.flat ? k.point : Vec2(at.b - c->kind.roller * k.normal);
      const cam::CamPoint mine = cam::camPointAt(g, theta);
      const Rot back = Rot::of(-theta);
      EXPECT_LT((mine.pitch - back * (at.b - at.centre)).norm(), 1e-9) << deg;
      EXPECT_LT((mine.surface - back * (surface - at.centre)).norm(), 1e-9) << deg;
      if (!c->kind.flat)
        EXPECT_NEAR(mine.pressureDeg, std::atan2(cross(dbds, k.normal), dbds.dot(k.normal)) / kDeg,
                    1e-9)
            << deg;
    }
  }
  const std::string path = writeFile("c.json", test::TranslatingCam().text());
  const std::string csv = (dir_ / "p.csv").string();
  ASSERT_EQ(run("cam '" + path + "' --steps 12 --out '" + csv + "'").exit, 0);
  std::istringstream in(test::slurp(csv));
  std::string line;
  int rows = -1;
  while (std::getline(in, line)) ++rows;
  EXPECT_EQ(rows, 12);
  EXPECT_EQ(run("cam '" + path + "' --out '" + (dir_ / "p.dxf").string() + "'").exit, 0);
  EXPECT_NE(test::slurp(dir_ / "p.dxf").find("CAM_SURFACE"), std::string::npos);
}

TEST_F(CliCamChecks, BadInputExitsTwoNamingIt) {
  const std::string path = writeFile("c.json", test::TranslatingCam().text());
  struct Case {
    std::string args, message;
  } cases[] = {{"cam four-bar-crank-rocker", "no cam joint"},
               {"cam '" + path + "' --joint 0", "joints[0] is a pin, not a cam"},
               {"cam '" + path + "' --joint 9", "no joints[9]"},
               {"cam '" + path + "' --out x.png", ".csv, .dxf or .svg"},
               {"cam '" + path + "' --steps 2", "--steps"}};
  for (const Case& c : cases) {
    const test::CliResult r = run(c.args);
    EXPECT_EQ(r.exit, 2) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
  }
}

// The sewing machine's cams (resources/examples/cams.py): on the command line each prints the
// same checks from 8 steps as from 3600, within the oscillating limit of 35 degrees and without
// undercut; the lockstitch machine's feed dog is up about half a turn and never while the needle
// is in the cloth (timing exits 0: no conflict; 4 would be one).
TEST_F(CliCamChecks, TheSewingMachineExamplesKeepTheirLimits) {
  for (const char* args :
       {"lockstitch-cams --joint 5", "lockstitch-cams --joint 9", "chainstitch-looper-cam"}) {
    const test::CliResult few = run(std::string("cam ") + args + " --steps 8");
    const test::CliResult many = run(std::string("cam ") + args + " --steps 3600");
    ASSERT_EQ(few.exit, 0) << args << ": " << few.err;
    EXPECT_EQ(few.out, many.out) << args;
    const std::vector<std::string> rows = few.lines();
    ASSERT_GE(rows.size(), 3u) << few.out;
    EXPECT_EQ(rows.back(), "undercut,no,") << args << ": " << few.err;
    const std::string first = rows[1].substr(0, rows[1].find(','));
    const double value =
        *parseNumber(rows[1].substr(first.size() + 1, rows[1].rfind(',') - first.size() - 1));
    if (first == "pressure_angle_max_deg") {
      EXPECT_LT(value, 35) << args;
    } else {
      EXPECT_EQ(first, "surface_radius_min_mm") << args;
      EXPECT_GT(value, 0) << args;
    }
  }
  const test::CliResult t = run("timing lockstitch-cams");
  ASSERT_EQ(t.exit, 0) << t.out << t.err;
  const std::vector<std::string> rows = t.lines();
  ASSERT_EQ(rows.size(), 3u) << t.out;
  ASSERT_EQ(rows[2].rfind("feed,", 0), 0u) << rows[2];
  std::istringstream cells(rows[2].substr(5));
  std::string from, to;
  std::getline(cells, from, ',');
  std::getline(cells, to, ',');
  EXPECT_NEAR(*parseNumber(to) - *parseNumber(from), 180, 10) << rows[2];
}

}  // namespace
}  // namespace linkage
#endif
