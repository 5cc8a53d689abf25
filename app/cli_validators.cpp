#include "cli_validators.h"

#include <charconv>
#include <cmath>

#include "linkage/io/numbers.h"

namespace linkage::cli {

namespace {

std::string quoted(const std::string& text) {
  return "\"" + text + "\"";
}

// A validator from a check that returns the problem, or "" when the value is fine.
CLI::Validator check(std::function<std::string(const std::string&)> problem, std::string what) {
  return CLI::Validator([problem](std::string& v) { return problem(v); }, std::move(what));
}

// "X,Y" split at its one comma; nullopt when there is not exactly one.
std::optional<std::pair<std::string, std::string>> splitPair(const std::string& text) {
  const size_t comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
    return std::nullopt;
  return std::pair{text.substr(0, comma), text.substr(comma + 1)};
}

std::string pairProblem(const std::string& v) {
  const auto parts = splitPair(v);
  if (!parts) return quoted(v) + " is not two numbers X,Y";
  for (const std::string& p : {parts->first, parts->second})
    if (!parseNumber(p)) return quoted(p) + " is not a number";
  return "";
}

}  // namespace

std::optional<long long> readWhole(const std::string& text) {
  long long v = 0;
  const char* end = text.data() + text.size();
  auto [p, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc() || p != end) return std::nullopt;
  return v;
}

std::optional<std::vector<long long>> readWholeList(const std::string& text) {
  std::vector<long long> v;
  for (size_t start = 0; start <= text.size();) {
    const size_t comma = std::min(text.find(',', start), text.size());
    const std::optional<long long> n = readWhole(text.substr(start, comma - start));
    if (!n) return std::nullopt;
    v.push_back(*n);
    start = comma + 1;
  }
  return v;
}

std::optional<Vec2> readPair(const std::string& text) {
  const auto parts = splitPair(text);
  if (!parts) return std::nullopt;
  const std::optional<double> x = parseNumber(parts->first), y = parseNumber(parts->second);
  if (!x || !y) return std::nullopt;
  return Vec2(*x, *y);
}

std::optional<std::pair<int, int>> readSize(const std::string& text) {
  const size_t x = text.find('x');
  if (x == std::string::npos) return std::nullopt;
  const std::optional<long long> w = readWhole(text.substr(0, x)),
                                 h = readWhole(text.substr(x + 1));
  if (!w || !h || *w < 50 || *h < 50 || *w > 20000 || *h > 20000) return std::nullopt;
  return std::pair{static_cast<int>(*w), static_cast<int>(*h)};
}

CLI::Validator isNumber() {
  return check(
      [](const std::string& v) { return parseNumber(v) ? "" : quoted(v) + " is not a number"; },
      "NUMBER");
}

CLI::Validator positive() {
  return check(
      [](const std::string& v) {
        const std::optional<double> x = parseNumber(v);
        if (!x) return quoted(v) + " is not a number";
        return *x > 0 ? "" : "must be positive, got " + v;
      },
      "POSITIVE");
}

CLI::Validator notNegative() {
  return check(
      [](const std::string& v) {
        const std::optional<double> x = parseNumber(v);
        if (!x) return quoted(v) + " is not a number";
        return *x >= 0 ? "" : "must be 0 or more, got " + v;
      },
      "NUMBER>=0");
}

CLI::Validator wholeIn(long long lo, long long hi) {
  return check(
      [lo, hi](const std::string& v) -> std::string {
        const std::optional<long long> n = readWhole(v);
        if (!n) return quoted(v) + " is not a whole number";
        if (*n >= lo && *n <= hi) return "";
        if (hi == LLONG_MAX) return "must be at least " + std::to_string(lo) + ", got " + v;
        return "must be from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got " + v;
      },
      "WHOLE");
}

CLI::Validator wholeList() {
  return check(
      [](const std::string& v) -> std::string {
        for (size_t start = 0; start <= v.size();) {
          const size_t comma = std::min(v.find(',', start), v.size());
          const std::string item = v.substr(start, comma - start);
          if (!readWhole(item)) return quoted(item) + " is not a whole number";
          start = comma + 1;
        }
        return "";
      },
      "N[,N...]");
}

CLI::Validator numberPair(bool nonZero) {
  return check(
      [nonZero](const std::string& v) -> std::string {
        if (std::string p = pairProblem(v); !p.empty()) return p;
        return nonZero && readPair(v)->isZero(0) ? "must not be 0,0" : "";
      },
      "X,Y");
}

std::optional<Vec3> readDirection(const std::string& text) {
  const size_t last = text.rfind(',');
  const size_t first = text.find(',');
  if (first == last) {
    const std::optional<Vec2> p = readPair(text);
    return p ? std::optional<Vec3>(Vec3(p->x(), p->y(), 0)) : std::nullopt;
  }
  const std::optional<Vec2> p = readPair(text.substr(0, last));
  const std::optional<double> z = parseNumber(text.substr(last + 1));
  return p && z ? std::optional<Vec3>(Vec3(p->x(), p->y(), *z)) : std::nullopt;
}

CLI::Validator direction() {
  return check(
      [](const std::string& v) -> std::string {
        const size_t last = v.rfind(',');
        const bool three = last != std::string::npos && v.find(',') != last;
        if (std::string p = pairProblem(three ? v.substr(0, last) : v); !p.empty()) return p;
        if (three && !parseNumber(v.substr(last + 1)))
          return quoted(v.substr(last + 1)) + " is not a number";
        return readDirection(v)->isZero(0) ? (three ? "must not be 0,0,0" : "must not be 0,0") : "";
      },
      "DX,DY[,DZ]");
}

CLI::Validator increasingPair() {
  return check(
      [](const std::string& v) -> std::string {
        if (std::string p = pairProblem(v); !p.empty()) return p;
        const Vec2 b = *readPair(v);
        return b.x() < b.y() ? "" : "the low end must be below the high end, got " + v;
      },
      "LO,HI");
}

CLI::Validator oneOf(std::vector<std::string> allowed) {
  return check(
      [allowed](const std::string& v) -> std::string {
        std::string list;
        for (size_t i = 0; i < allowed.size(); ++i) {
          if (v == allowed[i]) return "";
          list += (i == 0 ? "" : i + 1 == allowed.size() ? " or " : ", ") + allowed[i];
        }
        return quoted(v) + " is not " + list;
      },
      "WORD");
}

CLI::Validator pixelSize() {
  return check(
      [](const std::string& v) -> std::string {
        if (readSize(v)) return "";
        return quoted(v) + " is not WxH with whole numbers from 50 to 20000";
      },
      "WxH");
}

}  // namespace linkage::cli
