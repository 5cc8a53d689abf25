#include "io/forces_read.h"

namespace linkage::json_read {

namespace {

double nonNegative(const Json& v, const std::string& path) {
  const double x = getNumber(v, path, "a number >= 0");
  if (x < 0) refuse(path, "expected a number >= 0, got " + v.dump());
  return x;
}

// A mass or a moment of inertia: a number >= 0 (said as before), then within its bound.
double bounded(const Json& v, const std::string& path, std::string (*refusal)(double)) {
  const double x = nonNegative(v, path);
  if (std::string why = refusal(x); !why.empty()) refuse(path, why);
  return x;
}

Vec2 finitePair(const Json& v, const std::string& path) {
  const std::optional<Vec2> p = asPair(v);
  if (!p) refuse(path, "expected [x, y] with two finite numbers, got " + describe(v));
  return *p;
}

// A window of crank angles: both ends or neither.
void readWindow(const Json& l, const std::string& path, Load& load) {
  const Json *from = find(l, "from_deg"), *to = find(l, "to_deg");
  if (!from && !to) return;
  if (!from || !to)
    refuse(path, std::string("a window needs both \"from_deg\" and \"to_deg\"; only \"") +
                     (from ? "from_deg" : "to_deg") + "\" is given");
  load.fromDeg = getNumber(*from, path + ".from_deg");
  load.toDeg = getNumber(*to, path + ".to_deg");
}

}  // namespace

Mass readMass(const Json& v, const std::string& path) {
  requireObject(v, path);
  Mass m;
  m.kg = bounded(require(v, "kg", path), path + ".kg", massRefusal);
  m.com = finitePair(require(v, "com", path), path + ".com");
  if (const Json* j = find(v, "j_kg_mm2"))
    m.jKgMm2 = bounded(*j, path + ".j_kg_mm2", inertiaRefusal);
  if (const Json* c = find(v, "counterweights")) {
    const std::string at = path + ".counterweights";
    if (!c->is_array()) refuse(at, "expected an array of {\"kg\", \"at\"}, got " + describe(*c));
    for (size_t i = 0; i < c->size(); ++i) {
      const std::string e = element(at, i);
      requireObject((*c)[i], e);
      m.counterweights.push_back({bounded(require((*c)[i], "kg", e), e + ".kg", massRefusal),
                                  finitePair(require((*c)[i], "at", e), e + ".at")});
    }
  }
  m.extras = unknownFields(v, {"kg", "com", "j_kg_mm2", "counterweights"});
  return m;
}

Vec2 readGravity(const Json& v, const std::string& path, std::optional<double>& z) {
  const std::optional<Vec2> g = asPoint(v, z);
  if (!g)
    refuse(path,
           "expected [gx, gy] or [gx, gy, gz] with finite numbers (m/s^2), got " + describe(v));
  return *g;
}

void readLoads(const Json& v, const std::string& path, Mechanism& m, const PointRef& point,
               const BodyRef& body) {
  if (!v.is_array()) refuse(path, "expected an array of loads, got " + describe(v));
  for (size_t i = 0; i < v.size(); ++i) {
    const std::string at = element(path, i);
    const Json& l = v[i];
    requireObject(l, at);
    const Json *p = find(l, "point"), *b = find(l, "body");
    if (!p == !b)
      refuse(at,
             "a load names a \"point\" (a force, \"force_N\") or a \"body\" (a torque, "
             "\"torque_Nm\"): exactly one of them");
    Load load;
    if (p) {
      load.point = point(*p, at + ".point");
      load.forceN = finitePair(require(l, "force_N", at), at + ".force_N");
      if (find(l, "torque_Nm")) refuse(at + ".torque_Nm", "a force on a point has no torque");
    } else {
      load.body = body(*b, at + ".body");
      load.torqueNm = getNumber(require(l, "torque_Nm", at), at + ".torque_Nm");
      if (find(l, "force_N")) refuse(at + ".force_N", "a torque on a body has no force");
    }
    readWindow(l, at, load);
    load.extras = unknownFields(l, {"point", "body", "force_N", "torque_Nm", "from_deg", "to_deg"});
    m.addLoad(std::move(load));
  }
}

}  // namespace linkage::json_read
