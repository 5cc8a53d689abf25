// The options of every linkage-cli command, read one way (CLI11, app/cli_parser.h): help, an
// unknown option, a bad number, a missing value or argument each give their exit status and a
// message that names the command or the option and the cause.
#ifdef LINKAGE_CLI
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "cli_harness.h"

namespace linkage {
namespace {

using test::CliResult;

// Each command with arguments it runs with (a model and what it requires), and a whole-number
// option it takes.
struct CommandCase {
  std::string name, args, wholeOption;
};

const std::vector<CommandCase>& commands() {
  static const std::vector<CommandCase> c = {
      {"analyze", "wanzer-inversion-2", "--steps"},
      {"info", "wanzer-inversion-2", ""},
      {"ics", "wanzer-inversion-2 --angle 0", ""},
      {"limits", "wanzer-inversion-2 --point needlebar.G", "--steps"},
      {"transmission", "four-bar-crank-rocker", "--steps"},
      {"study",
       "four-bar-crank-rocker --move ground.O4 --by 1,0 --from 0 --to 1 --steps 3 "
       "--point coupler.P",
       "--crank-steps"},
      {"dynamics", "slider-crank-22a-masses", "--steps"},
      {"balance", "drop-feed --counterweight lowershaft --minimize fx", "--steps"},
      {"slots", "slider-crank-22a-lambda-0.3", "--steps"},
      {"clearance", "lockstitch-arm-shaft --between hook.K needlebar.N", "--steps"},
      {"timing", "slider-crank-22a-lambda-0.3 --window 'n=slider.B:y<60'", "--steps"},
  };
  return c;
}

bool plotAvailable() {
  return std::filesystem::exists(std::filesystem::path(LINKAGE_CLI).parent_path() / "linkage-plot");
}

class CliOptions : public test::CliTest {
 protected:
  // Exit status 2, nothing on standard output, and `message` on standard error.
  void expectBadInput(const std::string& args, const std::string& message) {
    const CliResult r = run(args);
    EXPECT_EQ(r.exit, 2) << args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << args << "\n" << r.out;
    EXPECT_NE(r.err.find("linkage-cli: " + message), std::string::npos)
        << args << "\nwanted: " << message << "\ngot: " << r.err;
  }
};

TEST_F(CliOptions, HelpOfEveryCommandIsItsOwnTextOnStandardOutput) {
  std::vector<std::string> names = {"examples"};
  for (const CommandCase& c : commands()) names.push_back(c.name);
  if (plotAvailable()) names.push_back("plot");
  for (const std::string& n : names)
    for (const std::string& flag : {"--help", "-h"}) {
      const CliResult r = run(n + " " + flag);
      EXPECT_EQ(r.exit, 0) << n << " " << flag << "\n" << r.err;
      EXPECT_EQ(r.out.rfind("usage: linkage-cli " + n, 0), 0u) << n << " " << flag << "\n" << r.out;
      EXPECT_EQ(r.err, "") << n;
    }
  // After the model and options too, as anywhere on the line.
  const CliResult r = run("analyze wanzer-inversion-2 --steps 4 --help");
  EXPECT_EQ(r.exit, 0);
  EXPECT_EQ(r.out.rfind("usage: linkage-cli analyze", 0), 0u) << r.out;
}

// Every option the help of a command lists is one its parser knows: given without its value,
// no command says "unknown option".
TEST_F(CliOptions, EveryOptionInTheHelpIsKnown) {
  const std::regex option(R"(\n  (--[a-z-]+))");
  for (const CommandCase& c : commands()) {
    const std::string help = run(c.name + " --help").out;
    std::set<std::string> listed;
    for (auto i = std::sregex_iterator(help.begin(), help.end(), option);
         i != std::sregex_iterator(); ++i)
      listed.insert((*i)[1]);
    EXPECT_GE(listed.size(), c.name == "info" ? 0u : 1u) << c.name;
    for (const std::string& o : listed) {
      const CliResult r = run(c.name + " " + c.args + " " + o);
      EXPECT_EQ(r.err.find("unknown option"), std::string::npos) << c.name << " " << o << r.err;
    }
  }
}

TEST_F(CliOptions, UnknownOptionExitsTwoNamingIt) {
  for (const CommandCase& c : commands())
    expectBadInput(
        c.name + " " + c.args + " --frobnicate",
        c.name + ": unknown option --frobnicate (see linkage-cli " + c.name + " --help)");
  // With a value after it, and before the model.
  expectBadInput("analyze --frob 3 wanzer-inversion-2", "analyze: unknown option --frob");
  if (plotAvailable())
    expectBadInput("plot wanzer-inversion-1 --out x.png --frob", "plot: unknown option --frob");
}

TEST_F(CliOptions, BadNumberExitsTwoNamingTheOptionAndTheCause) {
  for (const CommandCase& c : commands()) {
    if (c.wholeOption.empty()) continue;
    expectBadInput(c.name + " " + c.args + " " + c.wholeOption + " x",
                   c.wholeOption + ": \"x\" is not a whole number");
    expectBadInput(c.name + " " + c.args + " " + c.wholeOption + " 2.5",
                   c.wholeOption + ": \"2.5\" is not a whole number");
  }
  expectBadInput("ics wanzer-inversion-2 --angle 1,5", "--angle: \"1,5\" is not a number");
  expectBadInput("analyze wanzer-inversion-2 --rpm 0", "--rpm: must be positive, got 0");
  expectBadInput("analyze wanzer-inversion-2 --revs 1e999", "--revs: \"1e999\" is not a number");
  expectBadInput("analyze wanzer-inversion-2 --steps 0", "--steps: must be at least 1, got 0");
  expectBadInput("slots slider-crank-22a-lambda-0.3 --steps 3",
                 "--steps: must be from 4 to 1000000, got 3");
  expectBadInput("transmission four-bar-crank-rocker --band 30,x", "--band: \"x\" is not a number");
  expectBadInput("ics wanzer-inversion-2 --angle 0 --point needlebar.G --via 3,,2",
                 "--via: \"\" is not a whole number");
  expectBadInput("balance drop-feed --counterweight lowershaft --minimize torque",
                 "--minimize: \"torque\" is not fx, fy, fz or force");
  if (plotAvailable())
    expectBadInput("plot wanzer-inversion-1 --out x.png --units furlongs",
                   "--units: \"furlongs\" is not mm, m or g");
}

TEST_F(CliOptions, MissingValueOrArgumentExitsTwoNamingIt) {
  for (const CommandCase& c : commands()) {
    expectBadInput(c.name, c.name + ": no MODEL given (see linkage-cli " + c.name + " --help)");
    if (!c.wholeOption.empty())
      expectBadInput(c.name + " " + c.args + " " + c.wholeOption,
                     c.wholeOption + ": needs a value");
  }
  expectBadInput("clearance lockstitch-arm-shaft --between hook.K",
                 "--between: needs 2 values, A B");
  expectBadInput("clearance lockstitch-arm-shaft",
                 "clearance: --between is required (see linkage-cli clearance --help)");
  expectBadInput("balance drop-feed --counterweight lowershaft", "balance: --minimize is required");
  expectBadInput(
      "study four-bar-crank-rocker --move ground.O4 --by 1,0 --from 0 --steps 3 "
      "--point coupler.P",
      "study: --to is required");
  expectBadInput("info wanzer-inversion-2 wanzer-inversion-1",
                 "info: more than one MODEL given: wanzer-inversion-2, wanzer-inversion-1");
  expectBadInput("examples extra", "examples: unexpected argument extra");
  expectBadInput("frobnicate wanzer-inversion-2",
                 "unknown command \"frobnicate\" (see linkage-cli --help)");
  if (plotAvailable()) expectBadInput("plot --out x.png", "plot: no MODEL given");
}

TEST_F(CliOptions, ValuesAreReadAsTheyAreWritten) {
  const CliResult four = run("analyze wanzer-inversion-2 --steps 4");
  ASSERT_EQ(four.exit, 0) << four.err;
  EXPECT_EQ(four.lines().size(), 6u);
  // --option=value is the same; an option given twice keeps its last value.
  EXPECT_EQ(run("analyze wanzer-inversion-2 --steps=4").out, four.out);
  EXPECT_EQ(run("analyze wanzer-inversion-2 --steps 7 --steps 4").out, four.out);
  EXPECT_EQ(run("analyze --steps 4 wanzer-inversion-2").out, four.out);
  // A value that starts with '-' is the option's value, not an option.
  const CliResult minus = run("analyze wanzer-inversion-2 --angle -30");
  ASSERT_EQ(minus.exit, 0) << minus.err;
  ASSERT_EQ(minus.lines().size(), 2u) << minus.out;
  EXPECT_EQ(minus.lines()[1].rfind("-", 0), 0u) << minus.out;  // t_s of -30 degrees
  // --point takes one value: the model may follow it.
  const CliResult p = run("analyze --point needlebar.G wanzer-inversion-2 --steps 4");
  EXPECT_EQ(p.exit, 0) << p.err;
  EXPECT_EQ(p.out, four.out);
  // A model named like a command is a model, not a second command.
  expectBadInput("analyze info", "info: no such file, and no example of that name");
}

}  // namespace
}  // namespace linkage
#endif
