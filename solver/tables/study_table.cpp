// The table of a parameter study: see linkage/io/study_table.h.
#include "linkage/tables/study_table.h"

#include "linkage/io/numbers.h"

namespace linkage {

std::vector<std::string> studyColumns(const Mechanism& m, const StudySpec& spec, const Study& s) {
  const std::string p = m.pointLabel(spec.point);
  std::vector<std::string> out = {"t",
                                  "turns",
                                  "lock_deg",
                                  p + ".min_mm",
                                  p + ".max_mm",
                                  p + ".stroke_mm",
                                  p + ".peak_speed_mm_s",
                                  p + ".peak_accel_mm_s2"};
  for (BodyId b : spec.bodies) out.push_back(m.body(b) ? m.body(b)->name + ".swing_deg" : "?");
  for (const TransmissionJoint& t : s.joints) {
    out.push_back(t.label + ".min_deg");
    out.push_back(t.label + ".max_deg");
  }
  return out;
}

std::vector<std::optional<double>> studyValues(const StudySpec& spec, const Study& s,
                                               const StudyRow& r) {
  std::vector<std::optional<double>> out = {r.t, r.turns ? 1.0 : 0.0, r.lockDeg};
  const size_t measures = 5 + spec.bodies.size() + 2 * s.joints.size();
  if (!r.turns || !r.status.ok()) {
    out.resize(out.size() + measures);
    return out;
  }
  for (double v : {r.point.min, r.point.max, r.point.stroke, r.peakSpeed, r.peakAccel})
    out.push_back(v);
  for (const Limits& b : r.bodies) out.push_back(b.stroke);
  for (const TransmissionSummary& t : r.transmission) {
    out.push_back(t.min);
    out.push_back(t.max);
  }
  return out;
}

std::string studyTableCsv(const Mechanism& m, const StudySpec& spec, const Study& s) {
  std::string out;
  for (const std::string& c : studyColumns(m, spec, s))
    out.append(out.empty() ? "" : ",").append(c);
  out += "\n";
  for (const StudyRow& r : s.rows) {
    bool first = true;
    for (const std::optional<double>& v : studyValues(spec, s, r)) {
      // append, not operator+: g++ 12 -Wrestrict false alarm (as in motion_table.cpp)
      if (!first) out.append(",");
      if (v) out.append(formatNumber(*v));
      first = false;
    }
    out += "\n";
  }
  return out;
}

}  // namespace linkage
