// Distances in space: see analysis/space_distance.h.
//
// To the segment: with w = X - A and u = B - A (|u| fixed: one body), the foot of the
// perpendicular is at t = w.u / u.u along u and r = w - t u; t' and t'' follow from w.u
// differentiated (u.u is constant), r' = w' - t' u - t u', r'' = w'' - t'' u - 2 t' u' - t u''.
#include "analysis/space_distance.h"

#include "analysis/slot_frame.h"

namespace linkage {

SpaceMotion spaceMotion(const Kinematics& k, PointId p) {
  const double rate = secondsPerDegree(k);
  const Kinematics::PointMotion3 m = k.motionInSpace(p);
  return {m.position, m.velocity * rate, m.acceleration * (rate * rate)};
}

CycleReading spaceDistance(const Kinematics& k, PointId p, PointId q) {
  const SpaceMotion a = spaceMotion(k, p), b = spaceMotion(k, q);
  return lengthInSpace(Vec3(a.r - b.r), Vec3(a.dr - b.dr), Vec3(a.ddr - b.ddr));
}

CycleReading spaceDistanceToSegment(const Kinematics& k, PointId p, PointId a, PointId b,
                                    Vec3* nearest) {
  const SpaceMotion x = spaceMotion(k, p), A = spaceMotion(k, a), B = spaceMotion(k, b);
  const Vec3 w = x.r - A.r, w1 = x.dr - A.dr, w2 = x.ddr - A.ddr;
  const Vec3 u = B.r - A.r, u1 = B.dr - A.dr, u2 = B.ddr - A.ddr;
  const double uu = u.squaredNorm(), t = w.dot(u) / uu;
  if (t <= 0 || t >= 1) {
    const SpaceMotion& end = t <= 0 ? A : B;
    if (nearest) *nearest = end.r;
    return lengthInSpace(Vec3(x.r - end.r), Vec3(x.dr - end.dr), Vec3(x.ddr - end.ddr));
  }
  const double t1 = (w1.dot(u) + w.dot(u1)) / uu;
  const double t2 = (w2.dot(u) + 2 * w1.dot(u1) + w.dot(u2)) / uu;
  if (nearest) *nearest = A.r + t * u;
  return lengthInSpace(Vec3(w - t * u), Vec3(w1 - t1 * u - t * u1),
                       Vec3(w2 - t2 * u - 2 * t1 * u1 - t * u2));
}

}  // namespace linkage
