// Run time against error (docs/accuracy-and-speed.md, made by bench/accuracy_report.py): one
// iteration is one revolution of a mechanism with an exact answer, sampled at N steps, by one
// method; the counters carry the method's worst errors over that revolution against the exact
// closed forms (tests/reference, long double):
//   exact        the core's velocity and acceleration (linear solves with the Jacobian)
//   exact_newton the same through the general Newton solve, Newton tolerance as given
//   fd           central differences of the core's positions (2nd order)
//   lagrange5/7  derivatives of local Lagrange polynomials through 5 / 7 samples (as in the
//                overedge-machine paper, seeds/004)
#include <benchmark/benchmark.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "linkage/kinematics.h"
#include "mechanisms.h"
#include "reference/four_bar.h"
#include "reference/slider_crank.h"

namespace {

using namespace linkage;
using LD = long double;

struct Case {
  std::string name;
  Mechanism m;
  PointId point;
  double omega;  // rad/s
  // Exact y, vy, ay (slider) or x, y with derivatives (four-bar) at crank angle phi (rad).
  std::function<void(double, Vec2&, Vec2&, Vec2&)> exact;
};

Case makeCase(const std::string& name) {
  Case c;
  c.name = name;
  if (name == "four_bar") {
    auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25, Direction::Ccw, 60);
    c.m = f.m;
    c.point = f.P;
    linkref::FourBarParams<LD> p;
    p.O2 = {0, 0};
    p.O4 = {60, 0};
    p.r2 = 20, p.r3 = 70, p.r4 = 50;
    p.theta20 = linkref::deg2rad(LD(60));
    p.s = 1;
    p.omega = linkref::rpm_to_rad_s(LD(60));
    p.px = 35, p.py = 25;
    c.omega = double(p.omega);
    c.exact = [p](double phi, Vec2& x, Vec2& v, Vec2& a) {
      const auto r = linkref::four_bar(p, LD(phi));
      x = Vec2(double(r.P.x), double(r.P.y));
      v = Vec2(double(r.vP.x), double(r.vP.y));
      a = Vec2(double(r.aP.x), double(r.aP.y));
    };
  } else {
    const double e = name == "slider_crank_offset" ? 5 : 0;
    auto s = test::sliderCrank(15, 30, e, 90, Direction::Ccw, 1000);
    c.m = s.m;
    c.point = s.B;
    linkref::SliderCrankParams<LD> p;
    p.r = 15, p.l = 30, p.e = e, p.a0 = linkref::pi<LD>() / 2, p.s = 1;
    p.omega = linkref::rpm_to_rad_s(LD(1000));
    c.omega = double(p.omega);
    c.exact = [p, e](double phi, Vec2& x, Vec2& v, Vec2& a) {
      const auto r = linkref::slider_crank(p, LD(phi));
      x = Vec2(e, double(r.y));
      v = Vec2(0, double(r.vy));
      a = Vec2(0, double(r.ay));
    };
  }
  return c;
}

// Derivative weights of the Lagrange polynomial through 2m+1 equally spaced samples, at the
// middle one (h = 1): first and second derivative.
void lagrangeWeights(int m, std::vector<double>& d1, std::vector<double>& d2) {
  const int n = 2 * m + 1;
  d1.assign(n, 0);
  d2.assign(n, 0);
  for (int j = 0; j < n; ++j) {
    // L_j(x) = prod_{k != j} (x - x_k) / (x_j - x_k), x_k = k - m; derivatives at x = 0.
    double denom = 1;
    for (int k = 0; k < n; ++k)
      if (k != j) denom *= (j - k);
    double s1 = 0, s2 = 0;
    for (int a = 0; a < n; ++a) {
      if (a == j) continue;
      double p1 = 1;  // product over k != j, a of (0 - x_k)
      for (int k = 0; k < n; ++k)
        if (k != j && k != a) p1 *= -(k - m);
      s1 += p1;
      for (int b = 0; b < n; ++b) {
        if (b == j || b == a) continue;
        double p2 = 1;
        for (int k = 0; k < n; ++k)
          if (k != j && k != a && k != b) p2 *= -(k - m);
        s2 += p2;
      }
    }
    d1[j] = s1 / denom;
    d2[j] = s2 / denom;
  }
}

struct Errors {
  double pos = 0, vel = 0, acc = 0;
};

// One revolution by `method`; returns the samples' positions, velocities, accelerations.
void revolution(Kinematics& k, const Case& c, long n, long rev, const std::string& method,
                std::vector<Vec2>& x, std::vector<Vec2>& v, std::vector<Vec2>& a) {
  x.resize(n);
  v.resize(n);
  a.resize(n);
  const bool exact = method.rfind("exact", 0) == 0;
  for (long i = 0; i < n; ++i) {
    k.moveTo(360.0 * rev + 360.0 * static_cast<double>(i) / static_cast<double>(n));
    x[i] = k.position(c.point);
    if (exact) {
      v[i] = k.velocity(c.point);
      a[i] = k.acceleration(c.point);
    }
  }
  if (exact) return;
  const int m = method == "fd" ? 1 : method == "lagrange5" ? 2 : 3;
  std::vector<double> d1, d2;
  lagrangeWeights(m, d1, d2);
  const double h = 2 * M_PI / static_cast<double>(n) / c.omega;  // seconds per sample
  for (long i = 0; i < n; ++i) {
    Vec2 s1 = Vec2::Zero(), s2 = Vec2::Zero();
    for (int j = -m; j <= m; ++j) {
      const Vec2& xj = x[((i + j) % n + n) % n];  // the motion is periodic
      s1 += d1[j + m] * xj;
      s2 += d2[j + m] * xj;
    }
    v[i] = s1 / h;
    a[i] = s2 / (h * h);
  }
}

void accuracy(benchmark::State& state, const std::string& caseName, const std::string& method) {
  const Case c = makeCase(caseName);
  const long n = state.range(0);
  KinematicsOptions opt;
  // Positions come from the fastest exact solve for every method but the Newton sweep.
  opt.closedForm = method != "exact_newton";
  if (method == "exact_newton") opt.newton.relTol = std::pow(10.0, -double(state.range(1)));
  Kinematics k(opt);
  if (!k.load(c.m).ok()) {
    state.SkipWithError("cannot load");
    return;
  }
  std::vector<Vec2> x, v, a;
  long rev = 0;
  for (auto _ : state) {
    revolution(k, c, n, rev++, method, x, v, a);
    benchmark::DoNotOptimize(a.data());
  }
  Errors e;
  double peakV = 0, peakA = 0;
  for (long i = 0; i < n; ++i) {
    Vec2 X, V, A;
    c.exact(2 * M_PI * static_cast<double>(i) / static_cast<double>(n), X, V, A);
    e.pos = std::max(e.pos, (x[i] - X).norm());
    e.vel = std::max(e.vel, (v[i] - V).norm());
    e.acc = std::max(e.acc, (a[i] - A).norm());
    peakV = std::max(peakV, V.norm());
    peakA = std::max(peakA, A.norm());
  }
  state.counters["steps"] = static_cast<double>(n);
  state.counters["pos_err_mm"] = e.pos;
  state.counters["vel_err_rel"] = e.vel / peakV;
  state.counters["acc_err_rel"] = e.acc / peakA;
}

void registerAll() {
  for (const char* cs : {"slider_crank", "slider_crank_offset", "four_bar"}) {
    for (const char* method : {"exact", "fd", "lagrange5", "lagrange7"}) {
      auto* b = benchmark::RegisterBenchmark((std::string("accuracy/") + cs + "/" + method).c_str(),
                                             [cs = std::string(cs), method = std::string(method)](
                                                 benchmark::State& s) { accuracy(s, cs, method); });
      for (long n : {36, 360, 3600, 36000}) b->Args({n});
      b->Unit(benchmark::kMicrosecond);
    }
    auto* b = benchmark::RegisterBenchmark(
        (std::string("accuracy/") + cs + "/exact_newton").c_str(),
        [cs = std::string(cs)](benchmark::State& s) { accuracy(s, cs, "exact_newton"); });
    for (long n : {36, 360, 3600})
      for (long tol : {4, 7, 10, 13}) b->Args({n, tol});
    b->Unit(benchmark::kMicrosecond);
  }
}

const bool registered = (registerAll(), true);

}  // namespace
