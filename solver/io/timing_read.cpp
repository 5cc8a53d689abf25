#include "io/timing_read.h"

#include "linkage/timing_text.h"

namespace linkage::json_read {

namespace {

const Json& arrayAt(const Json& v, const char* key, const std::string& at, const char* of) {
  static const Json none = Json::array();
  const Json* a = find(v, key);
  if (!a) return none;
  if (!a->is_array())
    refuse(member(at, key), std::string("expected an array of ") + of + ", got " + describe(*a));
  return *a;
}

void readClearance(const Json& c, const std::string& at, Mechanism& m) {
  requireObject(c, at);
  const Json& between = require(c, "between", at);
  if (!between.is_array() || between.size() != 2)
    refuse(at + ".between",
           "expected two names [\"body.point\", \"body.point, body.P-Q or body.slot\"], got " +
               describe(between));
  ClearancePart part[2];
  for (size_t i = 0; i < 2; ++i) {
    std::string why;
    const std::optional<ClearancePart> p =
        parseClearancePart(m, getString(between[i], element(at + ".between", i)), &why);
    if (!p) refuse(element(at + ".between", i), why);
    part[i] = *p;
  }
  // A point on one side at least; it comes first.
  if (!part[0].isPoint()) std::swap(part[0], part[1]);
  if (!part[0].isPoint())
    refuse(at + ".between", "two segments or slots: one of the two must be a point");
  ClearanceWatch w;
  w.point = part[0].point;
  w.other = part[1];
  if (const Json* min = find(c, "min_mm"))
    w.minMm = getNumber(*min, at + ".min_mm", "a number >= 0 (mm)");
  m.timing.clearances.push_back(w);
}

}  // namespace

void readTiming(const Json& v, const std::string& path, Mechanism& m) {
  requireObject(v, path);
  Timing& t = m.timing;
  const Json& outputs = arrayAt(v, "outputs", path, "outputs \"body.point:y\"");
  for (size_t i = 0; i < outputs.size(); ++i) {
    const std::string at = element(path + ".outputs", i);
    std::string why;
    std::optional<LimitMeasure> x = parseMeasure(m, getString(outputs[i], at), &why);
    if (!x) refuse(at, why);
    t.outputs.push_back(*x);
  }
  const Json& windows = arrayAt(v, "windows", path, "windows \"NAME=body.point:y<VALUE\"");
  for (size_t i = 0; i < windows.size(); ++i) {
    const std::string at = element(path + ".windows", i);
    std::string why;
    std::optional<TimingWindow> w = parseTimingWindow(m, getString(windows[i], at), &why);
    if (!w) refuse(at, why);
    t.windows.push_back(*w);
  }
  const Json& conflicts = arrayAt(v, "conflicts", path, "pairs of window names");
  for (size_t i = 0; i < conflicts.size(); ++i) {
    const std::string at = element(path + ".conflicts", i);
    const Json& c = conflicts[i];
    if (!c.is_array() || c.size() != 2)
      refuse(at, "expected two window names [\"N1\", \"N2\"], got " + describe(c));
    t.conflicts.push_back({getString(c[0], element(at, 0)), getString(c[1], element(at, 1))});
  }
  const Json& clearances = arrayAt(v, "clearances", path, "clearances");
  for (size_t i = 0; i < clearances.size(); ++i)
    readClearance(clearances[i], element(path + ".clearances", i), m);
  t.extras = unknownFields(v, {"outputs", "windows", "conflicts", "clearances"});
  // Names given twice, conflicts naming no window, a point's distance to its own slot, ...
  if (std::string why = timingProblem(m, t); !why.empty()) throw Refusal{why};
}

}  // namespace linkage::json_read
