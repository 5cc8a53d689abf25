// The contact of a cam and its follower at a pose: linkage/cam.h has the derivation.
#include <cmath>

#include "linkage/cam.h"

namespace linkage::cam {

namespace {

using V = Eigen::Vector2d;

V perp(const V& v) {
  return V(-v.y(), v.x());
}
double cross(const V& a, const V& b) {
  return a.x() * b.y() - a.y() * b.x();
}

}  // namespace

Contact contact(const Follower& f, const Place& at, double sPrime) {
  const V r = at.b - at.centre;
  if (f.flat && !f.oscillating) {
    const V& u = at.along;
    const V w(u.y(), -u.x());
    return {at.b + (sPrime - cross(r, u)) * w, u};
  }
  if (f.flat) {
    const V& n = at.face;
    const double k = f.sign * sPrime;
    // k = 1: the follower turns with the cam, about the same centre: no contact point is
    // singled out (a cam no one cuts); b stands for it rather than a point at infinity.
    if (!(std::abs(1 - k) > 1e-12)) return {at.b, n};
    const double lambda = (cross(r, n) - k * cross(at.b - at.pivot, n)) / (1 - k);
    return {at.b + lambda * perp(n), n};
  }
  const V dbds = f.oscillating ? V(f.sign * perp(at.b - at.pivot)) : at.along;
  return {at.b, (r + sPrime * perp(dbds)).normalized()};
}

}  // namespace linkage::cam
