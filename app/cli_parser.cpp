#include "cli_parser.h"

#include <CLI/CLI.hpp>
#include <charconv>
#include <filesystem>
#include <iostream>

#include "cli_common.h"
#include "cli_validators.h"
#include "linkage/io/numbers.h"

namespace linkage::cli {

namespace {

// --help prints the command's own text as written (its usage, options, output and exit
// statuses), not a listing CLI11 would make of the options.
class HelpText : public CLI::Formatter {
 public:
  std::string make_help(const CLI::App* app, std::string, CLI::AppFormatMode) const override {
    return app->get_description();
  }
};

// CLI11's "NAME: K required TYPE missing" (an option at the end of the line without its value)
// in the program's words; nullopt for any other message.
std::optional<std::string> missingValue(const std::string& what) {
  const size_t colon = what.find(": "), required = what.find(" required ");
  if (colon == std::string::npos || required == std::string::npos || !what.ends_with(" missing"))
    return std::nullopt;
  int k = 0;
  const char* from = what.data() + colon + 2;
  if (std::from_chars(from, what.data() + required, k).ptr != what.data() + required)
    return std::nullopt;
  const std::string name = what.substr(0, colon);
  if (k == 1) return name + ": needs a value";
  const size_t type = required + 10, end = what.size() - 8;
  return name + ": needs " + std::to_string(k) + " values, " + what.substr(type, end - type);
}

// An argument the command has no place for: an unknown option, or a second MODEL.
std::string leftOver(const CLI::App& c, const std::vector<std::string>& extra) {
  const std::string cmd = c.get_name(), see = " (see linkage-cli " + cmd + " --help)";
  for (const std::string& a : extra)
    if (a.size() > 1 && a[0] == '-') return cmd + ": unknown option " + a + see;
  const CLI::Option* model = c.get_option_no_throw("MODEL");
  if (model && model->count() == 1)
    return cmd + ": more than one MODEL given: " + model->results().front() + ", " + extra.front();
  return cmd + ": unexpected argument " + extra.front() + see;
}

// What to print for a CLI11 error: the command, the option and the cause.
std::string problem(const CLI::App& root, const CLI::Error& e) {
  const std::string what = e.what();
  const std::vector<CLI::App*> given = root.get_subcommands();
  if (given.empty()) {
    if (root.remaining_size() > 0)
      return "unknown command \"" + root.remaining().front() + "\" (see linkage-cli --help)";
    return what;
  }
  const CLI::App& c = *given.front();
  const std::string cmd = c.get_name(), see = " (see linkage-cli " + cmd + " --help)";
  if (dynamic_cast<const CLI::RequiredError*>(&e))
    return cmd + ": " + (what == "MODEL is required" ? "no MODEL given" : what) + see;
  if (dynamic_cast<const CLI::ExtrasError*>(&e)) {
    std::vector<std::string> extra = c.remaining();
    if (extra.empty()) extra = root.remaining();
    return extra.empty() ? what : leftOver(c, extra);
  }
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&e))
    if (std::optional<std::string> m = missingValue(what)) return *m;
  return what;
}

// An option whose one value `read` stores once `rule` has passed it.
CLI::Option* addChecked(CLI::App& c, const std::string& name, const CLI::Validator& rule,
                        std::function<void(const std::string&)> read) {
  return c.add_option_function<std::string>(name, std::move(read))->check(rule);
}

CLI::Validator numberRule(NumberRule rule) {
  return rule == NumberRule::Positive      ? positive()
         : rule == NumberRule::NotNegative ? notNegative()
                                           : isNumber();
}

}  // namespace

Parser::Parser(const std::string& program, const char* help)
    : root_(std::make_unique<CLI::App>(help, program)) {
  root_->formatter(std::make_shared<HelpText>());
  root_->require_subcommand(1);
  // As the hand-written parsers did: an option given twice keeps its last value.
  root_->option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
}

Parser::~Parser() = default;

CLI::App& Parser::command(const std::string& name, const char* help) {
  return *root_->add_subcommand(name, help);
}

Command Parser::passThrough(const std::string& name,
                            std::function<int(const std::vector<std::string>&)> run) {
  CLI::App* c = root_->add_subcommand(name, "");
  c->prefix_command();
  c->set_help_flag();
  return {c, [c, run] { return run(c->remaining()); }};
}

void Parser::version(const std::string& text) {
  root_->add_flag_callback("--version", [text] {
    std::cout << text << "\n";
    throw CLI::Success();
  });
}

int Parser::run(const std::vector<Command>& commands, int argc, char** argv) {
  try {
    root_->parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << root_->help();
    return kOk;
  } catch (const CLI::Success&) {
    return kOk;  // --version, printed (CallForHelp is a Success too: caught first)
  } catch (const CLI::ParseError& e) {
    if (argc < 2) {
      std::cout << root_->help();  // no command at all: the help, as an error
      return kBadInput;
    }
    error(problem(*root_, e));
    return kBadInput;
  }
  for (const Command& c : commands)
    if (c.app->parsed()) return c.run();
  return kBadInput;  // (CLI11 requires one command)
}

void addModel(CLI::App& c, std::string& model) {
  c.add_option("MODEL", model)->required();
}

void addModels(CLI::App& c, std::vector<std::string>& models) {
  c.add_option("MODEL", models)->required();
}

CLI::Option* addText(CLI::App& c, const std::string& name, std::string& to) {
  return c.add_option(name, to);
}

CLI::Option* addTexts(CLI::App& c, const std::string& name, std::vector<std::string>& to) {
  // One value per occurrence: `--point a MODEL` leaves MODEL to be the model.
  return c.add_option(name, to)->allow_extra_args(false);
}

CLI::Option* addTextPair(CLI::App& c, const std::string& name,
                         std::pair<std::string, std::string>& to, const std::string& what) {
  return c.add_option(name, to)->type_name(what);
}

CLI::Option* addWord(CLI::App& c, const std::string& name, std::string& to,
                     std::vector<std::string> allowed) {
  return c.add_option(name, to)->check(oneOf(std::move(allowed)));
}

CLI::Option* addFlag(CLI::App& c, const std::string& name, bool& on) {
  return c.add_flag(name, on);
}

CLI::Option* addNumber(CLI::App& c, const std::string& name, double& to, NumberRule rule) {
  return addChecked(c, name, numberRule(rule), [&to](auto& v) { to = *parseNumber(v); });
}

CLI::Option* addNumber(CLI::App& c, const std::string& name, std::optional<double>& to,
                       NumberRule rule) {
  return addChecked(c, name, numberRule(rule), [&to](auto& v) { to = parseNumber(v); });
}

CLI::Option* addWhole(CLI::App& c, const std::string& name, int& to, long long lo, long long hi) {
  // (lo and hi are within int wherever an int is read)
  return addChecked(c, name, wholeIn(lo, hi),
                    [&to](auto& v) { to = static_cast<int>(*readWhole(v)); });
}

CLI::Option* addWhole(CLI::App& c, const std::string& name, long long& to, long long lo,
                      long long hi) {
  return addChecked(c, name, wholeIn(lo, hi), [&to](auto& v) { to = *readWhole(v); });
}

CLI::Option* addWholeList(CLI::App& c, const std::string& name, std::vector<long long>& to) {
  return addChecked(c, name, wholeList(), [&to](auto& v) { to = *readWholeList(v); });
}

CLI::Option* addPair(CLI::App& c, const std::string& name, std::optional<Vec2>& to, PairRule rule) {
  const CLI::Validator check =
      rule == PairRule::Increasing ? increasingPair() : numberPair(rule == PairRule::NonZero);
  return addChecked(c, name, check, [&to](auto& v) { to = readPair(v); });
}

CLI::Option* addDirection(CLI::App& c, const std::string& name, std::optional<Vec3>& to) {
  return addChecked(c, name, direction(), [&to](auto& v) { to = readDirection(v); });
}

CLI::Option* addFigureFile(CLI::App& c, const std::string& name, std::string& to) {
  return c.add_option_function<std::string>(name, [name, &to](const std::string& v) {
    const std::string ext = std::filesystem::path(v).extension().string();
    // The name is the place: "--out f.txt: ...", as every message about a name says it.
    if (ext != ".png" && ext != ".pdf" && ext != ".svg")
      throw CLI::ValidationError(name + " " + v + ": the name must end in .png, .pdf or .svg");
    to = v;
  });
}

CLI::Option* addPixelSize(CLI::App& c, const std::string& name,
                          std::optional<std::pair<int, int>>& to) {
  return addChecked(c, name, pixelSize(), [&to](auto& v) { to = readSize(v); });
}

CLI::Option* required(CLI::Option* o) {
  return o->required();
}

size_t count(const CLI::Option* o) {
  return o->count();
}

}  // namespace linkage::cli
