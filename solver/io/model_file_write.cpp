// Writing mechanism files, and comparing mechanisms the way a file sees them.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <span>
#include <unordered_map>

#include "io/json_tree.h"
#include "linkage/elements.h"
#include "linkage/io/model_file.h"
#include "linkage/timing_text.h"

namespace linkage {

namespace {

using Json = nlohmann::ordered_json;

// Whole numbers are written without a fraction ("10", not "10.0") and -0 as 0; the rest in
// nlohmann's shortest form that reads back to the same double.
Json number(double v) {
  if (v == 0) return 0;
  if (std::trunc(v) == v && std::fabs(v) < 9007199254740992.0) return static_cast<std::int64_t>(v);
  return v;
}

Json pair(const Vec2& p) {
  return Json::array({number(p.x()), number(p.y())});
}

// Extras as a JSON object; an empty object when there are none, or when the text is not an object
// the reader would accept (as can happen only when a program set it by hand).
Json parseExtras(const Extras& text) {
  Json parsed;
  std::string error;
  if (text.empty() || !json_tree::parse(text, parsed, error) || !parsed.is_object())
    return Json::object();
  return parsed;
}

// A key the reader would take for a known field must not come back from Extras.
void appendExtras(Json& obj, const Extras& extras, std::span<const char* const> known) {
  Json e = parseExtras(extras);
  for (auto it = e.begin(); it != e.end(); ++it) {
    bool isKnown = false;
    for (const char* k : known) isKnown = isKnown || it.key() == k;
    if (!isKnown) json_tree::appendMember(obj, it.key(), it.value());
  }
}

void appendExtras(Json& obj, const Extras& extras, std::initializer_list<const char*> known) {
  appendExtras(obj, extras, std::span<const char* const>(known.begin(), known.size()));
}

std::string scalar(const Json& v) {
  return v.dump(-1, ' ', false, Json::error_handler_t::replace);
}

// Short arrays of scalars or of such arrays ([x, y], [[x0, y0], [x1, y1]]) stay on one line.
bool inlineText(const Json& v, std::string& out) {
  std::string text = "[";
  for (size_t i = 0; i < v.size(); ++i) {
    if (text.size() > 80) return false;
    if (i > 0) text += ", ";
    const Json& e = v[i];
    if (e.is_array()) {
      text += "[";
      for (size_t k = 0; k < e.size(); ++k) {
        if (e[k].is_structured()) return false;
        text += (k > 0 ? ", " : "") + scalar(e[k]);
      }
      text += "]";
    } else if (e.is_object()) {
      return false;
    } else {
      text += scalar(e);
    }
  }
  text += "]";
  if (text.size() > 80) return false;
  out += text;
  return true;
}

void emit(const Json& v, size_t indent, std::string& out) {
  const std::string pad(indent + 2, ' ');
  if (v.is_object()) {
    if (v.empty()) {
      out += "{}";
      return;
    }
    out += "{\n";
    size_t i = 0;
    for (auto it = v.begin(); it != v.end(); ++it, ++i) {
      out += pad + scalar(Json(it.key())) + ": ";
      emit(it.value(), indent + 2, out);
      out += i + 1 < v.size() ? ",\n" : "\n";
    }
    out += std::string(indent, ' ') + "}";
  } else if (v.is_array()) {
    if (v.empty()) {
      out += "[]";
      return;
    }
    if (inlineText(v, out)) return;
    out += "[\n";
    for (size_t i = 0; i < v.size(); ++i) {
      out += pad;
      emit(v[i], indent + 2, out);
      out += i + 1 < v.size() ? ",\n" : "\n";
    }
    out += std::string(indent, ' ') + "]";
  } else {
    out += scalar(v);
  }
}

struct BodyContents {
  std::vector<const Point*> points;
  std::vector<const Slot*> slots;
};

// [x, y], or [x, y, third] when a third number was written.
Json coordinates(const Vec2& p, const std::optional<double>& third) {
  Json j = pair(p);
  if (third) j.push_back(number(*third));
  return j;
}

Json slotJson(const Slot& s) {
  std::vector<Vec2> ends{s.p0};
  if (s.mid) ends.push_back(*s.mid);
  ends.push_back(s.p1);
  Json j = Json::array();
  for (size_t k = 0; k < ends.size(); ++k)
    j.push_back(coordinates(ends[k], k < s.z.size() ? std::optional(s.z[k]) : std::nullopt));
  return j;
}

Json bodyJson(const Body& b, const BodyContents& contents) {
  Json j = Json::object();
  j["name"] = b.name;
  if (b.ground) j["ground"] = true;
  if (!b.plane.empty()) j["plane"] = b.plane;
  if (b.number) j["number"] = *b.number;
  Json points = Json::object();
  for (const Point* p : contents.points)
    json_tree::appendMember(points, p->name, coordinates(p->pos, p->third));
  j["points"] = std::move(points);
  Json slots = Json::object();
  for (const Slot* s : contents.slots) json_tree::appendMember(slots, s->name, slotJson(*s));
  if (!slots.empty()) j["slots"] = std::move(slots);
  if (b.mass) {
    Json mass = Json::object();
    mass["kg"] = number(b.mass->kg);
    mass["com"] = pair(b.mass->com);
    mass["j_kg_mm2"] = number(b.mass->jKgMm2);
    if (!b.mass->counterweights.empty()) {
      Json list = Json::array();
      for (const PointMass& c : b.mass->counterweights) {
        Json e = Json::object();
        e["kg"] = number(c.kg);
        e["at"] = pair(c.at);
        list.push_back(std::move(e));
      }
      mass["counterweights"] = std::move(list);
    }
    appendExtras(mass, b.mass->extras, {"kg", "com", "j_kg_mm2", "counterweights"});
    j["mass"] = std::move(mass);
  }
  appendExtras(j, b.extras, {"name", "ground", "plane", "number", "points", "slots", "mass"});
  return j;
}

// "body.name" for every point and slot at once: Mechanism's own lookups are linear.
struct Labels {
  std::unordered_map<std::uint32_t, std::string> points, slots, bodies;
  explicit Labels(const Mechanism& m) {
    for (const Body& b : m.bodies) bodies[b.id.value] = b.name;
    std::unordered_map<std::uint32_t, const std::string*> bodyNames;
    for (const Body& b : m.bodies) bodyNames[b.id.value] = &b.name;
    auto label = [&](BodyId b, const std::string& name) {
      auto it = bodyNames.find(b.value);
      return (it == bodyNames.end() ? std::string("?") : *it->second) + "." + name;
    };
    for (const Point& p : m.points) points[p.id.value] = label(p.body, p.name);
    for (const Slot& s : m.slots) slots[s.id.value] = label(s.body, s.name);
  }
  // Dangling ids are written as "?" (as Mechanism::pointLabel does); such a file will not load.
  static std::string of(const std::unordered_map<std::uint32_t, std::string>& map,
                        std::uint32_t id) {
    auto it = map.find(id);
    return it == map.end() ? "?" : it->second;
  }
};

// A structured field's records, their members as read (numbers written as every number is).
Json recordsJson(const std::vector<Record>& records) {
  Json out = Json::array();
  for (const Record& r : records) {
    Json o = Json::object();
    for (const RecordMember& x : r) {
      Json v = std::holds_alternative<double>(x.value) ? number(std::get<double>(x.value))
                                                       : Json(std::get<std::string>(x.value));
      json_tree::appendMember(o, x.key, std::move(v));
    }
    out.push_back(std::move(o));
  }
  return out;
}

// The fields the joint's kind reads, in its order (an optional body, an optional number not
// given and a flag not set left out).
Json jointJson(const Labels& labels, const Joint& jt) {
  Json j = Json::object();
  j["type"] = toString(jt.type);
  for (const FieldSpec& f : kindOf(jt).fields) {
    switch (f.type) {
      case FieldType::Point:
        j[f.key] = Labels::of(labels.points, pointField(jt, f).value);
        break;
      case FieldType::Slot:
        j[f.key] = Labels::of(labels.slots, jt.slot.value);
        break;
      case FieldType::Body:
        if (jt.carrier) j[f.key] = Labels::of(labels.bodies, jt.carrier.value);
        break;
      case FieldType::Number:
        if (f.required || jt.given(f.index)) j[f.key] = number(jt.number(f.index));
        break;
      case FieldType::Flag:
        if (jt.number(f.index) != 0) j[f.key] = true;
        break;
      case FieldType::Records:
        j[f.key] = recordsJson(jt.recordsAt(f.index));
        break;
    }
  }
  std::vector<const char*> known{"type"};
  for (const char* key : elementFieldKeys()) known.push_back(key);
  appendExtras(j, jt.extras, known);
  return j;
}

Json loadJson(const Labels& labels, const Load& l) {
  Json j = Json::object();
  if (l.point) {
    j["point"] = Labels::of(labels.points, l.point.value);
    j["force_N"] = pair(l.forceN);
  } else {
    j["body"] = Labels::of(labels.bodies, l.body.value);
    j["torque_Nm"] = number(l.torqueNm);
  }
  if (l.fromDeg && l.toDeg) {
    j["from_deg"] = number(*l.fromDeg);
    j["to_deg"] = number(*l.toDeg);
  }
  appendExtras(j, l.extras, {"point", "body", "force_N", "torque_Nm", "from_deg", "to_deg"});
  return j;
}

// The entries with the bodies that are still there (an entry whose bodies were all removed
// names nothing and is dropped).
Json mechanismsJson(const Mechanism& m) {
  Json out = Json::array();
  std::vector<BodyId> written;  // a body in one entry only, as the reader requires
  for (const MechanismEntry& e : m.mechanismEntries) {
    Json bodies = Json::array();
    for (BodyId id : e.bodies)
      if (const Body* b = m.body(id);
          b && std::find(written.begin(), written.end(), id) == written.end()) {
        bodies.push_back(b->name);
        written.push_back(id);
      }
    if (bodies.empty()) continue;
    Json j = Json::object();
    j["bodies"] = std::move(bodies);
    if (!e.name.empty()) j["name"] = e.name;
    if (!e.colour.empty()) j["colour"] = e.colour;
    if (e.hidden) j["hidden"] = true;
    appendExtras(j, e.extras, {"bodies", "name", "colour", "hidden"});
    out.push_back(std::move(j));
  }
  return out;
}

// The cycle diagram's parts as a user types them (linkage/timing_text.h).
Json timingJson(const Mechanism& m) {
  const Timing& t = m.timing;
  Json j = Json::object();
  auto texts = [&](const char* key, const auto& v, auto text) {
    if (v.empty()) return;
    Json a = Json::array();
    for (const auto& x : v) a.push_back(text(x));
    j[key] = std::move(a);
  };
  texts("outputs", t.outputs, [&](const LimitMeasure& x) { return measureText(m, x); });
  texts("windows", t.windows, [&](const TimingWindow& w) { return windowText(m, w); });
  texts("conflicts", t.conflicts, [](const TimingConflict& c) {
    return Json::array({c.first, c.second});
  });
  texts("clearances", t.clearances, [&](const ClearanceWatch& c) {
    Json x = Json::object();
    x["between"] = Json::array({m.pointLabel(c.point), m.partLabel(c.other)});
    if (c.minMm) x["min_mm"] = number(*c.minMm);
    return x;
  });
  appendExtras(j, t.extras, {"outputs", "windows", "conflicts", "clearances"});
  return j;
}

}  // namespace

std::string serializeMechanism(const Mechanism& m) {
  Json doc = Json::object();
  doc["format"] = "linkage";
  doc["version"] = 1;
  if (!m.name.empty()) doc["name"] = m.name;
  Json units = Json::object();
  units["length"] = "mm";
  appendExtras(units, m.unitsExtras, {"length"});
  doc["units"] = std::move(units);
  if (m.planes) {
    Json planes = Json::object();
    for (const Plane& p : *m.planes) {
      Json e = Json::object();
      for (const auto& [key, v] : {std::pair{"origin", &p.origin}, std::pair{"x_axis", &p.xAxis},
                                   std::pair{"y_axis", &p.yAxis}})
        e[key] = Json::array({number(v->x()), number(v->y()), number(v->z())});
      appendExtras(e, p.extras, {"origin", "x_axis", "y_axis"});
      json_tree::appendMember(planes, p.name, std::move(e));
    }
    doc["planes"] = std::move(planes);
  }
  std::unordered_map<std::uint32_t, BodyContents> contents;
  for (const Point& p : m.points) contents[p.body.value].points.push_back(&p);
  for (const Slot& s : m.slots) contents[s.body.value].slots.push_back(&s);
  Json bodies = Json::array();
  for (const Body& b : m.bodies) bodies.push_back(bodyJson(b, contents[b.id.value]));
  doc["bodies"] = std::move(bodies);
  const Labels labels(m);
  Json joints = Json::array();
  for (const Joint& j : m.joints) joints.push_back(jointJson(labels, j));
  doc["joints"] = std::move(joints);
  if (m.driver) {
    const Driver& d = *m.driver;
    Json driver = Json::object();
    driver["joint"] = m.jointIndex(d.joint);
    driver["rpm"] = number(d.rpm);
    driver["direction"] = d.direction == Direction::Cw ? "cw" : "ccw";
    if (d.startDeg != 0) driver["start_deg"] = number(d.startDeg);
    appendExtras(driver, d.extras, {"joint", "rpm", "direction", "start_deg"});
    doc["driver"] = std::move(driver);
  }
  Json outputs = Json::object();
  Json points = Json::array();
  for (PointId p : m.outputs) points.push_back(Labels::of(labels.points, p.value));
  outputs["points"] = std::move(points);
  appendExtras(outputs, m.outputsExtras, {"points"});
  if (!m.outputs.empty() || outputs.size() > 1) doc["outputs"] = std::move(outputs);
  if (m.gravity) doc["gravity"] = coordinates(*m.gravity, m.gravityZ);
  if (!m.loads.empty()) {
    Json loads = Json::array();
    for (const Load& l : m.loads) loads.push_back(loadJson(labels, l));
    doc["loads"] = std::move(loads);
  }
  if (Json e = mechanismsJson(m); !e.empty()) doc["mechanisms"] = std::move(e);
  if (Json t = timingJson(m); !t.empty()) doc["timing"] = std::move(t);
  appendExtras(doc, m.extras,
               {"format", "version", "name", "units", "planes", "bodies", "joints", "driver",
                "outputs", "gravity", "loads", "mechanisms", "timing"});
  std::string out;
  emit(doc, 0, out);
  out += "\n";
  return out;
}

WriteResult saveMechanismFile(const Mechanism& m, const std::string& path) {
  return writeFileAtomically(path, serializeMechanism(m));
}

namespace {

std::string shortest(double v) {
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : "?";
}

std::string compareExtras(const Extras& a, const Extras& b, const std::string& where) {
  if (parseExtras(a) == parseExtras(b)) return {};
  return where + ": unknown fields differ: " + (a.empty() ? "{}" : a) + " vs " +
         (b.empty() ? "{}" : b);
}

std::string compareVec(const Vec2& a, const Vec2& b, const std::string& where) {
  if (a.x() == b.x() && a.y() == b.y()) return {};
  return where + ": [" + shortest(a.x()) + ", " + shortest(a.y()) + "] vs [" + shortest(b.x()) +
         ", " + shortest(b.y()) + "]";
}

template <class T>
std::vector<const T*> ofBody(const std::vector<T>& all, BodyId body) {
  std::vector<const T*> out;
  for (const T& e : all)
    if (e.body == body) out.push_back(&e);
  return out;
}

std::string compareBody(const Mechanism& ma, const Body& a, const Mechanism& mb, const Body& b,
                        const std::string& where) {
  if (a.name != b.name) return where + ".name: \"" + a.name + "\" vs \"" + b.name + "\"";
  if (a.ground != b.ground) return where + ".ground differs";
  if (a.number != b.number) return where + ".number differs";
  if (auto d = compareExtras(a.extras, b.extras, where); !d.empty()) return d;
  auto pa = ofBody(ma.points, a.id), pb = ofBody(mb.points, b.id);
  if (pa.size() != pb.size()) return where + ".points: different number of points";
  for (size_t i = 0; i < pa.size(); ++i) {
    std::string w = where + ".points[" + std::to_string(i) + "]";
    if (pa[i]->name != pb[i]->name)
      return w + ": \"" + pa[i]->name + "\" vs \"" + pb[i]->name + "\"";
    if (auto d = compareVec(pa[i]->pos, pb[i]->pos, w); !d.empty()) return d;
  }
  auto sa = ofBody(ma.slots, a.id), sb = ofBody(mb.slots, b.id);
  if (sa.size() != sb.size()) return where + ".slots: different number of slots";
  for (size_t i = 0; i < sa.size(); ++i) {
    std::string w = where + ".slots[" + std::to_string(i) + "]";
    if (sa[i]->name != sb[i]->name)
      return w + ": \"" + sa[i]->name + "\" vs \"" + sb[i]->name + "\"";
    if (auto d = compareVec(sa[i]->p0, sb[i]->p0, w + ".p0"); !d.empty()) return d;
    if (auto d = compareVec(sa[i]->p1, sb[i]->p1, w + ".p1"); !d.empty()) return d;
    if (sa[i]->arc() != sb[i]->arc()) return w + ": an arc in only one";
    if (sa[i]->mid)
      if (auto d = compareVec(*sa[i]->mid, *sb[i]->mid, w + ".mid"); !d.empty()) return d;
  }
  return {};
}

// The mechanisms' names, colours and visibility, their bodies by name.
std::string compareEntries(const Mechanism& a, const Mechanism& b) {
  if (a.mechanismEntries.size() != b.mechanismEntries.size())
    return "mechanisms: different lengths";
  auto names = [](const Mechanism& m, const MechanismEntry& e) {
    std::vector<std::string> out;
    for (BodyId id : e.bodies)
      if (const Body* body = m.body(id)) out.push_back(body->name);
    return out;
  };
  for (size_t i = 0; i < a.mechanismEntries.size(); ++i) {
    const MechanismEntry &x = a.mechanismEntries[i], &y = b.mechanismEntries[i];
    const std::string w = "mechanisms[" + std::to_string(i) + "]";
    if (names(a, x) != names(b, y) || x.name != y.name || x.colour != y.colour ||
        x.hidden != y.hidden)
      return w + " differs";
    if (auto d = compareExtras(x.extras, y.extras, w); !d.empty()) return d;
  }
  return {};
}

// Masses, gravity, loads.
std::string compareForces(const Mechanism& a, const Mechanism& b) {
  for (size_t i = 0; i < a.bodies.size(); ++i)
    if (a.bodies[i].mass != b.bodies[i].mass)
      return "bodies[" + std::to_string(i) + "].mass differs";
  if (a.gravity != b.gravity || a.gravityZ != b.gravityZ) return "gravity differs";
  if (a.loads.size() != b.loads.size()) return "loads: different lengths";
  for (size_t i = 0; i < a.loads.size(); ++i) {
    const Load &x = a.loads[i], &y = b.loads[i];
    const std::string w = "loads[" + std::to_string(i) + "]";
    const Body *bx = a.body(x.body), *by = b.body(y.body);
    if (a.pointLabel(x.point) != b.pointLabel(y.point) ||
        (bx ? bx->name : "") != (by ? by->name : "") || x.forceN != y.forceN ||
        x.torqueNm != y.torqueNm || x.fromDeg != y.fromDeg || x.toDeg != y.toDeg)
      return w + " differs";
    if (auto d = compareExtras(x.extras, y.extras, w); !d.empty()) return d;
  }
  return {};
}

}  // namespace

std::string mechanismDifference(const Mechanism& a, const Mechanism& b) {
  if (a.name != b.name) return "name: \"" + a.name + "\" vs \"" + b.name + "\"";
  if (auto d = compareExtras(a.extras, b.extras, "top level"); !d.empty()) return d;
  if (auto d = compareExtras(a.unitsExtras, b.unitsExtras, "units"); !d.empty()) return d;
  if (a.bodies.size() != b.bodies.size())
    return "bodies: " + std::to_string(a.bodies.size()) + " vs " + std::to_string(b.bodies.size());
  for (size_t i = 0; i < a.bodies.size(); ++i) {
    auto d = compareBody(a, a.bodies[i], b, b.bodies[i], "bodies[" + std::to_string(i) + "]");
    if (!d.empty()) return d;
  }
  if (a.joints.size() != b.joints.size())
    return "joints: " + std::to_string(a.joints.size()) + " vs " + std::to_string(b.joints.size());
  for (size_t i = 0; i < a.joints.size(); ++i) {
    const Joint &ja = a.joints[i], &jb = b.joints[i];
    std::string w = "joints[" + std::to_string(i) + "]";
    if (ja.type != jb.type) return w + ".type differs";
    if (a.pointLabel(ja.a) != b.pointLabel(jb.a)) return w + ".a differs";
    const ElementKind& kind = kindOf(ja);
    if (kind.reads(FieldType::Point, 1) && a.pointLabel(ja.b) != b.pointLabel(jb.b))
      return w + ".b differs";
    if (kind.reads(FieldType::Slot) && a.slotLabel(ja.slot) != b.slotLabel(jb.slot))
      return w + ".slot differs";
    const Body *ca = a.body(ja.carrier), *cb = b.body(jb.carrier);
    if (kind.reads(FieldType::Body) && (ca ? ca->name : "") != (cb ? cb->name : ""))
      return w + ".carrier differs";
    for (const FieldSpec& f : kind.fields) {
      const bool number = f.type == FieldType::Number;
      if (number && ja.given(f.index) != jb.given(f.index))
        return w + "." + f.key + ": given in only one";
      if ((f.type == FieldType::Flag || (number && ja.given(f.index))) &&
          ja.number(f.index) != jb.number(f.index))
        return w + "." + f.key + ": " + shortest(ja.number(f.index)) + " vs " +
               shortest(jb.number(f.index));
      if (f.type == FieldType::Records && ja.recordsAt(f.index) != jb.recordsAt(f.index))
        return w + "." + f.key + ": " + recordsJson(ja.recordsAt(f.index)).dump() + " vs " +
               recordsJson(jb.recordsAt(f.index)).dump();
    }
    if (auto d = compareExtras(ja.extras, jb.extras, w); !d.empty()) return d;
  }
  if (a.driver.has_value() != b.driver.has_value()) return "driver: present in only one";
  if (a.driver) {
    const Driver &da = *a.driver, &db = *b.driver;
    if (a.jointIndex(da.joint) != b.jointIndex(db.joint)) return "driver.joint differs";
    if (da.rpm != db.rpm) return "driver.rpm: " + shortest(da.rpm) + " vs " + shortest(db.rpm);
    if (da.direction != db.direction) return "driver.direction differs";
    if (da.startDeg != db.startDeg)
      return "driver.start_deg: " + shortest(da.startDeg) + " vs " + shortest(db.startDeg);
    if (auto d = compareExtras(da.extras, db.extras, "driver"); !d.empty()) return d;
  }
  if (a.outputs.size() != b.outputs.size()) return "outputs.points: different lengths";
  for (size_t i = 0; i < a.outputs.size(); ++i)
    if (a.pointLabel(a.outputs[i]) != b.pointLabel(b.outputs[i]))
      return "outputs.points[" + std::to_string(i) + "] differs";
  if (auto d = compareExtras(a.outputsExtras, b.outputsExtras, "outputs"); !d.empty()) return d;
  if (auto d = compareEntries(a, b); !d.empty()) return d;
  if (auto d = compareForces(a, b); !d.empty()) return d;
  // The timing by its text: ids differ between two mechanisms, names and numbers do not.
  if (const std::string x = timingJson(a).dump(), y = timingJson(b).dump(); x != y)
    return "timing: " + x + " vs " + y;
  return {};
}

}  // namespace linkage
