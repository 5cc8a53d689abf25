// Argument handling the design-check commands (limits, transmission, study) share. A header, not
// a cli_*.cpp: every app/cli_*.cpp is a command. Each function prints its own error.
#pragma once

#include <optional>
#include <string>

#include "cli_common.h"
#include "linkage/geometry.h"

namespace linkage::cli {

// The value after option argv[i] (i moves onto it).
inline std::optional<std::string> optionValue(int argc, char** argv, int& i) {
  if (i + 1 >= argc) {
    error(std::string(argv[i]) + ": needs a value");
    return std::nullopt;
  }
  return std::string(argv[++i]);
}

// "X,Y": two numbers; with nonZero, not 0,0.
inline std::optional<Vec2> numberPair(const std::string& option, const std::string& text,
                                      bool nonZero = false) {
  const size_t comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) {
    error(option + ": \"" + text + "\" is not two numbers X,Y");
    return std::nullopt;
  }
  std::optional<double> x = number(option, text.substr(0, comma));
  if (!x) return std::nullopt;
  std::optional<double> y = number(option, text.substr(comma + 1));
  if (!y) return std::nullopt;
  if (nonZero && *x == 0 && *y == 0) {
    error(option + ": must not be 0,0");
    return std::nullopt;
  }
  return Vec2(*x, *y);
}

// A whole number from lo to hi.
inline std::optional<long long> wholeNumberIn(const std::string& option, const std::string& text,
                                              long long lo, long long hi) {
  std::optional<long long> n = wholeNumber(option, text);
  if (n && (*n < lo || *n > hi)) {
    error(option + ": must be from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got " +
          text);
    return std::nullopt;
  }
  return n;
}

// An argument that is no known option of `command`: the MODEL, once.
inline bool modelArgument(const std::string& command, const std::string& a, std::string& model) {
  if (!a.empty() && a[0] == '-') {
    error(command + ": unknown option " + a + " (see linkage-cli " + command + " --help)");
    return false;
  }
  if (!model.empty()) {
    error(command + ": more than one MODEL given: " + model + ", " + a);
    return false;
  }
  model = a;
  return true;
}

inline bool modelGiven(const std::string& command, const std::string& model) {
  if (model.empty()) error(command + ": no MODEL given (see linkage-cli " + command + " --help)");
  return !model.empty();
}

// MODEL opened; it must have a driver to turn.
inline std::optional<Mechanism> openDrivenModel(const std::string& model) {
  std::optional<Mechanism> m = openModel(model);
  if (m && !m->driver) {
    error(model + ": the mechanism has no driver: add \"driver\": {\"joint\": <pin index>, ...}");
    return std::nullopt;
  }
  return m;
}

}  // namespace linkage::cli
