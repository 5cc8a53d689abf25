// The cam example on the command line (issue 28): `analyze` writes the follower's motion, which
// is the programme's s, omega s', omega^2 s'' to 1e-9 of their peaks; `dynamics` writes the cam's
// columns, its contact force at a dwell the hand's (the spring and the follower's weight over
// cos(alpha)); the example is as the program saves it.
#ifdef LINKAGE_CLI
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "cli_harness.h"
#include "linkage/cam_joint.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "linkage/io/numbers.h"

namespace linkage {
namespace {

constexpr double kDeg = M_PI / 180;

const std::string kExample =
    std::string(LINKAGE_EXAMPLES_DIR) + "/cam-translating-roller.linkage.json";

std::vector<double> numbers(const std::string& row) {
  std::vector<double> v;
  std::istringstream s(row);
  for (std::string f; std::getline(s, f, ',');) v.push_back(parseNumber(f).value_or(NAN));
  return v;
}

class CliCam : public test::CliTest {};

TEST_F(CliCam, AnalyzeWritesTheProgrammesMotion) {
  const LoadResult r = loadMechanismFile(kExample);
  ASSERT_TRUE(r.mechanism) << r.error;
  const cam::Program program = camJoint(*r.mechanism, r.mechanism->joints[2])->program;
  const test::CliResult out = run("analyze '" + kExample + "' --steps 72 --point follower.R");
  ASSERT_EQ(out.exit, 0) << out.err;
  const std::vector<std::string> lines = out.lines();
  ASSERT_EQ(lines.size(), 74u);
  const double w = 1200 * 2 * M_PI / 60;
  const double peaks[3] = {8, w * 8 * 2 / (100 * kDeg),
                           w * w * 8 * 2 * M_PI / std::pow(100 * kDeg, 2)};
  for (size_t i = 1; i < lines.size(); ++i) {
    const std::vector<double> v = numbers(lines[i]);
    ASSERT_EQ(v.size(), 8u) << lines[i];
    const cam::Displacement s = program.at(v[1] * kDeg);
    EXPECT_NEAR(v[2], 9, 1e-9 * peaks[0]) << lines[i];
    EXPECT_NEAR(v[3] - 40, s.s, 1e-9 * peaks[0]) << lines[i];
    EXPECT_NEAR(v[5], w * s.v, 1e-9 * peaks[1]) << lines[i];
    EXPECT_NEAR(v[7], w * w * s.a, 1e-9 * peaks[2]) << lines[i];
  }
}

TEST_F(CliCam, DynamicsWritesTheContactForce) {
  const test::CliResult out = run("dynamics cam-translating-roller --steps 12");
  ASSERT_EQ(out.exit, 0) << out.err;
  const std::vector<std::string> lines = out.lines();
  ASSERT_EQ(lines.size(), 14u);
  EXPECT_NE(lines[0].find(",cam:cam.O.fx_N,cam:cam.O.fy_N,cam:cam.O.m_Nm,cam:cam.O.contact_N"),
            std::string::npos)
      << lines[0];
  // At 0 the follower dwells at the bottom: the spring's 20 N and its weight, over
  // cos(alpha) = 40 / 41 (b = (9, 40) from the cam's centre).
  const std::vector<double> first = numbers(lines[1]);
  EXPECT_NEAR(first.back(), (20 + 0.05 * 9.81) * 41 / 40, 1e-12);
}

TEST(CamExample, IsAsTheProgramSavesIt) {
  std::ifstream f(kExample);
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  const LoadResult r = parseMechanism(text);
  ASSERT_TRUE(r.mechanism) << r.error;
  EXPECT_EQ(serializeMechanism(*r.mechanism), text);
}

}  // namespace
}  // namespace linkage
#endif
