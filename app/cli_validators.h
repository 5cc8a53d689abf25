// The values options take, checked one way for every command of linkage-cli and linkage-plot
// (cli_parser.cpp attaches them to the options).
// Each check is a CLI::Validator: its message says what is wrong with the value, and CLI11
// puts the option's name in front ("--steps: \"ten\" is not a whole number"). The readers turn
// a checked value into what the command uses, with the program's own strict, locale-independent
// number parsing (linkage/io/numbers.h), never with CLI11's conversions, which go through the
// C library and would accept "1e3x" or depend on the locale.
#pragma once

#include <CLI/CLI.hpp>
#include <climits>
#include <optional>
#include <string>
#include <vector>

#include "linkage/geometry.h"

namespace linkage::cli {

// A finite number ("1.5", "-2e3").
CLI::Validator isNumber();
// A number above zero.
CLI::Validator positive();
// Zero or a number above it.
CLI::Validator notNegative();
// A whole number from lo to hi (hi LLONG_MAX: at least lo).
CLI::Validator wholeIn(long long lo, long long hi);
// Whole numbers separated by commas ("3" or "3,5,2").
CLI::Validator wholeList();
// Two numbers "X,Y"; with nonZero, not 0,0.
CLI::Validator numberPair(bool nonZero = false);
// A direction "DX,DY" or "DX,DY,DZ", not all 0.
CLI::Validator direction();
// Two numbers "LO,HI" with LO below HI.
CLI::Validator increasingPair();
// One of the words in `allowed`.
CLI::Validator oneOf(std::vector<std::string> allowed);
// A picture size "WxH" in pixels, whole numbers from 50 to 20000.
CLI::Validator pixelSize();

// Readers of values the validators above have passed (nullopt for anything else).
std::optional<long long> readWhole(const std::string& text);
std::optional<std::vector<long long>> readWholeList(const std::string& text);
std::optional<Vec2> readPair(const std::string& text);
std::optional<Vec3> readDirection(const std::string& text);  // DZ 0 where not given
std::optional<std::pair<int, int>> readSize(const std::string& text);

}  // namespace linkage::cli
