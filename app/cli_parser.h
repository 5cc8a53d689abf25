// The command line, read one way by linkage-cli and linkage-plot: with CLI11. Each command is a
// CLI11 subcommand whose options are bound to the command's own state by the add* functions
// below; the parser reads argv into them, turns CLI11's errors into the program's messages (the
// command, the option and the cause; exit status 2) and runs the command given. The help of a
// command is its own text, printed as written.
//
// Only cli_parser.cpp and cli_validators.cpp include CLI11 (a header-only library that takes
// seconds to compile): the commands see the declarations below.
#pragma once

#include <climits>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "linkage/geometry.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace linkage::cli {

// A command: its subcommand, and what runs it once argv has been read (its exit status).
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

class Parser {
 public:
  // `help` is printed for --help, and with exit status 2 when no command is given.
  Parser(const std::string& program, const char* help);
  ~Parser();

  CLI::App& command(const std::string& name, const char* help);
  // A command that hands every argument after its name, --help too, to `run` as it is.
  Command passThrough(const std::string& name,
                      std::function<int(const std::vector<std::string>&)> run);
  // --version prints `text` and exits 0.
  void version(const std::string& text);

  // Reads argv and runs the command given: its exit status; 0 after the help asked for, 2 after
  // a problem with the arguments (printed).
  int run(const std::vector<Command>& commands, int argc, char** argv);

 private:
  std::unique_ptr<CLI::App> root_;
};

constexpr long long kNoLimit = LLONG_MAX;
enum class NumberRule { Any, Positive, NotNegative };
enum class PairRule { Any, NonZero, Increasing };  // not 0,0; LO,HI with LO below HI

// The options a command reads. Numbers are checked by cli_validators.h and read with the
// program's own number parsing. An option given twice keeps its last value, except the
// repeatable ones (addTexts), which keep every value, one per occurrence.
void addModel(CLI::App& c, std::string& model);                 // MODEL, required
void addModels(CLI::App& c, std::vector<std::string>& models);  // MODEL..., at least one
CLI::Option* addText(CLI::App& c, const std::string& name, std::string& to);
CLI::Option* addTexts(CLI::App& c, const std::string& name, std::vector<std::string>& to);
// Two words "--name A B" (both required when the option is given).
CLI::Option* addTextPair(CLI::App& c, const std::string& name,
                         std::pair<std::string, std::string>& to, const std::string& what);
// A word out of `allowed`.
CLI::Option* addWord(CLI::App& c, const std::string& name, std::string& to,
                     std::vector<std::string> allowed);
CLI::Option* addFlag(CLI::App& c, const std::string& name, bool& on);
CLI::Option* addNumber(CLI::App& c, const std::string& name, double& to,
                       NumberRule rule = NumberRule::Any);
CLI::Option* addNumber(CLI::App& c, const std::string& name, std::optional<double>& to,
                       NumberRule rule = NumberRule::Any);
// A whole number from lo to hi.
CLI::Option* addWhole(CLI::App& c, const std::string& name, int& to, long long lo,
                      long long hi = kNoLimit);
CLI::Option* addWhole(CLI::App& c, const std::string& name, long long& to, long long lo,
                      long long hi = kNoLimit);
// Whole numbers "N[,N...]".
CLI::Option* addWholeList(CLI::App& c, const std::string& name, std::vector<long long>& to);
CLI::Option* addPair(CLI::App& c, const std::string& name, std::optional<Vec2>& to,
                     PairRule rule = PairRule::Any);
// A direction "DX,DY" or "DX,DY,DZ" (DZ 0 where not given), not all 0.
CLI::Option* addDirection(CLI::App& c, const std::string& name, std::optional<Vec3>& to);
// A figure's file name, which must end in .png, .pdf or .svg.
CLI::Option* addFigureFile(CLI::App& c, const std::string& name, std::string& to);
// A picture size "WxH" in pixels.
CLI::Option* addPixelSize(CLI::App& c, const std::string& name,
                          std::optional<std::pair<int, int>>& to);

// The option must be given.
CLI::Option* required(CLI::Option* o);
// How many times the option was given.
size_t count(const CLI::Option* o);

}  // namespace linkage::cli
