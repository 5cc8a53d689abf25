// linkage-cli sensitivity on a machine with cams (resources/examples/lockstitch-cams): it runs
// (a cam was refused before), lists each cam's rises, base and roller among the dimensions, and
// writes the library's numbers (linkage/sensitivity.h) to the last bit, rates included.
#ifdef LINKAGE_CLI
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cli_harness.h"
#include "examples.h"
#include "linkage/io/model_file.h"
#include "linkage/io/numbers.h"
#include "linkage/sensitivity.h"

namespace linkage {
namespace {

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> v;
  std::istringstream s(text);
  for (std::string f; std::getline(s, f, sep);) v.push_back(f);
  return v;
}

class CamSensitivityCli : public test::CliTest {};

TEST_F(CamSensitivityCli, TheLockstitchCamsListTheirRises) {
  const Mechanism m = test::example("lockstitch-cams");
  const std::string file = "'" + writeFile("m.linkage.json", serializeMechanism(m)) + "'";
  const test::CliResult res =
      run("sensitivity " + file + " --point takeup.E --steps 4 --velocity --acceleration");
  ASSERT_EQ(res.exit, 0) << res.err;
  const std::vector<std::string> lines = res.lines();
  const std::vector<Dimension> dims = dimensions(m);
  ASSERT_EQ(lines.size(), 1 + 4 * dims.size()) << res.out;
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dims).ok());
  const PointId E = *m.findPoint("takeup.E");
  std::vector<std::string> cams;
  for (int step = 0; step < 4; ++step) {
    ASSERT_TRUE(k.moveTo(90.0 * step).ok());
    ASSERT_TRUE(s.at(k).ok());
    for (size_t d = 0; d < dims.size(); ++d) {
      const std::vector<std::string> row = split(lines[1 + step * dims.size() + d], ',');
      ASSERT_EQ(row.size(), 8u);
      ASSERT_EQ(row[1], dims[d].name);
      if (step == 0 && row[1].rfind("cam:", 0) == 0) cams.push_back(row[1]);
      const int i = static_cast<int>(d);
      const Vec2 want[3] = {s.point(k, E, i), s.velocity(k, E, i), s.acceleration(k, E, i)};
      for (int o = 0; o < 3; ++o) {
        EXPECT_EQ(parseNumber(row[2 + 2 * o]), want[o].x()) << row[1];
        EXPECT_EQ(parseNumber(row[3 + 2 * o]), want[o].y()) << row[1];
      }
    }
  }
  // The take-up cam: a dwell, two rises and a dwell, a fall; the feed-lift cam: rise and fall.
  const std::vector<std::string> want = {
      "cam:takeup.R.segment2.rise",   "cam:takeup.R.segment3.rise",
      "cam:takeup.R.segment5.rise",   "cam:takeup.R.base",
      "cam:takeup.R.roller",          "cam:feedlift.R.segment2.rise",
      "cam:feedlift.R.segment4.rise", "cam:feedlift.R.base",
      "cam:feedlift.R.roller"};
  EXPECT_EQ(cams, want);
}

}  // namespace
}  // namespace linkage
#endif
