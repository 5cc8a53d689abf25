// The optimiser's variables and targets as text: see linkage/optimize_text.h.
#include "linkage/optimize_text.h"

#include <cmath>
#include <cstring>
#include <fstream>

#include "linkage/elements.h"
#include "linkage/io/numbers.h"
#include "linkage/transmission.h"

namespace linkage {

namespace {

// X,Y or X,Y,Z: the position target's point; nullopt else.
std::optional<std::vector<double>> parseCoordinates(const std::string& s) {
  std::vector<double> out;
  size_t from = 0;
  for (size_t comma = 0; comma != std::string::npos; from = comma + 1) {
    comma = s.find(',', from);
    const std::optional<double> v = parseNumber(s.substr(from, comma - from));
    if (!v) return std::nullopt;
    out.push_back(*v);
  }
  if (out.size() != 2 && out.size() != 3) return std::nullopt;
  return out;
}

// FILE.csv: x,y or x,y,z a line (every line alike); a first line that is not numbers is a
// header.
bool readPath(const std::string& file, OptTarget& t, std::string& why) {
  std::ifstream in(file);
  if (!in) {
    why = file + ": cannot be read";
    return false;
  }
  std::string line;
  bool first = true;  // the first line that is not a comment may be a header
  size_t columns = 0;
  for (int n = 1; std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;  // comments (a source cited, as four-bar-rs does)
    const std::optional<std::vector<double>> p = parseCoordinates(line);
    const bool header = !p && first;
    first = false;
    if (header) continue;
    if (!p || (columns != 0 && p->size() != columns)) {
      why = file + ":" + std::to_string(n) + ": not " +
            (columns == 3   ? "three numbers x,y,z as the lines before"
             : columns == 2 ? "two numbers x,y as the lines before"
                            : "two numbers x,y (or three x,y,z on a machine in space)");
      return false;
    }
    columns = p->size();
    t.path.push_back(Vec2((*p)[0], (*p)[1]));
    if (columns == 3) t.pathZ.push_back((*p)[2]);
  }
  if (t.path.empty()) why = file + ": no points";
  return !t.path.empty();
}

// transmission:[mu:]body.point>=DEG, the joint named as `transmission` names it.
bool parseTransmission(const Mechanism& m, const std::string& text, OptTarget& t,
                       std::string& why) {
  const size_t ge = text.find(">=");
  auto deg = ge == std::string::npos ? std::nullopt : parseNumber(text.substr(ge + 2));
  if (!deg) return why += "expected transmission:mu:body.point>=DEG", false;
  std::string name = text.substr(13, ge - 13);
  if (name.rfind("mu:", 0) != 0) name = "mu:" + name;
  const std::vector<TransmissionJoint> js = transmissionJoints(m);
  for (size_t j = 0; j < js.size(); ++j)
    if (js[j].label == name) {
      t.kind = OptTarget::Kind::Transmission;
      t.joint = j;
      t.limitDeg = *deg;
      t.point = m.joint(js[j].joint)->a;
      return true;
    }
  std::string known;
  for (const TransmissionJoint& j : js) known += (known.empty() ? "" : ", ") + j.label;
  return why += "no transmission angle '" + name + "' (the model's: " + known + ")", false;
}

// shaking:fx<=N (fy, fz on a machine in space, force; moment<=N m)
bool parseShaking(const std::string& text, OptTarget& t, std::string& why) {
  const std::string usage = "expected shaking:fx<=N (fx, fy, fz, force or moment; N (m) >= 0)";
  const size_t le = text.find("<=");
  if (le == std::string::npos) return why += usage, false;
  const std::string what = text.substr(8, le - 8);
  const std::optional<double> n = parseNumber(text.substr(le + 2));
  if (!n.has_value() || !(n.value() >= 0) ||
      (what != "fx" && what != "fy" && what != "fz" && what != "force" && what != "moment"))
    return why += usage, false;
  t.kind = OptTarget::Kind::Shaking;
  t.moment = what == "moment";
  t.measure = what == "fx"   ? BalanceMeasure::Fx
              : what == "fy" ? BalanceMeasure::Fy
              : what == "fz" ? BalanceMeasure::Fz
                             : BalanceMeasure::Force;
  t.limitN = n.value();
  return true;
}

std::string shakingName(const OptTarget& t) {
  if (t.moment) return "moment";
  return t.measure == BalanceMeasure::Fx   ? "fx"
         : t.measure == BalanceMeasure::Fy ? "fy"
         : t.measure == BalanceMeasure::Fz ? "fz"
                                           : "force";
}

// The part of a reaction a force target names after its joint: none, :fn or :tilt.
constexpr struct {
  const char* suffix;
  OptTarget::Reaction part;
} kReactionParts[] = {{":fn", OptTarget::Reaction::Normal}, {":tilt", OptTarget::Reaction::Tilt}};

// force:KIND:body.point<=N (:fn<=N, :tilt<=NM), the joint named as dynamics' columns name it
bool parseForce(const Mechanism& m, const std::string& text, OptTarget& t, std::string& why) {
  const size_t le = text.find("<=");
  const std::optional<double> n =
      le == std::string::npos ? std::nullopt : parseNumber(text.substr(le + 2));
  if (!n.has_value() || !(n.value() >= 0))
    return why +=
           "expected force:JOINT<=N (JOINT as dynamics names it, pin:crank.A; "
           "force:JOINT:fn<=N, force:JOINT:tilt<=NM out of its plane)",
           false;
  std::string name = text.substr(6, le - 6);
  t.reaction = OptTarget::Reaction::InPlane;
  for (const auto& [suffix, part] : kReactionParts)
    if (const size_t at = name.rfind(suffix);
        at != std::string::npos && at + std::strlen(suffix) == name.size()) {
      t.reaction = part;
      name.resize(at);
      break;
    }
  std::string known;
  for (size_t j = 0; j < m.joints.size(); ++j) {
    const std::string label =
        std::string(kindOf(m.joints[j]).name) + ":" + m.pointLabel(m.joints[j].a);
    known += (known.empty() ? "" : ", ") + label;
    if (label != name) continue;
    t.kind = OptTarget::Kind::Force;
    t.index = j;
    t.measure = BalanceMeasure::Force;
    t.limitN = n.value();
    return true;
  }
  return why += "no joint '" + name + "' (the model's: " + known + ")", false;
}

// clearance:N>=GAP
bool parseClearance(const std::string& text, OptTarget& t, std::string& why) {
  const std::string usage = "expected clearance:N>=GAP (N the file's clearance, from 0; GAP mm)";
  const size_t ge = text.find(">=");
  if (ge == std::string::npos) return why += usage, false;
  const std::optional<double> n = parseNumber(text.substr(10, ge - 10)),
                              gap = parseNumber(text.substr(ge + 2));
  if (!n.has_value() || !gap.has_value() || !(n.value() >= 0) || n.value() != std::floor(*n) ||
      !(gap.value() >= 0))
    return why += usage, false;
  t.kind = OptTarget::Kind::Clearance;
  t.index = static_cast<size_t>(n.value());
  t.gapMm = gap.value();
  return true;
}

// window:NAME.start=DEG, window:NAME.end=DEG
bool parseWindow(const std::string& text, OptTarget& t, std::string& why) {
  const std::string usage = "expected window:NAME.start=DEG or window:NAME.end=DEG";
  const size_t eq = text.rfind('=');
  if (eq == std::string::npos) return why += usage, false;
  const size_t dot = text.rfind('.', eq);
  const std::optional<double> deg = parseNumber(text.substr(eq + 1));
  if (dot == std::string::npos || dot <= 7 || !deg.has_value()) return why += usage, false;
  const std::string end = text.substr(dot + 1, eq - dot - 1);
  if (end != "start" && end != "end") return why += usage, false;
  t.kind = OptTarget::Kind::Window;
  t.window = text.substr(7, dot - 7);
  t.windowEnd = end == "end";
  t.crankDeg = deg.value();
  return true;
}

}  // namespace

std::optional<Vec3> parseDirection(const std::string& text) {
  if (text == "x") return Vec3::UnitX();
  if (text == "y") return Vec3::UnitY();
  if (text == "z") return Vec3::UnitZ();
  const std::optional<std::vector<double>> d = parseCoordinates(text);
  if (!d) return std::nullopt;
  const Vec3 v((*d)[0], (*d)[1], d->size() == 3 ? (*d)[2] : 0.0);
  // A length that overflows would normalise to nothing.
  if (!std::isfinite(v.norm()) || v.isZero()) return std::nullopt;
  return v;
}

std::string directionName(const Vec3& d) {
  if (d == Vec3::UnitX()) return "x";
  if (d == Vec3::UnitY()) return "y";
  if (d == Vec3::UnitZ()) return "z";
  return formatNumber(d.x()) + "," + formatNumber(d.y()) + "," + formatNumber(d.z());
}

bool parseOptVary(const std::string& text, OptVariable& v) {
  const size_t eq = text.rfind('='), colon = text.rfind(':');
  if (eq == std::string::npos || colon == std::string::npos || colon < eq) return false;
  auto lo = parseNumber(text.substr(eq + 1, colon - eq - 1)),
       hi = parseNumber(text.substr(colon + 1));
  if (!lo || !hi) return false;
  v = {text.substr(0, eq), *lo, *hi};
  return true;
}

// KIND:body.point=VALUE[*WEIGHT]
bool parseOptTarget(const Mechanism& m, std::string text, OptTarget& t, std::string& why) {
  why = "--target " + text + ": ";
  if (const size_t star = text.rfind('*'); star != std::string::npos) {
    auto w = parseNumber(text.substr(star + 1));
    if (!w || !(*w > 0)) return why += "the weight after * must be a positive number", false;
    t.weight = *w;
    text = text.substr(0, star);
  }
  if (text.rfind("transmission:", 0) == 0) return parseTransmission(m, text, t, why);
  if (text.rfind("shaking:", 0) == 0) return parseShaking(text, t, why);
  if (text.rfind("clearance:", 0) == 0) return parseClearance(text, t, why);
  if (text.rfind("force:", 0) == 0) return parseForce(m, text, t, why);
  if (text.rfind("window:", 0) == 0) return parseWindow(text, t, why);
  const size_t colon = text.find(':'), eq = text.find('=');
  if (colon == std::string::npos || eq == std::string::npos || eq < colon)
    return why += "expected KIND:body.point=VALUE", false;
  const std::string kind = text.substr(0, colon), value = text.substr(eq + 1);
  std::string point = text.substr(colon + 1, eq - colon - 1);
  if (kind == "position") {
    const size_t at = point.find('@');
    auto deg = at == std::string::npos ? std::nullopt : parseNumber(point.substr(at + 1));
    const std::optional<std::vector<double>> xyz = parseCoordinates(value);
    if (!deg || !xyz)
      return why += "expected position:body.point@DEG=X,Y (X,Y,Z on a machine in space)", false;
    t.kind = OptTarget::Kind::Position;
    t.crankDeg = *deg;
    t.at = Vec2((*xyz)[0], (*xyz)[1]);
    if (xyz->size() == 3) t.z = (*xyz)[2];
    point = point.substr(0, at);
  } else if (kind == "stroke") {
    auto mm = parseNumber(value);
    if (!mm || !(*mm >= 0)) return why += "the stroke must be a number >= 0", false;
    t.kind = OptTarget::Kind::Stroke;
    t.stroke = *mm;
    if (const size_t at = point.find('@'); at != std::string::npos) {
      t.direction = parseDirection(point.substr(at + 1));
      if (!t.direction)
        return why += "expected stroke:body.point@DIR=MM, DIR x, y, z or DX,DY[,DZ] (not 0)", false;
      point = point.substr(0, at);
    }
  } else if (kind == "path") {
    t.kind = OptTarget::Kind::Path;
    std::string fileWhy;
    if (!readPath(value, t, fileWhy)) return why += fileWhy, false;
  } else {
    return why += "unknown kind '" + kind +
                  "' (stroke, position, path, transmission, shaking, force, clearance, window)",
           false;
  }
  std::optional<PointId> p = m.findPoint(point);
  if (!p) return why += "no point '" + point + "' in the model", false;
  t.point = *p;
  return true;
}

std::string optTargetName(const Mechanism& m, const OptTarget& t) {
  if (t.kind == OptTarget::Kind::Shaking) return shakingName(t);
  if (t.kind == OptTarget::Kind::Clearance) return "clearance " + std::to_string(t.index);
  if (t.kind == OptTarget::Kind::Force) {
    std::string name =
        std::string(kindOf(m.joints[t.index]).name) + ":" + m.pointLabel(m.joints[t.index].a);
    for (const auto& [suffix, part] : kReactionParts)
      if (t.reaction == part) name += suffix;
    return name;
  }
  if (t.kind == OptTarget::Kind::Window) return t.window + (t.windowEnd ? ".end" : ".start");
  std::string name = m.pointLabel(t.point);
  if (t.kind == OptTarget::Kind::Position) name.append("@").append(formatNumber(t.crankDeg));
  if (t.kind == OptTarget::Kind::Stroke && t.direction)
    name.append("@").append(directionName(*t.direction));
  if (t.kind == OptTarget::Kind::Transmission) name.insert(0, "mu:");
  return name;
}

}  // namespace linkage
