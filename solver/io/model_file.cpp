// Reading mechanism files. Two passes: json_tree builds the JSON tree (refusing duplicate keys,
// overflowing numbers and excessive nesting by place), then a validating pass builds the Mechanism
// and stops at the first problem.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <nlohmann/json.hpp>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "io/forces_read.h"
#include "io/json_read.h"
#include "io/json_tree.h"
#include "io/mechanisms_read.h"
#include "io/timing_read.h"
#include "linkage/elements.h"
#include "linkage/guide.h"
#include "linkage/io/model_file.h"
#include "linkage/space.h"

namespace linkage {

namespace {

using namespace json_read;

class Reader {
 public:
  Mechanism read(const Json& root) {
    if (!root.is_object()) refuse("", "expected a JSON object {...}, got " + describe(root));
    readHeader(root);
    if (const Json* p = find(root, "planes")) readPlanes(*p);
    readBodies(require(root, "bodies", ""));
    if (std::string why = planesProblem(m_); !why.empty()) throw Refusal{why};
    const Json& joints = require(root, "joints", "");
    if (!joints.is_array())
      refuse("joints", "expected an array of joints, got " + describe(joints));
    for (size_t i = 0; i < joints.size(); ++i) readJoint(joints[i], element("joints", i));
    // What each kind checks beyond its references (a gear on its carrier's pins), now that
    // every joint is read.
    if (std::string why = checkJoints(m_); !why.empty()) throw Refusal{why};
    if (const Json* d = find(root, "driver")) readDriver(*d);
    if (const Json* o = find(root, "outputs")) readOutputs(*o);
    if (const Json* g = find(root, "gravity")) m_.gravity = readGravity(*g, "gravity", m_.gravityZ);
    if (const Json* l = find(root, "loads"))
      readLoads(
          *l, "loads", m_,
          [this](const Json& v, const std::string& at) { return readPointRef(v, at).first; },
          [this](const Json& v, const std::string& at) { return bodyRef(v, at); });
    if (const Json* e = find(root, "mechanisms"))
      readMechanismEntries(*e, "mechanisms", m_,
                           [this](const Json& v, const std::string& at) { return bodyRef(v, at); });
    if (const Json* t = find(root, "timing")) readTiming(*t, "timing", m_);
    m_.extras =
        unknownFields(root, {"format", "version", "name", "units", "planes", "bodies", "joints",
                             "driver", "outputs", "gravity", "loads", "mechanisms", "timing"});
    return std::move(m_);
  }

 private:
  struct BodyNames {
    BodyId id;
    std::string name;
    std::unordered_map<std::string, PointId> points;
    std::unordered_map<std::string, SlotId> slots;
  };
  Mechanism m_;
  std::unordered_map<std::string, BodyNames> bodies_;

  BodyId bodyRef(const Json& v, const std::string& at) const {
    const std::string& name = getString(v, at);
    auto it = bodies_.find(name);
    if (it == bodies_.end()) refuse(at, "no body " + literal(name));
    return it->second.id;
  }

  void readHeader(const Json& root) {
    const Json& format = require(root, "format", "");
    if (!format.is_string() || format.get_ref<const std::string&>() != "linkage")
      refuse("format", "expected \"linkage\", got " + describe(format));
    // The version is checked before anything else can fail, so a newer file says so.
    const Json& version = require(root, "version", "");
    long long v = getInteger(version, "version", "the integer 1");
    if (v > 1)
      refuse("version",
             "this file is version " + version.dump() +
                 ", newer than this program reads (version 1); a newer program wrote it");
    if (v < 1) refuse("version", "expected the integer 1, got " + version.dump());
    if (const Json* name = find(root, "name")) m_.name = getString(*name, "name");
    if (const Json* units = find(root, "units")) {
      requireObject(*units, "units");
      if (const Json* length = find(*units, "length")) {
        if (!length->is_string() || length->get_ref<const std::string&>() != "mm")
          refuse("units.length",
                 "expected \"mm\" (the only length unit), got " + describe(*length));
      }
      m_.unitsExtras = unknownFields(*units, {"length"});
    }
  }

  // "planes": {"name": {"origin": [x, y, z], "x_axis": [...], "y_axis": [...]}, ...}; the
  // axes' checks come with the bodies' (planesProblem).
  void readPlanes(const Json& planes) {
    requireObject(planes, "planes");
    m_.planes.emplace();
    for (auto it = planes.begin(); it != planes.end(); ++it) {
      const std::string path = member("planes", it.key());
      requireObject(it.value(), path);
      Plane p;
      p.name = it.key();
      for (const auto& [key, v] : {std::pair{"origin", &p.origin}, std::pair{"x_axis", &p.xAxis},
                                   std::pair{"y_axis", &p.yAxis}}) {
        const Json& x = require(it.value(), key, path);
        if (!x.is_array() || x.size() != 3 || !x[0].is_number() || !x[1].is_number() ||
            !x[2].is_number())
          refuse(path + "." + key,
                 "expected [x, y, z] with three finite numbers, got " + describe(x));
        *v = Vec3(x[0].get<double>(), x[1].get<double>(), x[2].get<double>());
      }
      p.extras = unknownFields(it.value(), {"origin", "x_axis", "y_axis"});
      m_.planes->push_back(std::move(p));
    }
  }

  void readBodies(const Json& bodies) {
    if (!bodies.is_array() || bodies.empty())
      refuse("bodies", "expected a non-empty array of bodies, got " + describe(bodies));
    std::unordered_map<long long, std::string> numbers;
    std::vector<size_t> grounds;
    for (size_t i = 0; i < bodies.size(); ++i) {
      const std::string path = element("bodies", i);
      const Json& b = bodies[i];
      requireObject(b, path);
      const std::string& name = getString(require(b, "name", path), path + ".name");
      checkName(name, path + ".name", "body");
      if (bodies_.count(name)) refuse(path + ".name", "two bodies are named " + literal(name));
      BodyId id = m_.addBody(name);
      Body& body = m_.bodies.back();
      BodyNames& names = bodies_[name];
      names.id = id;
      names.name = name;
      if (const Json* g = find(b, "ground")) {
        if (!g->is_boolean())
          refuse(path + ".ground", "expected true or false, got " + describe(*g));
        body.ground = g->get<bool>();
        if (body.ground) grounds.push_back(i);
      }
      if (const Json* n = find(b, "number")) {
        long long num = getInteger(*n, path + ".number", "an integer >= 1");
        if (num < 1 || num > INT_MAX)
          refuse(path + ".number", "expected an integer >= 1, got " + n->dump());
        auto [it, fresh] = numbers.emplace(num, name);
        if (!fresh)
          refuse(path + ".number",
                 n->dump() + " is already the number of body " + literal(it->second));
        body.number = static_cast<int>(num);
      }
      if (const Json* mass = find(b, "mass")) body.mass = readMass(*mass, path + ".mass");
      if (const Json* plane = find(b, "plane")) body.plane = getString(*plane, path + ".plane");
      body.extras =
          unknownFields(b, {"name", "ground", "plane", "number", "points", "slots", "mass"});

      const Json& points = require(b, "points", path);
      requireObject(points, path + ".points");
      for (auto it = points.begin(); it != points.end(); ++it) {
        const std::string ppath = member(path + ".points", it.key());
        checkName(it.key(), ppath, "point");
        std::optional<double> third;
        std::optional<Vec2> p = asPoint(it.value(), third);
        if (!p)
          refuse(ppath, "expected [x, y] (or [x, y, " + std::string(body.ground ? "z" : "depth") +
                            "]) with finite numbers, got " + describe(it.value()));
        names.points[it.key()] = m_.addPoint(id, it.key(), *p);
        m_.points.back().third = third;
      }
      if (const Json* slots = find(b, "slots")) {
        requireObject(*slots, path + ".slots");
        for (auto it = slots->begin(); it != slots->end(); ++it)
          readSlot(id, it.key(), it.value(), member(path + ".slots", it.key()), names);
      }
    }
    if (grounds.empty()) refuse("bodies", "no body has \"ground\": true; exactly one must");
    if (grounds.size() > 1) {
      std::string list;
      for (size_t k = 0; k < grounds.size(); ++k) {
        if (k > 0) list += k + 1 == grounds.size() ? " and " : ", ";
        list += literal(m_.bodies[grounds[k]].name) + " (" + element("bodies", grounds[k]) + ")";
      }
      refuse("bodies", "exactly one body may have \"ground\": true, but " + list + " do");
    }
  }

  // Two points: a straight slot; three: the arc from the first through the second to the third.
  void readSlot(BodyId body, const std::string& name, const Json& s, const std::string& spath,
                BodyNames& names) {
    checkName(name, spath, "slot");
    std::optional<Vec2> p[3];
    std::optional<double> z[3];
    const size_t n = s.is_array() ? s.size() : 0;
    const bool ground = m_.body(body)->ground;
    if (n == 2 || n == 3)
      for (size_t k = 0; k < n; ++k) p[k] = ground ? asPoint(s[k], z[k]) : asPair(s[k]);
    if (n < 2 || n > 3 || !p[0] || !p[1] || (n == 3 && !p[2]))
      refuse(spath,
             "expected [[x0, y0], [x1, y1]] (or an arc [[x0, y0], [xm, ym], [x1, y1]]) with finite "
             "numbers, got " +
                 describe(s));
    Slot slot{{}, body, name, *p[0], *p[n - 1], std::nullopt, {}};
    if (n == 3) slot.mid = *p[1];
    // The ground's ends in the world: all with z or none (a slot half in the drawing plane is
    // more likely a slip than meant).
    const int withZ = (z[0] ? 1 : 0) + (z[1] ? 1 : 0) + (z[2] ? 1 : 0);
    if (withZ > 0 && withZ != static_cast<int>(n))
      refuse(spath, "give every end three numbers [x, y, z] or every end two");
    for (size_t k = 0; k < n && withZ > 0; ++k) slot.z.push_back(*z[k]);
    std::string why;
    if (!soundSlot(slot, &why)) refuse(spath, why);
    names.slots[name] = slot.mid ? m_.addArcSlot(body, name, slot.p0, *slot.mid, slot.p1)
                                 : m_.addSlot(body, name, slot.p0, slot.p1);
    m_.slots.back().z = slot.z;
  }

  // "body.name" to the body and the name after the dot.
  std::pair<const BodyNames*, std::string> splitReference(const Json& v, const std::string& path,
                                                          const char* what) {
    const std::string& ref = getString(v, path);
    size_t dot = ref.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == ref.size())
      refuse(path, std::string("expected \"body.") + what + "\", got " + literal(ref));
    std::string bodyName = ref.substr(0, dot);
    auto it = bodies_.find(bodyName);
    if (it == bodies_.end()) refuse(path, "no body " + literal(bodyName));
    return {&it->second, ref.substr(dot + 1)};
  }

  // The body comes back too: Mechanism's own lookups are linear, too slow for large files.
  std::pair<PointId, const BodyNames*> readPointRef(const Json& v, const std::string& path) {
    auto [body, name] = splitReference(v, path, "point");
    auto it = body->points.find(name);
    if (it == body->points.end())
      refuse(path, "no point " + literal(name) + " on body " + literal(body->name));
    return {it->second, body};
  }

  std::pair<SlotId, const BodyNames*> readSlotRef(const Json& v, const std::string& path) {
    auto [body, name] = splitReference(v, path, "slot");
    auto it = body->slots.find(name);
    if (it == body->slots.end())
      refuse(path, "no slot " + literal(name) + " on body " + literal(body->name));
    return {it->second, body};
  }

  // The fields its kind reads (linkage/elements.h); a field only other kinds read is refused.
  void readJoint(const Json& j, const std::string& path) {
    requireObject(j, path);
    const Json& type = require(j, "type", path);
    const ElementKind* kind =
        type.is_string() ? elementKindNamed(type.get<std::string>()) : nullptr;
    if (!kind) refuse(path + ".type", "expected " + elementKindNames() + ", got " + describe(type));
    for (const char* key : elementFieldKeys())
      if (!kind->field(key) && find(j, key))
        refuse(path + "." + key,
               std::string("a ") + kind->name + " " + kind->joins + "; it has no " + noun(key));
    Joint joint;
    joint.type = kind->type;
    const BodyNames* sides[2] = {nullptr, nullptr};
    for (const FieldSpec& f : kind->fields) {
      const Json* v = f.required ? &require(j, f.key, path) : find(j, f.key);
      if (v) readField(joint, f, *v, path + "." + f.key, sides);
      if (!v && (f.type == FieldType::Number || f.type == FieldType::Flag))
        numberAt(joint, f.index) = f.type == FieldType::Number ? NAN : 0.0;  // not given
    }
    if (sides[0] && sides[0] == sides[1])
      refuse(path, "both sides are on body " + literal(sides[0]->name));
    std::vector<const char*> known{"type"};
    for (const char* key : elementFieldKeys()) known.push_back(key);
    joint.extras = unknownFields(j, known);
    m_.addJoint(std::move(joint));
  }

  // What a key names in a message, by the type other kinds give it.
  static std::string noun(const char* key) {
    for (const ElementKind& k : elementKinds())
      if (const FieldSpec* f = k.field(key)) {
        if (f->type == FieldType::Point) return std::string("point ") + literal(key);
        if (f->type == FieldType::Slot) return "slot";
      }
    return literal(key);
  }

  // One field into the joint; the bodies of what it joins (a, and b or the slot) to `sides`.
  void readField(Joint& joint, const FieldSpec& f, const Json& v, const std::string& path,
                 const BodyNames* sides[2]) {
    switch (f.type) {
      case FieldType::Point:
        std::tie(pointField(joint, f), sides[f.index == 0 ? 0 : 1]) = readPointRef(v, path);
        break;
      case FieldType::Slot:
        std::tie(joint.slot, sides[1]) = readSlotRef(v, path);
        break;
      case FieldType::Body:
        joint.carrier = bodyRef(v, path);
        break;
      case FieldType::Number:
        numberAt(joint, f.index) = getNumber(v, path);
        break;
      case FieldType::Flag:
        if (!v.is_boolean()) refuse(path, "expected true or false, got " + describe(v));
        numberAt(joint, f.index) = v.get<bool>() ? 1.0 : 0.0;
        break;
      case FieldType::Records:
        if (joint.records.size() <= f.index) joint.records.resize(f.index + 1);
        joint.records[f.index] = readRecords(v, path);
        break;
    }
  }

  static double& numberAt(Joint& joint, size_t k) {
    if (joint.numbers.size() <= k) joint.numbers.resize(k + 1, 0.0);
    return joint.numbers[k];
  }

  // An array of objects whose members are numbers or strings, kept as written.
  static std::vector<Record> readRecords(const Json& v, const std::string& path) {
    if (!v.is_array()) refuse(path, "expected an array of objects, got " + describe(v));
    std::vector<Record> out;
    for (size_t i = 0; i < v.size(); ++i) {
      const std::string at = element(path, i);
      requireObject(v[i], at);
      Record r;
      for (auto it = v[i].begin(); it != v[i].end(); ++it) {
        if (it.value().is_number())
          r.push_back({it.key(), getNumber(it.value(), member(at, it.key()))});
        else if (it.value().is_string())
          r.push_back({it.key(), it.value().get<std::string>()});
        else
          refuse(member(at, it.key()),
                 "expected a number or a string, got " + describe(it.value()));
      }
      out.push_back(std::move(r));
    }
    return out;
  }

  void readDriver(const Json& d) {
    requireObject(d, "driver");
    Driver driver;
    const Json& index = require(d, "joint", "driver");
    long long i = getInteger(index, "driver.joint", "a joint index (an integer)");
    if (i < 0 || static_cast<unsigned long long>(i) >= m_.joints.size()) {
      refuse("driver.joint", index.dump() + " is not a joint index (" +
                                 (m_.joints.empty() ? std::string("there are no joints")
                                                    : "joints are numbered 0 to " +
                                                          std::to_string(m_.joints.size() - 1)) +
                                 ")");
    }
    const Joint& joint = m_.joints[static_cast<size_t>(i)];
    if (kindOf(joint).role != Role::Revolute)
      refuse("driver.joint", element("joints", static_cast<size_t>(i)) + " is a " +
                                 toString(joint.type) + ", a driver needs a pin");
    driver.joint = joint.id;
    const Json& rpm = require(d, "rpm", "driver");
    driver.rpm = getNumber(rpm, "driver.rpm", "a number > 0");
    if (!(driver.rpm > 0)) refuse("driver.rpm", "expected a number > 0, got " + rpm.dump());
    const Json& dir = require(d, "direction", "driver");
    if (dir != "cw" && dir != "ccw")
      refuse("driver.direction", "expected \"cw\" or \"ccw\", got " + describe(dir));
    driver.direction = dir == "cw" ? Direction::Cw : Direction::Ccw;
    if (const Json* start = find(d, "start_deg"))
      driver.startDeg = getNumber(*start, "driver.start_deg");
    driver.extras = unknownFields(d, {"joint", "rpm", "direction", "start_deg"});
    m_.driver = std::move(driver);
  }

  void readOutputs(const Json& o) {
    requireObject(o, "outputs");
    if (const Json* points = find(o, "points")) {
      if (!points->is_array())
        refuse("outputs.points", "expected an array of \"body.point\", got " + describe(*points));
      std::unordered_set<std::uint32_t> listed;
      for (size_t i = 0; i < points->size(); ++i) {
        const std::string path = element("outputs.points", i);
        PointId p = readPointRef((*points)[i], path).first;
        if (!listed.insert(p.value).second)
          refuse(path, literal((*points)[i].get<std::string>()) + " is listed twice");
        m_.outputs.push_back(p);
      }
    }
    m_.outputsExtras = unknownFields(o, {"points"});
  }
};

}  // namespace

LoadResult parseMechanism(std::string_view jsonText) {
  Json root;
  std::string error;
  if (!json_tree::parse(jsonText, root, error)) return {std::nullopt, error};
  try {
    return {Reader().read(root), {}};
  } catch (const Refusal& r) {
    return {std::nullopt, r.message};
  } catch (const std::exception& e) {
    // A bug here, not a bad file; say so rather than blame the file.
    return {std::nullopt, std::string("internal error while reading: ") + e.what()};
  }
}

LoadResult loadMechanismFile(const std::string& path) {
  constexpr long kMaxBytes = 64L << 20;  // mechanism files are kilobytes; refuse a mistaken pick
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return {std::nullopt, path + ": cannot open: " + std::strerror(errno)};
  std::string text;
  char buf[65536];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) {
    text.append(buf, n);
    if (static_cast<long>(text.size()) > kMaxBytes) {
      std::fclose(f);
      return {std::nullopt, path + ": too large for a mechanism file (over 64 MiB)"};
    }
  }
  int err = std::ferror(f) ? errno : 0;
  std::fclose(f);
  if (err) return {std::nullopt, path + ": cannot read: " + std::strerror(err)};
  LoadResult r = parseMechanism(text);
  if (!r.mechanism) r.error = path + ": " + r.error;
  return r;
}

}  // namespace linkage
