#include "linkage/timing_text.h"
#include "linkage/space.h"

#include <algorithm>
#include <charconv>
#include <cmath>

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

// A unit vector that normalising leaves as it is, so that the text a file keeps of it (its
// shortest digits, which read back to the same doubles) reads back to the same direction:
// normalising once may leave a vector one rounding off length 1, which the next would change.
template <class V>
V unitOf(V v) {
  for (int i = 0; i < 8; ++i) {
    const V n = v.normalized();
    if (n == v) break;
    v = n;
  }
  return v;
}

std::optional<Vec2> directionOf(const std::string& t) {
  const size_t comma = t.find(',');
  if (comma == std::string::npos) return std::nullopt;
  const std::optional<double> x = numberOf(t.substr(0, comma)), y = numberOf(t.substr(comma + 1));
  if (!x || !y || (*x == 0 && *y == 0)) return std::nullopt;
  return unitOf(Vec2(*x, *y));
}

bool fail(std::string* why, std::string text) {
  if (why) *why = std::move(text);
  return false;
}

std::string quoted(const std::string& s) {
  return "\"" + s + "\"";
}

// DX,DY,DZ (a machine in space), unit; nullopt for anything else or 0,0,0.
std::optional<Vec3> directionOf3(const std::string& t) {
  const size_t a = t.find(','), b = a == std::string::npos ? a : t.find(',', a + 1);
  if (b == std::string::npos) return std::nullopt;
  const std::optional<double> x = numberOf(t.substr(0, a)),
                              y = numberOf(t.substr(a + 1, b - a - 1)),
                              z = numberOf(t.substr(b + 1));
  if (!x || !y || !z || (*x == 0 && *y == 0 && *z == 0)) return std::nullopt;
  return unitOf(Vec3(*x, *y, *z));
}

// body.point:distance:body.point, nullopt when `text` is not of that form.
std::optional<LimitMeasure> distanceMeasure(const Mechanism& m, const std::string& text,
                                            std::string* why, bool& asked) {
  static const std::string key = ":distance:";
  const size_t at = text.find(key);
  asked = at != std::string::npos;
  if (!asked) return std::nullopt;
  const std::string a = text.substr(0, at), b = text.substr(at + key.size());
  const std::optional<PointId> p = m.findPoint(a), q = m.findPoint(b);
  if (!p || !q) {
    fail(why, "no point " + quoted(p ? b : a) +
                  " (a distance is between two points: " + "body.point:distance:body.point)");
    return std::nullopt;
  }
  if (*p == *q) {
    fail(why, quoted(text) + " is a point's distance to itself");
    return std::nullopt;
  }
  return LimitMeasure::distance(*p, *q);
}

std::string measureProblem(const Mechanism& m, const LimitMeasure& x) {
  if (x.body) return m.contains(x.body) ? "" : "the body is not in the mechanism";
  if (!m.contains(x.point)) return "the point is not in the mechanism";
  if (x.other) {
    if (!m.contains(x.other)) return "the other point is not in the mechanism";
    return x.other == x.point ? "a point's distance to itself" : "";
  }
  if (!x.direction3().allFinite() || std::abs(x.direction3().norm() - 1) > 1e-12)
    return "the direction is not a unit vector";
  if (x.dz != 0 && !isSpatial(m))
    return "a direction with a z component is of a machine in space (this one is planar)";
  return "";
}

std::string windowsProblem(const Mechanism& m, const Timing& t) {
  for (size_t i = 0; i < t.windows.size(); ++i) {
    const TimingWindow& w = t.windows[i];
    const std::string at = "timing.windows[" + std::to_string(i) + "]: ";
    if (!validWindowName(w.name)) return at + "the name " + quoted(w.name) + " is not valid";
    for (size_t j = 0; j < i; ++j)
      if (t.windows[j].name == w.name) return at + "a second window named " + quoted(w.name);
    if (std::string p = measureProblem(m, w.output); !p.empty()) return at + p;
    if (!std::isfinite(w.level)) return at + "the level is not a number";
  }
  return "";
}

std::string conflictsProblem(const Timing& t) {
  auto known = [&](const std::string& n) {
    return std::any_of(t.windows.begin(), t.windows.end(),
                       [&](const TimingWindow& w) { return w.name == n; });
  };
  for (size_t i = 0; i < t.conflicts.size(); ++i) {
    const TimingConflict& c = t.conflicts[i];
    const std::string at = "timing.conflicts[" + std::to_string(i) + "]: ";
    for (const std::string* n : {&c.first, &c.second})
      if (!known(*n)) return at + "no window named " + quoted(*n);
    if (c.first == c.second) return at + "a window cannot conflict with itself";
  }
  return "";
}

std::string clearancesProblem(const Mechanism& m, const Timing& t) {
  for (size_t i = 0; i < t.clearances.size(); ++i) {
    const ClearanceWatch& c = t.clearances[i];
    const std::string at = "timing.clearances[" + std::to_string(i) + "]: ";
    if (!m.contains(c.point)) return at + "the point is not in the mechanism";
    if (std::string p = clearancePartProblem(m, c.point, c.other); !p.empty()) return at + p;
    if (c.minMm && !(std::isfinite(*c.minMm) && *c.minMm >= 0))
      return at + "the minimum is not a number >= 0";
  }
  return "";
}

}  // namespace

std::string shortestText(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

bool validWindowName(const std::string& name) {
  if (name.empty() || name.find_first_of(",+:<>=\" ") != std::string::npos) return false;
  // Control characters (a newline would end a CSV row) are no part of a name either.
  return std::none_of(name.begin(), name.end(),
                      [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
}

std::optional<LimitMeasure> parseMeasure(const Mechanism& m, const std::string& text,
                                         std::string* why) {
  bool distance = false;
  std::optional<LimitMeasure> d = distanceMeasure(m, text, why, distance);
  if (distance) return d;
  const size_t colon = text.rfind(':');
  if (colon == std::string::npos) {
    fail(why, quoted(text) +
                  " is not body.point:y, body.point:x, body.point:DX,DY, body:angle or "
                  "body.point:distance:body.point (in space also body.point:z, "
                  "body.point:DX,DY,DZ)");
    return std::nullopt;
  }
  const std::string target = text.substr(0, colon), what = text.substr(colon + 1);
  if (what == "angle") {
    if (const Body* b = m.bodyNamed(target)) return LimitMeasure::angleOf(b->id);
    fail(why, "no body " + quoted(target) + " (an angle is of a body: body:angle)");
    return std::nullopt;
  }
  const std::optional<PointId> p = m.findPoint(target);
  if (!p) {
    fail(why, "no point " + quoted(target) + " (body.point)");
    return std::nullopt;
  }
  if (isSpatial(m)) {
    std::optional<Vec3> d3 = what == "z" ? Vec3(0, 0, 1) : directionOf3(what);
    if (d3) return LimitMeasure::alongInSpace(*p, *d3);
  }
  std::optional<Vec2> dir = what == "x" ? Vec2(1, 0) : what == "y" ? Vec2(0, 1) : directionOf(what);
  if (!dir) {
    fail(why, quoted(what) + " after " + quoted(target + ":") +
                  (isSpatial(m) ? " is not x, y, z, angle or a direction DX,DY or DX,DY,DZ other "
                                  "than 0"
                                : " is not x, y, angle or a direction DX,DY other than 0,0"));
    return std::nullopt;
  }
  return LimitMeasure::along(*p, *dir);
}

std::string measureText(const Mechanism& m, const LimitMeasure& x) {
  if (x.body) {
    const Body* b = m.body(x.body);
    return (b ? b->name : "?") + ":angle";
  }
  const std::string p = m.contains(x.point) ? m.pointLabel(x.point) : "?";
  if (x.other) return p + ":distance:" + (m.contains(x.other) ? m.pointLabel(x.other) : "?");
  if (x.dz != 0) {
    if (x.direction3() == Vec3(0, 0, 1)) return p + ":z";
    return p + ":" + shortestText(x.direction.x()) + "," + shortestText(x.direction.y()) + "," +
           shortestText(x.dz);
  }
  if (x.direction == Vec2(1, 0)) return p + ":x";
  if (x.direction == Vec2(0, 1)) return p + ":y";
  return p + ":" + shortestText(x.direction.x()) + "," + shortestText(x.direction.y());
}

std::optional<TimingWindow> parseTimingWindow(const Mechanism& m, const std::string& text,
                                              std::string* why) {
  const size_t eq = text.find('=');
  const std::string name = eq == std::string::npos ? "" : text.substr(0, eq);
  if (!validWindowName(name)) {
    fail(why, quoted(text) +
                  " is not NAME=OUTPUT<VALUE or NAME=OUTPUT>VALUE (a NAME without "
                  "',', '+', ':', '<', '>', '\"', spaces or control characters)");
    return std::nullopt;
  }
  const std::string rest = text.substr(eq + 1);
  const size_t op = rest.find_first_of("<>");
  if (op == std::string::npos) {
    fail(why, quoted(rest) + " has no '<' or '>' (OUTPUT<VALUE or OUTPUT>VALUE)");
    return std::nullopt;
  }
  TimingWindow w;
  w.name = name;
  w.below = rest[op] == '<';
  const std::string value = rest.substr(op + 1);
  const std::optional<double> level = numberOf(value);
  if (!level) {
    fail(why, quoted(value) + " after '" + rest[op] + "' is not a number");
    return std::nullopt;
  }
  w.level = *level;
  std::optional<LimitMeasure> o = parseMeasure(m, rest.substr(0, op), why);
  if (!o) return std::nullopt;
  w.output = *o;
  return w;
}

std::string windowText(const Mechanism& m, const TimingWindow& w) {
  return w.name + "=" + measureText(m, w.output) + (w.below ? "<" : ">") + shortestText(w.level);
}

std::optional<ClearancePart> parseClearancePart(const Mechanism& m, const std::string& text,
                                                std::string* why) {
  if (std::optional<PointId> p = m.findPoint(text)) return ClearancePart::of(*p);
  const size_t dot = text.rfind('.');
  const Body* b = dot == std::string::npos ? nullptr : m.bodyNamed(text.substr(0, dot));
  if (b) {
    const std::string name = text.substr(dot + 1);
    if (const Slot* s = m.slotNamed(b->id, name)) return ClearancePart::of(s->id);
    // body.P-Q: a '-' between two of the body's points (points may have '-' in their names).
    for (size_t dash = name.find('-'); dash != std::string::npos; dash = name.find('-', dash + 1)) {
      const Point* p = m.pointNamed(b->id, name.substr(0, dash));
      const Point* q = m.pointNamed(b->id, name.substr(dash + 1));
      if (p && q) {
        if (p->id == q->id) break;
        return ClearancePart::segment(p->id, q->id);
      }
    }
  }
  fail(why, "no point, segment or slot " + quoted(text) +
                " (body.point, body.P-Q: the segment between two points of a body, or body.slot)");
  return std::nullopt;
}

std::string clearancePartProblem(const Mechanism& m, PointId point, const ClearancePart& other) {
  if (other.isSlot() + other.isPoint() + other.isSegment() != 1 || (other.slot && other.point))
    return "a second point, a segment or a slot, one of them";
  const bool there = other.isSlot()
                         ? m.contains(other.slot)
                         : m.contains(other.point) && (!other.end || m.contains(other.end));
  if (!there) return "the other point, segment or slot is not in the mechanism";
  if (other.point == point || other.end == point) return "a point's clearance to itself";
  const BodyId pointBody = m.point(point)->body;
  if (other.isSegment()) {
    const Point &a = *m.point(other.point), &b = *m.point(other.end);
    if (a.body != b.body) return "a segment's two ends must be points of one body";
    if (!((a.pos - b.pos).norm() > 1e-9)) return "a segment's two ends are in one place";
  }
  const BodyId otherBody = other.isSlot() ? m.slot(other.slot)->body : m.point(other.point)->body;
  if (!other.isPoint() && otherBody == pointBody)
    return "the point " + m.pointLabel(point) + " is on the body of " + m.partDescription(other) +
           ": their distance does not change";
  return "";
}

std::string timingProblem(const Mechanism& m, const Timing& t) {
  for (size_t i = 0; i < t.outputs.size(); ++i)
    if (std::string p = measureProblem(m, t.outputs[i]); !p.empty())
      return "timing.outputs[" + std::to_string(i) + "]: " + p;
  if (std::string p = windowsProblem(m, t); !p.empty()) return p;
  if (std::string p = conflictsProblem(t); !p.empty()) return p;
  return clearancesProblem(m, t);
}

}  // namespace linkage
