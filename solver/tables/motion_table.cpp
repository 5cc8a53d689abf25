#include "linkage/tables/motion_table.h"

#include <cmath>
#include <span>

#include "linkage/io/numbers.h"
#include "linkage/space.h"

namespace linkage {

namespace {
constexpr const char* kPlanar[] = {".x_mm",    ".y_mm",     ".vx_mm_s",
                                   ".vy_mm_s", ".ax_mm_s2", ".ay_mm_s2"};
// A model with planes (linkage/space.h): the world's x, y, z and their rates.
constexpr const char* kSpatial[] = {".x_mm",    ".y_mm",     ".z_mm",     ".vx_mm_s", ".vy_mm_s",
                                    ".vz_mm_s", ".ax_mm_s2", ".ay_mm_s2", ".az_mm_s2"};
}  // namespace

std::string motionTableHeader(const Mechanism& m, const std::vector<PointId>& points) {
  std::string h = "t_s,crank_deg";
  const bool spatial = isSpatial(m);
  for (PointId p : points) {
    const std::string l = m.pointLabel(p);
    for (const char* c :
         spatial ? std::span<const char* const>(kSpatial) : std::span<const char* const>(kPlanar)) {
      h.append(",").append(l).append(c);  // append, not operator+: g++ 12 -Wrestrict false alarm
    }
  }
  return h;
}

std::string motionTableRow(const Kinematics& k, double crankDeg,
                           const std::vector<PointId>& points) {
  std::string r = formatNumber(crankDeg / (6.0 * k.rpm()));
  r.append(",").append(formatNumber(crankDeg));
  const bool spatial = isSpatial(k.mechanism());
  for (PointId p : points) {
    if (spatial) {
      const Kinematics::PointMotion3 m = k.motionInSpace(p);
      for (const Vec3* v : {&m.position, &m.velocity, &m.acceleration})
        for (int c = 0; c < 3; ++c) r.append(",").append(formatNumber((*v)[c]));
      continue;
    }
    const Kinematics::PointMotion m = k.motion(p);
    for (double value : {m.position.x(), m.position.y(), m.velocity.x(), m.velocity.y(),
                         m.acceleration.x(), m.acceleration.y()})
      r.append(",").append(formatNumber(value));
  }
  return r;
}

long long motionTableRows(const MotionTableSpec& spec) {
  const double total = static_cast<double>(spec.steps) * spec.revs;
  const double whole = std::round(total);
  if (!(spec.steps > 0 && spec.revs > 0) || std::abs(total - whole) > 1e-9 * std::max(1.0, total))
    return -1;
  return static_cast<long long>(whole) + 1;
}

Status sweepMotionTable(Kinematics& k, const MotionTableSpec& spec,
                        const std::function<void(const std::string&)>& sink) {
  if (spec.rpm > 0) k.setRpm(spec.rpm);
  sink(motionTableHeader(k.mechanism(), spec.points));
  const long long rows = motionTableRows(spec);
  for (long long i = 0; i < rows; ++i) {
    // Angles from the index, not by accumulation, so the last row is exactly 360 * revs.
    const double crank = static_cast<double>(i) * 360.0 / static_cast<double>(spec.steps);
    Status s = k.moveTo(crank);
    if (!s.ok()) return s;
    sink(motionTableRow(k, crank, spec.points));
  }
  return Status::success();
}

}  // namespace linkage
