// Pieces every linkage-cli command shares: exit codes, option parsing, opening a model.
#pragma once

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

// argv[0], to find the examples installed next to the executable.
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

// Loads and assembles; prints notes (assembly moves, redundant joints) to standard error.
// Returns the exit status, kOk when the kinematics are ready.
int prepare(Kinematics& k, const Mechanism& m);

// Resolves --point arguments (or the file's outputs when none); prints the error itself.
std::optional<std::vector<PointId>> outputPoints(const Mechanism& m,
                                                 const std::vector<std::string>& asked);

bool isHelp(const std::string& arg);

}  // namespace linkage::cli
