// The machine commands as a user and a script see them: slots, clearance, timing; exact
// headers, numbers against closed forms, exit statuses and the place named in messages.
#ifdef LINKAGE_CLI
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "cli_harness.h"
#include "linkage/io/model_file.h"
#include "linkage/io/numbers.h"
#include "mechanisms.h"

namespace linkage {
namespace {

using test::CliResult;

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> v;
  std::istringstream s(text);
  for (std::string f; std::getline(s, f, sep);) v.push_back(f);
  if (!text.empty() && text.back() == sep) v.push_back("");
  return v;
}

double field(const std::string& text) {
  std::optional<double> v = parseNumber(text);
  EXPECT_TRUE(v.has_value()) << "not a number: '" << text << "'";
  return v.value_or(NAN);
}

class MachineCli : public test::CliTest {
 protected:
  std::string save(const Mechanism& m, const std::string& name = "m.linkage.json") {
    return "'" + writeFile(name, serializeMechanism(m)) + "'";
  }
};

TEST_F(MachineCli, SlotsOfASliderCrankAgainstItsClosedForm) {
  const double r = 20, l = 60, e = 8;
  const test::SliderCrank s = test::sliderCrank(r, l, e, 30);
  const CliResult res = run("slots " + save(s.m));
  ASSERT_EQ(res.exit, 0) << res.err;
  const std::vector<std::string> lines = res.lines();
  ASSERT_EQ(lines.size(), 2u) << res.out;
  EXPECT_EQ(lines[0], "joint,min_mm,max_mm,slot_from_mm,slot_to_mm,inside");
  const std::vector<std::string> f = split(lines[1], ',');
  ASSERT_EQ(f.size(), 6u);
  EXPECT_EQ(f[0], "slider.B");
  EXPECT_NEAR(field(f[1]), std::sqrt((l - r) * (l - r) - e * e), 1e-9 * l);
  EXPECT_NEAR(field(f[2]), std::sqrt((l + r) * (l + r) - e * e), 1e-9 * l);
  EXPECT_EQ(field(f[3]), 0);
  EXPECT_NEAR(field(f[4]), r + l, 1e-12);
  EXPECT_EQ(f[5], "yes");
  const CliResult info = run("info " + save(s.m));
  EXPECT_NE(info.out.find("slot travel: slider.B in ground.guide: "), std::string::npos)
      << info.out;
}

TEST_F(MachineCli, SlotsExitFourWhenABlockLeavesItsSlot) {
  test::SliderCrank s = test::sliderCrank(20, 60, 0, 30);
  s.m.slots.front().p1 = Vec2(0, 70);  // the block rises to 80
  const CliResult res = run("slots " + save(s.m));
  EXPECT_EQ(res.exit, 4) << res.err;
  ASSERT_EQ(res.lines().size(), 2u);
  EXPECT_EQ(split(res.lines()[1], ',')[5], "no");
  EXPECT_NE(res.err.find("10 mm past its end"), std::string::npos) << res.err;
  EXPECT_NE(run("info " + save(s.m)).out.find("(leaves the slot)"), std::string::npos);
}

TEST_F(MachineCli, SlotsBadInput) {
  EXPECT_EQ(run("slots").exit, 2);
  const CliResult r = run("slots slider-crank-22a-lambda-0.3 --steps 2");
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("--steps"), std::string::npos) << r.err;
  EXPECT_EQ(run("slots slider-crank-22a-lambda-0.3 --bogus").exit, 2);
  EXPECT_EQ(run("slots --help").exit, 0);
}

}  // namespace
}  // namespace linkage
#endif
