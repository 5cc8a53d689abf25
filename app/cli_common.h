// Pieces every linkage-cli command shares: exit codes, messages, opening a model, writing out.
// (Options are read by cli_parser.h.)
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

// This program's path (linkage::runningExecutable), to find the examples installed with it and
// linkage-plot next to it.
extern std::string executablePath;

// Prints "linkage-cli: <message>" to standard error.
void error(const std::string& message);
void note(const std::string& message);

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

}  // namespace linkage::cli
