// Exact offset slider-crank, and the central slider-crank in the form of Karabegovic, Bolic and
// Ujevic (machine 22-A needle bar). See README.md for the derivations and the angle conventions.
#pragma once

#include <stdexcept>

#include "reference/scalar.h"
#include "reference/vec2.h"

namespace linkref {

// Crank pivot O at the origin; crank pin A(phi) = r (cos theta, sin theta) with
// theta = a0 + s * phi; slider pin B = (e, y) on the vertical line x = e, on the branch with B
// above the crank pin. phi = omega t, omega > 0 constant; s = +1 turns the crank ccw, -1 cw.
template <class T>
struct SliderCrankParams {
  T r{};      // crank radius OA, mm
  T l{};      // rod length AB, mm
  T e{};      // slider line x = e, mm (0: central)
  T a0{};     // absolute angle of OA at phi = 0, rad, ccw from +x
  int s = 1;  // +1 ccw, -1 cw
  T omega{};  // crank speed, rad/s, > 0
};

template <class T>
struct SliderCrankState {
  T theta{};                 // absolute crank angle a0 + s phi, rad
  Vec2<T> A, vA, aA;         // crank pin, mm, mm/s, mm/s^2
  T y{}, vy{}, ay{};         // slider pin B = (e, y) and its time derivatives
  T psi{}, dpsi{}, ddpsi{};  // rod angle: direction of A->B, ccw from +x, rad, rad/s, rad/s^2
};

// True when the rod reaches the slider line at crank angle phi (rad).
template <class T>
bool slider_crank_reachable(const SliderCrankParams<T>& p, T phi) {
  const T dx = p.e - p.r * cos(p.a0 + T(p.s) * phi);
  return p.l * p.l - dx * dx >= T(0);
}

// State at crank angle phi (rad). Throws std::domain_error where the rod cannot reach the line.
template <class T>
SliderCrankState<T> slider_crank(const SliderCrankParams<T>& p, T phi) {
  SliderCrankState<T> st;
  const T w = T(p.s) * p.omega;  // d theta / dt
  st.theta = p.a0 + T(p.s) * phi;
  const T c = cos(st.theta), sn = sin(st.theta);
  st.A = {p.r * c, p.r * sn};
  st.vA = {-p.r * sn * w, p.r * c * w};
  st.aA = {-p.r * c * w * w, -p.r * sn * w * w};

  // Horizontal and vertical legs of the rod: dx^2 + h^2 = l^2, h > 0 on this branch.
  const T dx = p.e - st.A.x, ddx = -st.vA.x, dddx = -st.aA.x;
  const T h2 = p.l * p.l - dx * dx;
  if (!(h2 > T(0))) throw std::domain_error("slider_crank: rod cannot reach the slider line");
  const T h = sqrt(h2);
  const T dh = -dx * ddx / h;
  const T ddh = -(ddx * ddx + dx * dddx + dh * dh) / h;

  st.y = st.A.y + h;
  st.vy = st.vA.y + dh;
  st.ay = st.aA.y + ddh;

  // cos psi = dx / l, sin psi = h / l; differentiate dx = l cos psi twice.
  st.psi = atan2(h, dx);
  st.dpsi = -ddx / h;
  st.ddpsi = -(dddx + dx * st.dpsi * st.dpsi) / h;
  return st;
}

// The paper's exact position (its eq. 2) and its exact derivatives (its eqs. 10 and 12 are the
// first-order truncations in lambda of these):
//   S_B = (r - l) - r cos phi_B + l sqrt(1 - lambda^2 sin^2 phi_B),  lambda = r / l,
// phi_B measured from the needle's upper dead centre of the paper's machine, where the needle bar
// hangs below the crankshaft, so that dead centre is the inner one (crank pin pointing away from
// the slider, B nearest to O); S_B is B's distance travelled away from O. For the upright
// slider_crank() above with e = 0 this is S_B = y - (l - r), v = dy/dt, a = d2y/dt2 at
// phi_B = s (theta + pi / 2), the crank's turn from the inner dead centre in its own direction.
template <class T>
struct PaperSliderCrank {
  T S{}, v{}, a{};  // mm, mm/s, mm/s^2
};

template <class T>
PaperSliderCrank<T> paper_slider_crank(T r, T lambda, T omega, T phi_B) {
  const T l = r / lambda;
  const T c = cos(phi_B), sn = sin(phi_B);
  const T s2 = T(2) * sn * c, c2 = c * c - sn * sn;  // sin 2phi, cos 2phi
  const T D = sqrt(T(1) - lambda * lambda * sn * sn);
  PaperSliderCrank<T> out;
  out.S = (r - l) - r * c + l * D;
  out.v = r * omega * (sn - lambda * s2 / (T(2) * D));
  out.a = r * omega * omega *
          (c - lambda * c2 / D - lambda * lambda * lambda * s2 * s2 / (T(4) * D * D * D));
  return out;
}

// The central slider-crank of the 22-A needle bar as drawn in
// resources/examples/slider-crank-22a-lambda-*.linkage.json: r = 15 mm, rod l (30 or 50 mm, so
// lambda = 15 / l), sketch at the outer dead centre (A = (0, 15), B = (0, 15 + l)), 1000 rpm ccw.
// Crank angle 0 is the sketch; the paper's angle is phi_B = phi + pi.
template <class T>
SliderCrankParams<T> slider_crank_22a(T rod_length) {
  SliderCrankParams<T> p;
  p.r = T(15);
  p.l = rod_length;
  p.e = T(0);
  p.a0 = pi<T>() / T(2);
  p.s = 1;
  p.omega = rpm_to_rad_s(T(1000));
  return p;
}

}  // namespace linkref
