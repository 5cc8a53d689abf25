// The reference solutions in tests/reference/ checked against themselves: positions against the
// loop and distance equations they were derived from, derivatives against finite differences of
// their own positions, and the double and long double builds against __float128. Finite
// differences are legitimate here because they validate the references, not the program.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "reference/four_bar.h"
#include "reference/scalar.h"
#include "reference/slider_crank.h"
#include "reference/wanzer.h"

namespace {

using linkref::Vec2;
using Q = __float128;

// |a - b| / scale as a double, for messages and comparisons.
template <class T>
double rel(T a, T b, T scale) {
  return static_cast<double>(linkref::abs(a - b) / scale);
}

// Crank angles over one turn in 7.5 degree steps, avoiding none: every reference here is regular
// over its whole cycle.
template <class T>
std::vector<T> sweep(int turns = 1) {
  std::vector<T> out;
  for (int k = 0; k <= 48 * turns; ++k) out.push_back(linkref::deg2rad(T(7.5) * T(k)));
  return out;
}

// Difference of two angles wrapped to (-pi, pi], so that atan2's cut does not spoil a difference.
Q wrap(Q d) {
  const Q two_pi = 2 * linkref::pi<Q>();
  while (d > linkref::pi<Q>()) d -= two_pi;
  while (d <= -linkref::pi<Q>()) d += two_pi;
  return d;
}

// Central differences in crank angle with step h (rad), converted to time derivatives.
struct FiniteDiff {
  Q v, a;
};
FiniteDiff fd(Q xm, Q x0, Q xp, Q h, Q omega) {
  return {(xp - xm) / (2 * h) * omega, (xp - 2 * x0 + xm) / (h * h) * omega * omega};
}
FiniteDiff fd_angle(Q xm, Q x0, Q xp, Q h, Q omega) {
  const Q dp = wrap(xp - x0), dm = wrap(x0 - xm);
  return {(dp + dm) / (2 * h) * omega, (dp - dm) / (h * h) * omega * omega};
}

constexpr double kClose = 1e-25;   // loop closure in __float128, relative
constexpr double kFd = 1e-12;      // finite differences in __float128, relative to the scale
constexpr double kDouble = 1e-12;  // double and long double against __float128
const Q kStep = Q(1e-8);           // finite-difference step in crank angle, rad

// ------------------------------------------------------------------------------------------------
// Slider-crank

std::vector<linkref::SliderCrankParams<Q>> slider_cranks() {
  std::vector<linkref::SliderCrankParams<Q>> out = {linkref::slider_crank_22a(Q(30)),
                                                    linkref::slider_crank_22a(Q(50))};
  linkref::SliderCrankParams<Q> off;  // offset, clockwise, arbitrary start
  off.r = 15, off.l = 40, off.e = 6, off.a0 = Q(0.3), off.s = -1;
  off.omega = linkref::rpm_to_rad_s(Q(700));
  out.push_back(off);
  return out;
}

template <class T>
linkref::SliderCrankParams<T> cast(const linkref::SliderCrankParams<Q>& p) {
  return {T(p.r), T(p.l), T(p.e), T(p.a0), p.s, T(p.omega)};
}

TEST(ReferenceSliderCrank, PositionsCloseTheLoop) {
  for (const auto& p : slider_cranks()) {
    for (Q phi : sweep<Q>()) {
      const auto st = linkref::slider_crank(p, phi);
      const Vec2<Q> B{p.e, st.y};
      EXPECT_LE(rel(linkref::norm(B - st.A), p.l, p.l), kClose);
      EXPECT_LE(rel(linkref::norm(st.A), p.r, p.r), kClose);
      EXPECT_GT(st.y, st.A.y);  // the branch with B above the crank pin
      EXPECT_LE(rel(st.A.x + p.l * linkref::cos(st.psi), p.e, p.l), kClose);
      EXPECT_LE(rel(st.A.y + p.l * linkref::sin(st.psi), st.y, p.l), kClose);
    }
  }
}

TEST(ReferenceSliderCrank, DerivativesMatchFiniteDifferences) {
  for (const auto& p : slider_cranks()) {
    const Q w = p.omega, L = p.r;
    for (Q phi : sweep<Q>()) {
      const auto m = linkref::slider_crank(p, phi - kStep);
      const auto z = linkref::slider_crank(p, phi);
      const auto pl = linkref::slider_crank(p, phi + kStep);
      const auto y = fd(m.y, z.y, pl.y, kStep, w);
      EXPECT_LE(rel(y.v, z.vy, L * w), kFd) << static_cast<double>(phi);
      EXPECT_LE(rel(y.a, z.ay, L * w * w), kFd) << static_cast<double>(phi);
      const auto psi = fd_angle(m.psi, z.psi, pl.psi, kStep, w);
      EXPECT_LE(rel(psi.v, z.dpsi, w), kFd) << static_cast<double>(phi);
      EXPECT_LE(rel(psi.a, z.ddpsi, w * w), kFd) << static_cast<double>(phi);
    }
  }
}

template <class T>
void slider_crank_precision_check() {
  for (const auto& p : slider_cranks()) {
    const auto pt = cast<T>(p);
    const Q w = p.omega, L = p.r;
    for (Q phi : sweep<Q>()) {
      const auto q = linkref::slider_crank(p, phi);
      const auto t = linkref::slider_crank(pt, T(phi));
      EXPECT_LE(rel(Q(t.y), q.y, L), kDouble);
      EXPECT_LE(rel(Q(t.vy), q.vy, L * w), kDouble);
      EXPECT_LE(rel(Q(t.ay), q.ay, L * w * w), kDouble);
      EXPECT_LE(rel(Q(t.psi), q.psi, Q(1)), kDouble);
      EXPECT_LE(rel(Q(t.dpsi), q.dpsi, w), kDouble);
      EXPECT_LE(rel(Q(t.ddpsi), q.ddpsi, w * w), kDouble);
    }
  }
}

TEST(ReferenceSliderCrank, DoubleAndLongDoubleAgreeWithQuad) {
  slider_crank_precision_check<double>();
  slider_crank_precision_check<long double>();
}

TEST(ReferenceSliderCrank, PaperFormAgreesWithCoordinates) {
  for (Q l : {Q(30), Q(50)}) {
    const auto p = linkref::slider_crank_22a(l);
    const Q lambda = p.r / p.l, w = p.omega;
    // Drawn start (outer dead centre, ccw): the paper's angle is phi + pi.
    for (Q phi : sweep<Q>()) {
      const auto st = linkref::slider_crank(p, phi);
      const auto pa = linkref::paper_slider_crank(p.r, lambda, w, phi + linkref::pi<Q>());
      EXPECT_LE(rel(pa.S, st.y - (p.l - p.r), p.r), kClose);
      EXPECT_LE(rel(pa.v, st.vy, p.r * w), kClose);
      EXPECT_LE(rel(pa.a, st.ay, p.r * w * w), kClose);
    }
    // Started at the paper's own origin (inner dead centre) and turning clockwise:
    // phi_B = s (theta + pi / 2) = phi.
    auto cw = p;
    cw.a0 = -linkref::pi<Q>() / 2;
    cw.s = -1;
    for (Q phi : sweep<Q>()) {
      const auto st = linkref::slider_crank(cw, phi);
      const auto pa = linkref::paper_slider_crank(p.r, lambda, w, phi);
      EXPECT_LE(rel(pa.S, st.y - (p.l - p.r), p.r), kClose);
      EXPECT_LE(rel(pa.v, st.vy, p.r * w), kClose);
      EXPECT_LE(rel(pa.a, st.ay, p.r * w * w), kClose);
    }
    // The paper's dead-centre accelerations: r w^2 (1 - lambda) at phi_B = 0 (its "a_min") and
    // -r w^2 (1 + lambda) at phi_B = pi (its largest, at the needle's lower dead centre).
    const Q rw2 = p.r * w * w;
    EXPECT_LE(rel(linkref::paper_slider_crank(p.r, lambda, w, Q(0)).a, rw2 * (1 - lambda), rw2),
              kClose);
    EXPECT_LE(rel(linkref::paper_slider_crank(p.r, lambda, w, linkref::pi<Q>()).a,
                  -rw2 * (1 + lambda), rw2),
              kClose);
    EXPECT_LE(rel(linkref::paper_slider_crank(p.r, lambda, w, linkref::pi<Q>()).S, 2 * p.r, p.r),
              kClose);
  }
}

// ------------------------------------------------------------------------------------------------
// Four-bar

// The example, the same turned and moved (ground at an angle), and a crossed, clockwise variant.
std::vector<linkref::FourBarParams<Q>> four_bars() {
  auto ex = linkref::four_bar_crank_rocker_example<Q>();
  auto turned = ex;
  const Q beta = Q(2.2), c = linkref::cos(beta), s = linkref::sin(beta);
  turned.O2 = Vec2<Q>{Q(-13), Q(41)};
  turned.O4 = turned.O2 + linkref::rotate(ex.O4 - ex.O2, c, s);
  turned.theta20 += beta;
  auto crossed = turned;
  crossed.branch = linkref::FourBarBranch::kCrossed;
  crossed.s = -1;
  crossed.omega = linkref::rpm_to_rad_s(Q(333));
  crossed.px = Q(-12), crossed.py = Q(-40);
  return {ex, turned, crossed};
}

template <class T>
linkref::FourBarParams<T> cast(const linkref::FourBarParams<Q>& p) {
  linkref::FourBarParams<T> o;
  o.O2 = {T(p.O2.x), T(p.O2.y)};
  o.O4 = {T(p.O4.x), T(p.O4.y)};
  o.r2 = T(p.r2), o.r3 = T(p.r3), o.r4 = T(p.r4), o.theta20 = T(p.theta20);
  o.s = p.s, o.omega = T(p.omega), o.branch = p.branch, o.px = T(p.px), o.py = T(p.py);
  return o;
}

TEST(ReferenceFourBar, PositionsCloseTheLoop) {
  for (const auto& p : four_bars()) {
    for (Q phi : sweep<Q>()) {
      const auto st = linkref::four_bar(p, phi);
      const Q L = p.r3;
      EXPECT_LE(rel(linkref::norm(st.A - p.O2), p.r2, L), kClose);
      EXPECT_LE(rel(linkref::norm(st.B - st.A), p.r3, L), kClose);
      EXPECT_LE(rel(linkref::norm(st.B - p.O4), p.r4, L), kClose);
      const Vec2<Q> u = linkref::unit_at(st.theta3);
      EXPECT_LE(rel(linkref::dot(st.P - st.A, u), p.px, L), kClose);
      EXPECT_LE(rel(linkref::cross(u, st.P - st.A), p.py, L), kClose);
      const Vec2<Q> c = p.O4 + p.r4 * linkref::unit_at(st.theta4);
      EXPECT_LE(rel(c.x, st.B.x, L), kClose);
      EXPECT_LE(rel(c.y, st.B.y, L), kClose);
      const Q side = linkref::cross(p.O4 - st.A, st.B - st.A);
      EXPECT_EQ(side > 0, p.branch == linkref::FourBarBranch::kOpen);
    }
  }
}

TEST(ReferenceFourBar, DerivativesMatchFiniteDifferences) {
  for (const auto& p : four_bars()) {
    const Q w = p.omega, L = p.r3;
    for (Q phi : sweep<Q>()) {
      const auto m = linkref::four_bar(p, phi - kStep);
      const auto z = linkref::four_bar(p, phi);
      const auto pl = linkref::four_bar(p, phi + kStep);
      const auto t3 = fd_angle(m.theta3, z.theta3, pl.theta3, kStep, w);
      const auto t4 = fd_angle(m.theta4, z.theta4, pl.theta4, kStep, w);
      EXPECT_LE(rel(t3.v, z.w3, w), kFd);
      EXPECT_LE(rel(t3.a, z.al3, w * w), kFd);
      EXPECT_LE(rel(t4.v, z.w4, w), kFd);
      EXPECT_LE(rel(t4.a, z.al4, w * w), kFd);
      auto check = [&](auto get_p, auto get_v, auto get_a) {
        for (int k = 0; k < 2; ++k) {
          auto comp = [k](Vec2<Q> v) { return k == 0 ? v.x : v.y; };
          const auto d = fd(comp(get_p(m)), comp(get_p(z)), comp(get_p(pl)), kStep, w);
          EXPECT_LE(rel(d.v, comp(get_v(z)), L * w), kFd);
          EXPECT_LE(rel(d.a, comp(get_a(z)), L * w * w), kFd);
        }
      };
      using S = linkref::FourBarState<Q>;
      check([](const S& s) { return s.A; }, [](const S& s) { return s.vA; },
            [](const S& s) { return s.aA; });
      check([](const S& s) { return s.B; }, [](const S& s) { return s.vB; },
            [](const S& s) { return s.aB; });
      check([](const S& s) { return s.P; }, [](const S& s) { return s.vP; },
            [](const S& s) { return s.aP; });
    }
  }
}

template <class T>
void four_bar_precision_check() {
  for (const auto& p : four_bars()) {
    const auto pt = cast<T>(p);
    const Q w = p.omega, L = p.r3;
    for (Q phi : sweep<Q>()) {
      const auto q = linkref::four_bar(p, phi);
      const auto t = linkref::four_bar(pt, T(phi));
      EXPECT_LE(static_cast<double>(linkref::abs(wrap(Q(t.theta3) - q.theta3))), kDouble);
      EXPECT_LE(static_cast<double>(linkref::abs(wrap(Q(t.theta4) - q.theta4))), kDouble);
      EXPECT_LE(rel(Q(t.w3), q.w3, w), kDouble);
      EXPECT_LE(rel(Q(t.w4), q.w4, w), kDouble);
      EXPECT_LE(rel(Q(t.al3), q.al3, w * w), kDouble);
      EXPECT_LE(rel(Q(t.al4), q.al4, w * w), kDouble);
      EXPECT_LE(rel(Q(t.P.x), q.P.x, L), kDouble);
      EXPECT_LE(rel(Q(t.P.y), q.P.y, L), kDouble);
      EXPECT_LE(rel(Q(t.vP.x), q.vP.x, L * w), kDouble);
      EXPECT_LE(rel(Q(t.vP.y), q.vP.y, L * w), kDouble);
      EXPECT_LE(rel(Q(t.aP.x), q.aP.x, L * w * w), kDouble);
      EXPECT_LE(rel(Q(t.aP.y), q.aP.y, L * w * w), kDouble);
      EXPECT_LE(rel(Q(t.aB.x), q.aB.x, L * w * w), kDouble);
      EXPECT_LE(rel(Q(t.aB.y), q.aB.y, L * w * w), kDouble);
    }
  }
}

TEST(ReferenceFourBar, DoubleAndLongDoubleAgreeWithQuad) {
  four_bar_precision_check<double>();
  four_bar_precision_check<long double>();
}

// Norton's closed form for theta4 (ground along +x): an independent derivation of the open branch.
TEST(ReferenceFourBar, OpenBranchIsNortonsOpenCircuit) {
  const auto p = linkref::four_bar_crank_rocker_example<Q>();
  const Q a = p.r2, b = p.r3, c = p.r4, d = p.O4.x - p.O2.x;
  const Q K1 = d / a, K2 = d / c, K3 = (a * a - b * b + c * c + d * d) / (2 * a * c);
  for (Q phi : sweep<Q>()) {
    const auto st = linkref::four_bar(p, phi);
    const Q c2 = linkref::cos(st.theta2), s2 = linkref::sin(st.theta2);
    const Q A = c2 - K1 - K2 * c2 + K3, B = -2 * s2, C = K1 - (K2 + 1) * c2 + K3;
    const Q open = 2 * linkref::atan2(-B - linkref::sqrt(B * B - 4 * A * C), 2 * A);
    EXPECT_LE(static_cast<double>(linkref::abs(wrap(open - st.theta4))), 1e-28);
  }
}

TEST(ReferenceFourBar, TurnedGroundIsARigidMotionOfTheExample) {
  const auto all = four_bars();
  const auto &ex = all[0], &turned = all[1];
  const Q beta = turned.theta20 - ex.theta20;
  const Q c = linkref::cos(beta), s = linkref::sin(beta);
  for (Q phi : sweep<Q>()) {
    const auto a = linkref::four_bar(ex, phi);
    const auto b = linkref::four_bar(turned, phi);
    const Vec2<Q> P = turned.O2 + linkref::rotate(a.P - ex.O2, c, s);
    EXPECT_LE(rel(P.x, b.P.x, ex.r3), kClose);
    EXPECT_LE(rel(P.y, b.P.y, ex.r3), kClose);
    EXPECT_LE(static_cast<double>(linkref::abs(wrap(a.theta4 + beta - b.theta4))), kClose);
    EXPECT_LE(rel(a.al3, b.al3, ex.omega * ex.omega), kClose);
  }
}

TEST(ReferenceFourBar, GrashofClassesAndReach) {
  using G = linkref::Grashof;
  EXPECT_EQ(linkref::grashof_class(linkref::four_bar_crank_rocker_example<Q>()), G::kCrankRocker);
  EXPECT_EQ(linkref::grashof_class(20.0, 60.0, 70.0, 50.0), G::kDoubleCrank);
  EXPECT_EQ(linkref::grashof_class(60.0, 50.0, 20.0, 70.0), G::kDoubleRocker);
  EXPECT_EQ(linkref::grashof_class(60.0, 50.0, 70.0, 20.0), G::kRockerCrank);
  EXPECT_EQ(linkref::grashof_class(40.0, 20.0, 40.0, 20.0), G::kChangePoint);
  EXPECT_EQ(linkref::grashof_class(60.0, 50.0, 40.0, 45.0), G::kTripleRocker);

  // A crank-rocker reaches every crank angle.
  const auto ex = linkref::four_bar_crank_rocker_example<double>();
  for (double phi : sweep<double>()) EXPECT_TRUE(linkref::four_bar_reachable(ex, phi));

  // A triple rocker (ground 60, input 50, coupler 40, output 45) reaches the sketch at 60 degrees
  // but not with its input pointing away from O4 (|O4 - A| = 110 > 40 + 45).
  auto tr = ex;
  tr.r2 = 50, tr.r3 = 40, tr.r4 = 45;
  EXPECT_TRUE(linkref::four_bar_reachable(tr, 0.0));
  const double away = linkref::deg2rad(120.0);
  EXPECT_FALSE(linkref::four_bar_reachable(tr, away));
  EXPECT_LT(linkref::four_bar_discriminant(tr, away), 0.0);
  EXPECT_THROW(linkref::four_bar(tr, away), std::domain_error);
}

// ------------------------------------------------------------------------------------------------
// Wanzer

const linkref::WanzerInversion kInversions[] = {linkref::WanzerInversion::k1,
                                                linkref::WanzerInversion::k2};

template <class T>
linkref::Wanzer<T> wanzer(linkref::WanzerInversion inv) {
  return linkref::Wanzer<T>(linkref::wanzer_homework_params<T>(inv));
}

TEST(ReferenceWanzer, SketchIsTheHomeworkSolution) {
  auto w2 = wanzer<Q>(linkref::WanzerInversion::k2);
  EXPECT_NEAR(static_cast<double>(w2.sketch().E.y), 19.9279, 5e-5);
  EXPECT_NEAR(static_cast<double>(w2.sketch().F.x), 22.5473, 5e-5);
  EXPECT_NEAR(static_cast<double>(w2.sketch().G.y), -41.2603, 5e-5);
  auto w1 = wanzer<Q>(linkref::WanzerInversion::k1);
  EXPECT_NEAR(static_cast<double>(w1.sketch().E.x), -4.5132, 5e-5);
  EXPECT_NEAR(static_cast<double>(w1.sketch().F.y), 3.2644, 5e-5);
  EXPECT_NEAR(static_cast<double>(w1.sketch().G.y), -51.8355, 5e-5);
  for (auto inv : kInversions) {
    auto w = wanzer<Q>(inv);
    const auto& sk = w.sketch();
    EXPECT_LE(rel(linkref::norm(sk.E - sk.F), Q(16), Q(62)), kClose);
    EXPECT_LE(rel(linkref::norm(sk.F - sk.G), Q(56), Q(62)), kClose);
    EXPECT_LE(rel(linkref::norm(sk.E - sk.G), Q(62), Q(62)), kClose);
    // The one-angle formulation starts exactly where the homework's Newton ended.
    const auto st = w.at(Q(0));
    EXPECT_LE(rel(st.E.x, sk.E.x, Q(62)), kClose);
    EXPECT_LE(rel(st.E.y, sk.E.y, Q(62)), kClose);
    EXPECT_LE(rel(st.F.x, sk.F.x, Q(62)), kClose);
    EXPECT_LE(rel(st.F.y, sk.F.y, Q(62)), kClose);
    EXPECT_LE(rel(st.G.y, sk.G.y, Q(62)), kClose);
  }
}

TEST(ReferenceWanzer, PositionsSatisfyTheJointsOverTwoTurns) {
  for (auto inv : kInversions) {
    auto w = wanzer<Q>(inv);
    const auto& p = w.params();
    for (Q phi : sweep<Q>(2)) {
      const auto st = w.at(phi);
      const Q L = Q(62);
      EXPECT_LE(rel(linkref::norm(st.E - st.F), p.EF, L), kClose);
      EXPECT_LE(rel(linkref::norm(st.F - st.G), p.FG, L), kClose);
      EXPECT_LE(rel(linkref::norm(st.E - st.G), p.EG, L), kClose);
      EXPECT_LE(rel(st.G.x, Q(0), L), kClose);
      // Disk axes in global coordinates: slot B is {x_disk = eB}, slot C is {y_disk = eC}.
      const Q th = -phi;
      const Vec2<Q> ex{linkref::cos(th), linkref::sin(th)}, ey = linkref::perp(ex);
      const Vec2<Q>& onB = inv == linkref::WanzerInversion::k2 ? st.E : st.F;
      const Vec2<Q>& onC = inv == linkref::WanzerInversion::k2 ? st.F : st.E;
      EXPECT_LE(rel(linkref::dot(onB, ex), p.eB, L), kClose);
      EXPECT_LE(rel(linkref::dot(onC, ey), p.eC, L), kClose);
      // E, G, F stay counter-clockwise: the triangle is never mirrored.
      EXPECT_LT(linkref::cross(st.F - st.E, st.G - st.E), Q(0));
      EXPECT_LE(
          static_cast<double>(linkref::abs(wrap(st.tri_angle - linkref::angle_of(st.F - st.E)))),
          kClose);
    }
  }
}

TEST(ReferenceWanzer, DerivativesMatchFiniteDifferences) {
  for (auto inv : kInversions) {
    auto w = wanzer<Q>(inv);
    const Q om = w.params().omega, L = Q(62);
    for (Q phi : sweep<Q>()) {
      const auto m = w.at(phi - kStep);
      const auto pl = w.at(phi + kStep);
      const auto z = w.at(phi);
      using S = linkref::WanzerState<Q>;
      const auto pts = {
          std::make_tuple(&S::E, &S::vE, &S::aE),
          std::make_tuple(&S::F, &S::vF, &S::aF),
          std::make_tuple(&S::G, &S::vG, &S::aG),
      };
      for (const auto& [P, V, A] : pts) {
        const auto dx = fd((m.*P).x, (z.*P).x, (pl.*P).x, kStep, om);
        const auto dy = fd((m.*P).y, (z.*P).y, (pl.*P).y, kStep, om);
        EXPECT_LE(rel(dx.v, (z.*V).x, L * om), kFd) << static_cast<double>(phi);
        EXPECT_LE(rel(dy.v, (z.*V).y, L * om), kFd) << static_cast<double>(phi);
        EXPECT_LE(rel(dx.a, (z.*A).x, L * om * om), kFd) << static_cast<double>(phi);
        EXPECT_LE(rel(dy.a, (z.*A).y, L * om * om), kFd) << static_cast<double>(phi);
      }
      const auto t = fd_angle(m.tri_angle, z.tri_angle, pl.tri_angle, kStep, om);
      EXPECT_LE(rel(t.v, z.tri_omega, om), kFd);
      EXPECT_LE(rel(t.a, z.tri_alpha, om * om), kFd);
    }
  }
}

template <class T>
void wanzer_precision_check() {
  for (auto inv : kInversions) {
    auto q = wanzer<Q>(inv);
    auto t = wanzer<T>(inv);
    const Q om = q.params().omega, L = Q(62);
    for (Q phi : sweep<Q>(2)) {
      const auto a = q.at(phi);
      const auto b = t.at(T(phi));
      EXPECT_LE(rel(Q(b.G.y), a.G.y, L), kDouble);
      EXPECT_LE(rel(Q(b.vG.y), a.vG.y, L * om), kDouble);
      EXPECT_LE(rel(Q(b.aG.y), a.aG.y, L * om * om), kDouble);
      EXPECT_LE(rel(Q(b.E.x), a.E.x, L), kDouble);
      EXPECT_LE(rel(Q(b.F.y), a.F.y, L), kDouble);
      EXPECT_LE(rel(Q(b.aE.x), a.aE.x, L * om * om), kDouble);
      EXPECT_LE(rel(Q(b.aF.y), a.aF.y, L * om * om), kDouble);
      EXPECT_LE(static_cast<double>(linkref::abs(wrap(Q(b.tri_angle) - a.tri_angle))), kDouble);
      EXPECT_LE(rel(Q(b.tri_omega), a.tri_omega, om), kDouble);
      EXPECT_LE(rel(Q(b.tri_alpha), a.tri_alpha, om * om), kDouble);
    }
  }
}

TEST(ReferenceWanzer, DoubleAndLongDoubleAgreeWithQuad) {
  wanzer_precision_check<double>();
  wanzer_precision_check<long double>();
}

// After a full disk turn the mechanism is back where it started (same assembly), and the state
// at an angle does not depend on the path the continuation took to it.
TEST(ReferenceWanzer, PeriodicAndPathIndependent) {
  for (auto inv : kInversions) {
    auto w = wanzer<Q>(inv);
    const Q om = w.params().omega, L = Q(62), two_pi = 2 * linkref::pi<Q>();
    for (Q phi : sweep<Q>()) {
      auto fresh = wanzer<Q>(inv);
      const auto a = fresh.at(phi);
      const auto b = w.at(phi + two_pi);
      EXPECT_LE(rel(a.G.y, b.G.y, L), 1e-28);
      EXPECT_LE(rel(a.vG.y, b.vG.y, L * om), 1e-28);
      EXPECT_LE(rel(a.aG.y, b.aG.y, L * om * om), 1e-28);
      EXPECT_LE(rel(a.E.x, b.E.x, L), 1e-28);
      EXPECT_LE(static_cast<double>(linkref::abs(wrap(a.tri_angle - b.tri_angle))), 1e-28);
    }
    // Back down from two turns to a quarter turn: the same state again.
    auto fresh = wanzer<Q>(inv);
    const Q quarter = linkref::pi<Q>() / 2;
    const auto a = fresh.at(quarter);
    w.at(2 * two_pi);
    const auto b = w.at(quarter);
    EXPECT_LE(rel(a.G.y, b.G.y, L), 1e-28);
    EXPECT_LE(rel(a.aG.y, b.aG.y, L * om * om), 1e-28);
  }
}

}  // namespace
