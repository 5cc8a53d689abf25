// The RSSR crank-rocker (tests/spatial_fixtures.h, test::rssrText) in closed form over
// std::complex, in its dimensions' terms, for complex-step derivatives that use no solver row
// (tests/test_spatial_sensitivity.cpp, tests/test_stroke_sensitivity_space.cpp).
#pragma once

#include <array>
#include <cmath>
#include <complex>
#include <map>
#include <string>

#include "linkage/model.h"
#include "spatial_fixtures.h"

namespace linkage::test {

using C = std::complex<double>;
inline constexpr double kRssrH = 1e-30;  // the complex step

struct C3 {
  C x, y, z;
};
inline C3 operator+(const C3& a, const C3& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline C3 operator-(const C3& a, const C3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline C3 operator*(C s, const C3& a) {
  return {s * a.x, s * a.y, s * a.z};
}
inline C dot(const C3& a, const C3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline C3 real(const Vec3& v) {
  return {v.x(), v.y(), v.z()};
}
inline Vec3 im(const C3& v) {
  return Vec3(v.x.imag(), v.y.imag(), v.z.imag()) / kRssrH;
}
inline Vec3 re(const C3& v) {
  return Vec3(v.x.real(), v.y.real(), v.z.real());
}

// The RSSR (test::rssrText) in its dimensions' terms: the ground's O and H in the world, the
// crank's O-A and A's depth, the rocker's H-C and C's depth, the rod's length and the rocker
// plane's origin. The rocker turns about the ground's H projected onto its plane (the pin's
// rows are in the plane), C at its depth along the normal; the crank about O's (x, y), its ball
// at its depth. Returns the rocker point C's world position, and its first two derivatives by
// the crank angle, at crank angle phi from the drawing, on the branch whose rocker angle is
// nearest `near`.
struct RssrClosedForm {
  std::map<std::string, C> v;
  std::array<C3, 3> rocker(double phi, double near) const {
    using namespace test::rssr;
    const C3 X = real(kX), Y = real(kY), n = real(kX.cross(kY));
    const C3 O{v.at("ground.O.x"), v.at("ground.O.y"), 0.0};
    const C3 Hg{v.at("ground.H.x"), v.at("ground.H.y"), v.at("ground.H.z")};
    const C3 origin{v.at("planes.rocker.origin.x"), v.at("planes.rocker.origin.y"),
                    v.at("planes.rocker.origin.z")};
    const C r = v.at("crank.O-A"), w = v.at("rocker.H-C"), l = v.at("ball-rod:crank.A.length");
    const C3 centre = Hg - dot(n, Hg - origin) * n + v.at("rocker.C.depth") * n;
    const double t = kPhi0 + phi;
    const C3 A = O + C3{r * std::cos(t), r * std::sin(t), v.at("crank.A.depth")};
    const C3 A1{-r * std::sin(t), r * std::cos(t), 0.0},
        A2{-r * std::cos(t), -r * std::sin(t), 0.0};
    // |A - centre - w (cos psi X + sin psi Y)|^2 = l^2 with psi = near + u:
    // a' cos u + b' sin u = c, u = 2 atan((b' + s sqrt(a'^2 + b'^2 - c^2)) / (a' + c)).
    const C3 AH = A - centre;
    const C a = 2.0 * w * dot(AH, X), b = 2.0 * w * dot(AH, Y);
    const C c = dot(AH, AH) + w * w - l * l;
    const C a1 = a * std::cos(near) + b * std::sin(near),
            b1 = -a * std::sin(near) + b * std::cos(near);
    // Of the two forms of each root, t = (b' + s q) / (a' + c) = (c - a') / (b' - s q), the
    // one without cancellation; then two Newton steps on the equation (over std::complex, so
    // they polish the derivative too) take it to rounding.
    C psi = 0;
    double best = INFINITY;
    for (double s : {1.0, -1.0}) {
      const C q = std::sqrt(a1 * a1 + b1 * b1 - c * c);
      const C t = s * b1.real() >= 0 ? (b1 + s * q) / (a1 + c) : (c - a1) / (b1 - s * q);
      const C u = 2.0 * std::atan(t);
      if (std::abs(u.real()) < best) best = std::abs(u.real()), psi = near + u;
    }
    for (int it = 0; it < 2; ++it)
      psi -= (a * std::cos(psi) + b * std::sin(psi) - c) / (b * std::cos(psi) - a * std::sin(psi));
    const C3 e = std::cos(psi) * X + std::sin(psi) * Y;
    const C3 e1 = (-std::sin(psi)) * X + std::cos(psi) * Y;
    const C3 Cw = centre + w * e, C1 = w * e1, C2 = (-w) * e;
    // F(phi, psi) = |A - C|^2 - l^2 = 0 differentiated twice (as test::rockerAt).
    const C3 D = A - Cw;
    const C Fphi = 2.0 * dot(D, A1), Fpsi = -2.0 * dot(D, C1);
    const C d1 = -Fphi / Fpsi;
    const C Fpp = 2.0 * (dot(A1, A1) + dot(D, A2)), Fps = -2.0 * dot(A1, C1),
            Fss = 2.0 * (dot(C1, C1) - dot(D, C2));
    const C d2 = -(Fpp + 2.0 * Fps * d1 + Fss * d1 * d1) / Fpsi;
    return {Cw, d1 * C1, d2 * C1 + (d1 * d1) * C2};
  }
};

}  // namespace linkage::test
