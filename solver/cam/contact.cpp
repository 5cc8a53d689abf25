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

Contact contactChange(const Follower& f, const Place& at, const Place& move, double sPrime,
                      double dsPrime) {
  const V r = at.b - at.centre, dr = move.b - move.centre;
  if (f.flat && !f.oscillating) {
    const V &u = at.along, &du = move.along;
    const V w(u.y(), -u.x()), dw(du.y(), -du.x());
    const double t = sPrime - cross(r, u), dt = dsPrime - cross(dr, u) - cross(r, du);
    return {move.b + dt * w + t * dw, du};
  }
  if (f.flat) {
    const V &n = at.face, &dn = move.face;
    const double k = f.sign * sPrime, dk = f.sign * dsPrime;
    if (!(std::abs(1 - k) > 1e-12)) return {move.b, dn};
    const V q = at.b - at.pivot, dq = move.b - move.pivot;
    const double num = cross(r, n) - k * cross(q, n);
    const double dnum =
        cross(dr, n) + cross(r, dn) - dk * cross(q, n) - k * (cross(dq, n) + cross(q, dn));
    const double lambda = num / (1 - k),
                 dlambda = (dnum * (1 - k) + num * dk) / ((1 - k) * (1 - k));
    return {move.b + dlambda * perp(n) + lambda * perp(dn), dn};
  }
  const V dbds = f.oscillating ? V(f.sign * perp(at.b - at.pivot)) : at.along;
  const V ddbds = f.oscillating ? V(f.sign * perp(move.b - move.pivot)) : move.along;
  const V m = r + sPrime * perp(dbds), dm = dr + dsPrime * perp(dbds) + sPrime * perp(ddbds);
  const V n = m.normalized();
  return {move.b, (dm - n * n.dot(dm)) / m.norm()};
}

}  // namespace linkage::cam
