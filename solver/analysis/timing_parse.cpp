// Outputs and windows as a user writes them: see linkage/timing.h.
#include <charconv>
#include <cmath>

#include "linkage/timing.h"

namespace linkage {

namespace {

// A number, locale-independent and strict (no spaces, no trailing characters).
std::optional<double> numberOf(const std::string& t) {
  double v = 0;
  const char* end = t.data() + t.size();
  const auto [p, ec] = std::from_chars(t.data(), end, v);
  if (t.empty() || ec != std::errc() || p != end || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<Vec2> directionOf(const std::string& t) {
  const size_t comma = t.find(',');
  if (comma == std::string::npos) return std::nullopt;
  const std::optional<double> x = numberOf(t.substr(0, comma)), y = numberOf(t.substr(comma + 1));
  if (!x || !y || (*x == 0 && *y == 0)) return std::nullopt;
  return Vec2(*x, *y).normalized();
}

bool fail(std::string* why, std::string text) {
  if (why) *why = std::move(text);
  return false;
}

}  // namespace

std::optional<CycleOutput> parseOutput(const Mechanism& m, const std::string& text,
                                       std::string* why) {
  const size_t colon = text.rfind(':');
  if (colon == std::string::npos) {
    fail(why, "\"" + text + "\" is not body.point:y, body.point:x, body.point:DX,DY or body:angle");
    return std::nullopt;
  }
  const std::string target = text.substr(0, colon), what = text.substr(colon + 1);
  CycleOutput o;
  o.name = text;
  if (what == "angle") {
    const Body* b = m.bodyNamed(target);
    if (!b) {
      fail(why, "no body \"" + target + "\" (an angle is of a body: body:angle)");
      return std::nullopt;
    }
    o.measure = LimitMeasure::angleOf(b->id);
    return o;
  }
  const std::optional<PointId> p = m.findPoint(target);
  if (!p) {
    fail(why, "no point \"" + target + "\" (body.point)");
    return std::nullopt;
  }
  std::optional<Vec2> d;
  if (what == "x")
    d = Vec2(1, 0);
  else if (what == "y")
    d = Vec2(0, 1);
  else
    d = directionOf(what);
  if (!d) {
    fail(why, "\"" + what + "\" after \"" + target +
                  ":\" is not x, y, angle or a direction DX,DY other than 0,0");
    return std::nullopt;
  }
  o.measure = LimitMeasure::along(*p, *d);
  return o;
}

std::optional<CycleWindow> parseWindow(const Mechanism& m, const std::string& text,
                                       std::string* why) {
  const size_t eq = text.find('=');
  const std::string name = eq == std::string::npos ? "" : text.substr(0, eq);
  if (name.empty() || name.find_first_of(",+ \t<>:") != std::string::npos) {
    fail(why, "\"" + text +
                  "\" is not NAME=OUTPUT<VALUE or NAME=OUTPUT>VALUE (a NAME without "
                  "',', '+', ':', '<', '>' or spaces)");
    return std::nullopt;
  }
  const std::string rest = text.substr(eq + 1);
  const size_t op = rest.find_first_of("<>");
  if (op == std::string::npos) {
    fail(why, "\"" + rest + "\" has no '<' or '>' (OUTPUT<VALUE or OUTPUT>VALUE)");
    return std::nullopt;
  }
  CycleWindow w;
  w.name = name;
  w.below = rest[op] == '<';
  const std::string value = rest.substr(op + 1);
  const std::optional<double> level = numberOf(value);
  if (!level) {
    fail(why, "\"" + value + "\" after '" + rest[op] + "' is not a number");
    return std::nullopt;
  }
  w.level = *level;
  std::optional<CycleOutput> o = parseOutput(m, rest.substr(0, op), why);
  if (!o) return std::nullopt;
  w.output = *o;
  return w;
}

}  // namespace linkage
