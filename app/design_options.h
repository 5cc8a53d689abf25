// Option values the design-check commands (limits, transmission, study) share. A header, not a
// cli_*.cpp: every app/cli_*.cpp is a command.
#pragma once

#include <optional>
#include <string>

#include "cli_common.h"
#include "linkage/geometry.h"

namespace linkage::cli {

// The value after option argv[i] (i moves onto it), or nullopt after printing the error.
inline std::optional<std::string> optionValue(int argc, char** argv, int& i) {
  if (i + 1 >= argc) {
    error(std::string(argv[i]) + ": needs a value");
    return std::nullopt;
  }
  return std::string(argv[++i]);
}

// "X,Y": two numbers; prints the error itself.
inline std::optional<Vec2> numberPair(const std::string& option, const std::string& text) {
  const size_t comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) {
    error(option + ": \"" + text + "\" is not two numbers X,Y");
    return std::nullopt;
  }
  std::optional<double> x = number(option, text.substr(0, comma));
  if (!x) return std::nullopt;
  std::optional<double> y = number(option, text.substr(comma + 1));
  if (!y) return std::nullopt;
  return Vec2(*x, *y);
}

}  // namespace linkage::cli
