#include "analysis/study_variant.h"

#include <algorithm>
#include <cmath>

#include "analysis/measure_track.h"
#include "analysis/transmission_track.h"

namespace linkage {

StudyRow measureVariant(const Mechanism& moved, const StudySpec& spec, const Vec2& direction,
                        const std::vector<TransmissionJoint>& joints) {
  StudyRow row;
  Kinematics k;
  if (row.status = k.load(moved); !row.status.ok()) return row;
  const LimitMeasure along = LimitMeasure::along(spec.point, direction);
  if (row.status = checkMeasure(k, along); !row.status.ok()) return row;
  // The probe that finds the extremes starts where the sweep does, at crank angle 0.
  Kinematics probe = k;
  MeasureTrack point(k, along);
  std::vector<MeasureTrack> bodies;
  for (BodyId b : spec.bodies) bodies.emplace_back(k, LimitMeasure::angleOf(b));
  std::vector<TransmissionTrack> tracks;
  for (const TransmissionJoint& t : joints) tracks.emplace_back(moved, t);
  std::vector<double> crank;
  for (int i = 0; i <= spec.steps; ++i) {
    // Angles from the index, as the motion table's, so that the samples are its rows.
    crank.push_back(static_cast<double>(i) * 360.0 / static_cast<double>(spec.steps));
    if (row.status = k.moveTo(crank.back()); !row.status.ok()) {
      row.lockDeg = row.status.lastReachedDeg ? row.status.lastReachedDeg : row.status.crankDeg;
      return row;
    }
    const Kinematics::PointMotion p = k.motion(spec.point);
    if (spec.keepPaths) row.path.push_back(p.position);
    row.peakSpeed = std::max(row.peakSpeed, std::hypot(p.velocity.x(), p.velocity.y()));
    row.peakAccel = std::max(row.peakAccel, std::hypot(p.acceleration.x(), p.acceleration.y()));
    point.sample(k);
    for (MeasureTrack& b : bodies) b.sample(k);
    for (TransmissionTrack& t : tracks) t.sample(k);
  }
  row.turns = true;
  bool periodic = point.repeats();
  for (const MeasureTrack& b : bodies) periodic = periodic && b.repeats();
  for (const TransmissionTrack& t : tracks)
    periodic = periodic && std::abs(t.mu.back() - t.mu.front()) <= 1e-9;
  std::vector<RootChannel*> channels = point.channels();
  if (periodic) point.closePeriod();
  for (MeasureTrack& b : bodies) {
    if (periodic) b.closePeriod();
    for (RootChannel* c : b.channels()) channels.push_back(c);
  }
  for (TransmissionTrack& t : tracks) {
    if (periodic) t.closePeriod();
    for (RootChannel* c : t.channels()) channels.push_back(c);
  }
  if (row.status = findRoots(probe, crank, channels, periodic); !row.status.ok()) return row;
  row.point = point.result(periodic);
  for (const MeasureTrack& b : bodies) row.bodies.push_back(b.result(periodic));
  for (const TransmissionTrack& t : tracks) row.transmission.push_back(t.summary(periodic));
  return row;
}

}  // namespace linkage
