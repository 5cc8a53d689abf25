#include "io/mechanisms_read.h"

#include <cctype>

namespace linkage::json_read {

namespace {

bool isColour(const std::string& s) {
  if (s.size() != 7 || s[0] != '#') return false;
  for (size_t i = 1; i < s.size(); ++i)
    if (!std::isxdigit(static_cast<unsigned char>(s[i]))) return false;
  return true;
}

MechanismEntry readEntry(const Json& e, const std::string& at, const BodyRef& body) {
  requireObject(e, at);
  MechanismEntry entry;
  const std::string where = at + ".bodies";
  const Json& bodies = require(e, "bodies", at);
  if (!bodies.is_array() || bodies.empty())
    refuse(where, "expected a non-empty array of body names, got " + describe(bodies));
  for (size_t k = 0; k < bodies.size(); ++k) {
    const BodyId id = body(bodies[k], element(where, k));
    for (BodyId seen : entry.bodies)
      if (seen == id) refuse(element(where, k), "the body is listed twice");
    entry.bodies.push_back(id);
  }
  if (const Json* n = find(e, "name")) entry.name = getString(*n, at + ".name");
  if (const Json* c = find(e, "colour")) {
    entry.colour = getString(*c, at + ".colour");
    if (!isColour(entry.colour))
      refuse(at + ".colour", "expected a colour \"#rrggbb\", got " + describe(*c));
  }
  if (const Json* h = find(e, "hidden")) {
    if (!h->is_boolean()) refuse(at + ".hidden", "expected true or false, got " + describe(*h));
    entry.hidden = h->get<bool>();
  }
  entry.extras = unknownFields(e, {"bodies", "name", "colour", "hidden"});
  return entry;
}

}  // namespace

void readMechanismEntries(const Json& v, const std::string& path, Mechanism& m,
                          const BodyRef& body) {
  if (!v.is_array()) refuse(path, "expected an array of mechanisms, got " + describe(v));
  for (size_t i = 0; i < v.size(); ++i) {
    const std::string at = element(path, i);
    MechanismEntry entry = readEntry(v[i], at, body);
    // Two entries for one body would make which mechanism takes which a matter of order.
    for (const MechanismEntry& before : m.mechanismEntries)
      for (BodyId a : before.bodies)
        for (BodyId b : entry.bodies)
          if (a == b)
            refuse(at + ".bodies",
                   "body " + literal(m.body(b)->name) + " is already in an earlier mechanism");
    m.mechanismEntries.push_back(std::move(entry));
  }
}

}  // namespace linkage::json_read
