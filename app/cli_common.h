// Pieces every linkage-cli command shares: exit codes, option parsing, opening a model.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "linkage/kinematics.h"
#include "linkage/model.h"

namespace linkage::cli {

enum Exit { kOk = 0, kFailure = 1, kBadInput = 2, kUnreachable = 3 };

// Exit status for a solver status: the mechanism's own problems are bad input, a crank angle it
// cannot reach (or where it is singular) is 3.
int exitFor(const Status& s);

// This program's path (linkage::runningExecutable), to find the examples installed with it and
// linkage-plot next to it.
extern std::string executablePath;

// Prints "linkage-cli: <message>" to standard error.
void error(const std::string& message);
void note(const std::string& message);

// Strict, locale-independent number parsing for options; prints the error itself.
std::optional<double> number(const std::string& option, const std::string& text);
std::optional<double> positiveNumber(const std::string& option, const std::string& text);
std::optional<long long> wholeNumber(const std::string& option, const std::string& text);

// Loads MODEL (a path or an example name); prints the error and returns nullopt on failure.
std::optional<Mechanism> openModel(const std::string& nameOrPath);

// openModel, for a command that turns the crank: a mechanism without a driver is refused (the
// message says how to add one).
std::optional<Mechanism> openDrivenModel(const std::string& nameOrPath);

// Writes text to standard output, or atomically to `path` when it is not empty; kOk, or
// kFailure with the error printed.
int writeOutput(const std::string& path, const std::string& text);

// Loads and assembles; prints notes (assembly moves, redundant joints) to standard error.
// Returns the exit status, kOk when the kinematics are ready.
int prepare(Kinematics& k, const Mechanism& m);

// Resolves --point arguments (or the file's outputs when none); prints the error itself.
std::optional<std::vector<PointId>> outputPoints(const Mechanism& m,
                                                 const std::vector<std::string>& asked);

bool isHelp(const std::string& arg);

// The arguments of one command, read in order as every command reads them: -h or --help prints
// the help; an option with a value hands it to its reader (which prints its own error and
// returns false); a flag is set; any other argument starting with '-' (but "-" itself) is an
// unknown option; the first other argument is MODEL, a second one an error, none an error.
class Arguments {
 public:
  using Reader = std::function<bool(const std::string& option, const std::string& value)>;
  Arguments(std::string command, const char* help) : command_(std::move(command)), help_(help) {}
  Arguments& value(std::string option, Reader read);
  Arguments& flag(std::string option, bool& on);
  // Reads argv into the readers and `model`: nullopt to go on, else the exit status to return
  // (kOk after the help, kBadInput after an error, printed).
  std::optional<int> read(int argc, char** argv, std::string& model) const;

 private:
  std::string command_;
  const char* help_;
  std::vector<std::pair<std::string, Reader>> values_;
  std::vector<std::pair<std::string, bool*>> flags_;
};

}  // namespace linkage::cli
