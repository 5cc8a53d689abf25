// Wanzer needle-bar mechanism (ME 481 homework H05), both inversions, by the reduced one-angle
// formulation rather than a general constraint system. See README.md.
//
// Disk frame: origin at the disk centre A, coinciding with the global frame in the sketch. Slot B
// is the line x = eB, slot C the line y = eC (90 degrees apart). Relative to the disk the triangle
// EFG is an elliptical trammel: its orientation alpha (the angle of E->F in the disk frame) fixes
// it. Globally the disk is at theta = s phi (s = -1: clockwise), and the needle condition is that
// G lies on the ground slot D, the vertical line x = 0 through A.
#pragma once

#include <stdexcept>

#include "reference/scalar.h"
#include "reference/vec2.h"

namespace linkref {

enum class WanzerInversion {
  k1 = 1,  // slider 4 (E) in slot C, slider 5 (F) in slot B
  k2 = 2,  // slider 4 (E) in slot B, slider 5 (F) in slot C
};

template <class T>
struct WanzerParams {
  WanzerInversion inversion = WanzerInversion::k2;
  T EF{16}, FG{56}, EG{62};  // triangle 3, mm
  T eB{10}, eC{10};          // slot offsets from the disk centre, mm
  int s = -1;                // disk direction: -1 clockwise
  T omega{};                 // disk speed, rad/s, > 0
  // Start of the homework-style Newton iteration for the sketch, (yE, xF, yG) for inversion 2 and
  // (xE, yF, yG) for inversion 1; it selects the assembly (triangle E, G, F counter-clockwise).
  T q0[3]{};
};

// The homework's data: 240 rpm clockwise; inversion 2 starts from its script's (20, 20, -40),
// inversion 1 from the approximate solution (-4.5132, 3.2644, -51.8355).
template <class T>
WanzerParams<T> wanzer_homework_params(WanzerInversion inv) {
  WanzerParams<T> p;
  p.inversion = inv;
  p.s = -1;
  p.omega = rpm_to_rad_s(T(240));
  if (inv == WanzerInversion::k2) {
    p.q0[0] = T(20), p.q0[1] = T(20), p.q0[2] = T(-40);
  } else {
    p.q0[0] = T(-4.5132), p.q0[1] = T(3.2644), p.q0[2] = T(-51.8355);
  }
  return p;
}

template <class T>
struct WanzerState {
  T phi{};                         // crank angle, rad, positive in the driving direction
  T theta{};                       // disk angle s phi, rad, ccw from the sketch
  T alpha{}, dalpha{}, ddalpha{};  // triangle relative to the disk (angle of E->F), rad, /s, /s^2
  Vec2<T> E, vE, aE;               // global, mm, mm/s, mm/s^2
  Vec2<T> F, vF, aF;
  Vec2<T> G, vG, aG;  // needle: G.x = 0; G.y, vG.y, aG.y are the needle's motion
  T tri_angle{}, tri_omega{}, tri_alpha{};  // absolute angle of E->F, ccw from +x, and derivatives
};

// Sketch configuration (crank angle 0): E, F, G in global = disk coordinates.
template <class T>
struct WanzerSketch {
  Vec2<T> E, F, G;
  int newton_iterations = 0;
};

template <class T>
class Wanzer {
 public:
  explicit Wanzer(const WanzerParams<T>& p) : p_(p) {
    gx_ = (p.EF * p.EF + p.EG * p.EG - p.FG * p.FG) / (T(2) * p.EF);
    gy_ = -sqrt(p.EG * p.EG - gx_ * gx_);  // G to the right of E->F: E, G, F counter-clockwise
    solve_sketch();
    alpha_ = angle_of(sketch_.F - sketch_.E);
    theta_ = T(0);
    newton(theta_);  // agree with the sketch to the last bit of this formulation
  }

  const WanzerParams<T>& params() const { return p_; }
  const WanzerSketch<T>& sketch() const { return sketch_; }

  // State at crank angle phi (rad), reached by continuation from the previous call (or from the
  // sketch) in steps of at most max_step, so the assembly branch is the one of the sketch.
  WanzerState<T> at(T phi) {
    const T target = T(p_.s) * phi;
    const T max_step = pi<T>() / T(90);  // 2 degrees
    while (theta_ != target) {
      T next = target;
      if (next - theta_ > max_step) next = theta_ + max_step;
      if (theta_ - next > max_step) next = theta_ - max_step;
      alpha_ += dalpha_dtheta(alpha_, theta_) * (next - theta_);  // tangent predictor
      theta_ = next;
      newton(theta_);
    }
    return state(phi);
  }
  WanzerState<T> at_deg(T phi_deg) { return at(deg2rad(phi_deg)); }

  // Points in the disk frame as functions of alpha, with first and second alpha-derivatives.
  struct Local {
    Vec2<T> E, E1, E2, F, F1, F2, G, G1, G2;
  };
  Local local(T alpha) const {
    const T c = cos(alpha), s = sin(alpha), k = p_.EF;
    Local L;
    if (p_.inversion == WanzerInversion::k2) {  // E on x = eB, F on y = eC
      L.E = {p_.eB, p_.eC - k * s};
      L.E1 = {T(0), -k * c};
      L.E2 = {T(0), k * s};
      L.F = {p_.eB + k * c, p_.eC};
      L.F1 = {-k * s, T(0)};
      L.F2 = {-k * c, T(0)};
    } else {  // E on y = eC, F on x = eB
      L.E = {p_.eB - k * c, p_.eC};
      L.E1 = {k * s, T(0)};
      L.E2 = {k * c, T(0)};
      L.F = {p_.eB, p_.eC + k * s};
      L.F1 = {T(0), k * c};
      L.F2 = {T(0), -k * s};
    }
    const Vec2<T> g = rotate(Vec2<T>{gx_, gy_}, c, s);  // E -> G
    L.G = L.E + g;
    L.G1 = L.E1 + perp(g);
    L.G2 = L.E2 - g;
    return L;
  }

 private:
  // Global x of G at (alpha, theta) and its alpha-derivative: the needle equation and its slope.
  T needle_x(T alpha, T theta, T* slope) const {
    const Local L = local(alpha);
    const T c = cos(theta), s = sin(theta);
    if (slope) *slope = c * L.G1.x - s * L.G1.y;
    return c * L.G.x - s * L.G.y;
  }

  T dalpha_dtheta(T alpha, T theta) const {
    const Local L = local(alpha);
    const T c = cos(theta), s = sin(theta);
    const Vec2<T> jg = perp(L.G);
    return -(c * jg.x - s * jg.y) / (c * L.G1.x - s * L.G1.y);
  }

  void newton(T theta) {
    T prev = T(-1);
    for (int it = 0; it < 100; ++it) {
      T slope;
      const T f = needle_x(alpha_, theta, &slope);
      const T d = f / slope;
      alpha_ -= d;
      const T ad = abs(d);
      // Stop once the correction is at rounding level or has stopped shrinking (it then only
      // dithers in the last bits).
      if (ad <= T(4) * epsilon<T>() * (T(1) + abs(alpha_))) return;
      if (prev >= T(0) && ad >= prev && ad <= T(1e6) * epsilon<T>() * (T(1) + abs(alpha_))) return;
      prev = ad;
    }
    throw std::runtime_error("Wanzer: Newton did not converge");
  }

  // The homework script's Newton iteration on the three distance equations, unknowns
  // (yE, xF, yG) (inversion 2) or (xE, yF, yG) (inversion 1), run to convergence.
  void solve_sketch() {
    const T xG = T(0);
    T q[3] = {p_.q0[0], p_.q0[1], p_.q0[2]};
    auto points = [&](const T* v, Vec2<T>& E, Vec2<T>& F, Vec2<T>& G) {
      if (p_.inversion == WanzerInversion::k2) {
        E = {p_.eB, v[0]}, F = {v[1], p_.eC};
      } else {
        E = {v[0], p_.eC}, F = {p_.eB, v[1]};
      }
      G = {xG, v[2]};
    };
    T prev = T(-1);
    int it = 0;
    for (; it < 100; ++it) {
      Vec2<T> E, F, G;
      points(q, E, F, G);
      const Vec2<T> ef = E - F, fg = F - G, eg = E - G;
      const T r[3] = {dot(ef, ef) - p_.EF * p_.EF, dot(fg, fg) - p_.FG * p_.FG,
                      dot(eg, eg) - p_.EG * p_.EG};
      // Jacobian rows: d/dq of the three squared distances; which coordinate of E and F is free
      // depends on the inversion.
      T J[3][3];
      if (p_.inversion == WanzerInversion::k2) {  // q = (yE, xF, yG)
        J[0][0] = T(2) * ef.y, J[0][1] = -T(2) * ef.x, J[0][2] = T(0);
        J[1][0] = T(0), J[1][1] = T(2) * fg.x, J[1][2] = -T(2) * fg.y;
        J[2][0] = T(2) * eg.y, J[2][1] = T(0), J[2][2] = -T(2) * eg.y;
      } else {  // q = (xE, yF, yG)
        J[0][0] = T(2) * ef.x, J[0][1] = -T(2) * ef.y, J[0][2] = T(0);
        J[1][0] = T(0), J[1][1] = T(2) * fg.y, J[1][2] = -T(2) * fg.y;
        J[2][0] = T(2) * eg.x, J[2][1] = T(0), J[2][2] = -T(2) * eg.y;
      }
      const T det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                    J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                    J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
      T dq[3];
      for (int k = 0; k < 3; ++k) {  // Cramer: column k replaced by the residual
        T M[3][3];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) M[i][j] = (j == k) ? r[i] : J[i][j];
        dq[k] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
                 M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                 M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) /
                det;
      }
      T size = T(0), step = T(0);
      for (int k = 0; k < 3; ++k) {
        q[k] -= dq[k];
        size += abs(q[k]);
        step += abs(dq[k]);
      }
      if (step <= T(4) * epsilon<T>() * size) break;
      if (prev >= T(0) && step >= prev && step <= T(1e6) * epsilon<T>() * size) break;
      prev = step;
    }
    if (it == 100) throw std::runtime_error("Wanzer: sketch Newton did not converge");
    points(q, sketch_.E, sketch_.F, sketch_.G);
    sketch_.newton_iterations = it + 1;
    if (!(cross(sketch_.F - sketch_.E, sketch_.G - sketch_.E) < T(0)))
      throw std::runtime_error("Wanzer: sketch start led to the mirrored triangle");
  }

  WanzerState<T> state(T phi) const {
    WanzerState<T> st;
    st.phi = phi;
    st.theta = theta_;
    st.alpha = alpha_;
    const T w = T(p_.s) * p_.omega;  // d theta / dt
    const T c = cos(theta_), s = sin(theta_);
    const Local L = local(alpha_);
    auto glob = [&](Vec2<T> v) { return rotate(v, c, s); };
    // G stays on x = 0: the x components of its global velocity and acceleration vanish, which
    // gives alpha' and then alpha''.
    const T gx1 = glob(L.G1).x;
    st.dalpha = -(w * glob(perp(L.G)).x) / gx1;
    const T da = st.dalpha;
    const Vec2<T> rest = -(w * w) * L.G + (T(2) * w * da) * perp(L.G1) + (da * da) * L.G2;
    st.ddalpha = -glob(rest).x / gx1;
    const T dda = st.ddalpha;
    auto kin = [&](Vec2<T> X, Vec2<T> X1, Vec2<T> X2, Vec2<T>& P, Vec2<T>& V, Vec2<T>& A) {
      P = glob(X);
      V = glob(w * perp(X) + da * X1);
      A = glob(-(w * w) * X + (T(2) * w * da) * perp(X1) + (da * da) * X2 + dda * X1);
    };
    kin(L.E, L.E1, L.E2, st.E, st.vE, st.aE);
    kin(L.F, L.F1, L.F2, st.F, st.vF, st.aF);
    kin(L.G, L.G1, L.G2, st.G, st.vG, st.aG);
    st.tri_angle = theta_ + alpha_;
    st.tri_omega = w + da;
    st.tri_alpha = dda;
    return st;
  }

  WanzerParams<T> p_;
  T gx_{}, gy_{};  // G relative to E in the triangle frame (E->F along +x)
  WanzerSketch<T> sketch_;
  T alpha_{}, theta_{};
};

// One-off state at crank angle phi (rad) with the homework's data, tracked from the sketch. For a
// sequence of angles keep one Wanzer object instead: each call then continues from the last.
template <class T>
WanzerState<T> wanzer_state(WanzerInversion inv, T phi) {
  Wanzer<T> w(wanzer_homework_params<T>(inv));
  return w.at(phi);
}

}  // namespace linkref
