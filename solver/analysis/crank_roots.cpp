#include "analysis/crank_roots.h"

#include <cmath>

namespace linkage {

namespace {

// The sign a sample stands for: a sample that is exactly zero takes the sign of the next one
// that is not, so that a root exactly at a sample is found once, in the interval that ends
// there, and a zero that only touches is no root.
int sideOf(const std::vector<RootSample>& s, size_t i, bool periodic) {
  const size_t n = s.size();
  for (size_t k = i, seen = 0; seen < n; ++seen) {
    if (s[k].g > 0) return 1;
    if (s[k].g < 0) return -1;
    if (k + 1 < n)
      ++k;
    else if (periodic && n > 1)
      k = 1;  // the last sample is the first one
    else
      return s[k].dg < 0 ? -1 : 1;
  }
  return 1;
}

int sign(double x) {
  return x > 0 ? 1 : -1;
}

// Where in (0, 1) the cubic Hermite interpolant of the interval is farthest on the other side
// of zero from its ends (of side `side`); -1 when it stays on their side.
double hermiteDip(const RootSample& a, const RootSample& b, double h, int side) {
  const double p0 = a.g, p1 = b.g, m0 = h * a.dg, m1 = h * b.dg;
  auto p = [&](double t) {
    const double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * p1 +
           (t3 - t2) * m1;
  };
  // p'(t) = A t^2 + B t + C
  const double A = 6 * p0 + 3 * m0 - 6 * p1 + 3 * m1, B = -6 * p0 - 4 * m0 + 6 * p1 - 2 * m1,
               C = m0;
  double ts[2];
  int n = 0;
  if (A == 0) {
    if (B != 0) ts[n++] = -C / B;
  } else {
    const double disc = B * B - 4 * A * C;
    if (disc >= 0) {
      const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
      if (q != 0) ts[n++] = C / q;
      ts[n++] = q / A;
    }
  }
  double best = -1, lowest = 0;
  for (int k = 0; k < n; ++k) {
    if (!(ts[k] > 0 && ts[k] < 1)) continue;
    const double v = side * p(ts[k]);
    if (v < lowest) {
      lowest = v;
      best = ts[k];
    }
  }
  return best;
}

Status refine(Kinematics& probe, const RootFunction& f, double a, RootSample ga, double b,
              RootSample gb, double tol, double& root) {
  if (ga.g == 0 || gb.g == 0) {
    root = ga.g == 0 ? a : b;
    return Status::success();
  }
  const int sa = sign(ga.g);
  // Start from Newton at the end nearer its root, else the secant.
  double x = a + (b - a) * ga.g / (ga.g - gb.g);
  const RootSample& near = std::abs(ga.g) < std::abs(gb.g) ? ga : gb;
  const double newton = (&near == &ga ? a : b) - near.g / near.dg;
  if (std::isfinite(newton) && newton > a && newton < b) x = newton;
  if (!(x > a && x < b)) x = 0.5 * (a + b);
  double lastStep = b - a;
  for (int it = 0; it < 200; ++it) {
    if (Status s = probe.moveTo(x); !s.ok()) return s;
    const RootSample gx = f(probe);
    if (gx.g == 0) {
      root = x;
      return Status::success();
    }
    if (sign(gx.g) == sa) {
      a = x;
      ga = gx;
    } else {
      b = x;
      gb = gx;
    }
    if (b - a <= tol) {
      root = std::abs(ga.g) < std::abs(gb.g) ? a : b;
      return Status::success();
    }
    const double n = x - gx.g / gx.dg;
    const double step = std::abs(n - x);
    if (std::isfinite(n) && n > a && n < b && step <= 0.5 * lastStep) {
      if (step <= 0.1 * tol) {
        root = n;
        return Status::success();
      }
      lastStep = step;
      x = n;
    } else {
      lastStep = b - a;
      x = 0.5 * (a + b);
    }
  }
  // Unreachable in practice: 200 halvings shrink any bracket below the tolerance.
  root = 0.5 * (a + b);
  return Status::success();
}

// Records a root with the channel's value there.
Status found(Kinematics& probe, RootChannel& c, double root, bool rising) {
  Root r{root, rising, 0};
  if (c.value) {
    // No step at all when the probe was last moved to exactly this angle.
    if (Status s = probe.moveTo(root); !s.ok()) return s;
    r.value = c.value(probe);
  }
  c.roots.push_back(r);
  return Status::success();
}

}  // namespace

Status findRoots(Kinematics& probe, const std::vector<double>& crank,
                 const std::vector<RootChannel*>& channels, bool periodic, double toleranceDeg) {
  for (RootChannel* c : channels) c->roots.clear();
  for (size_t i = 0; i + 1 < crank.size(); ++i) {
    const double a = crank[i], b = crank[i + 1];
    for (RootChannel* cp : channels) {
      RootChannel& c = *cp;
      const RootSample &ga = c.samples[i], &gb = c.samples[i + 1];
      const int sa = sideOf(c.samples, i, periodic), sb = sideOf(c.samples, i + 1, periodic);
      double root = 0;
      if (sa != sb) {
        if (Status s = refine(probe, c.f, a, ga, b, gb, toleranceDeg, root); !s.ok()) return s;
        if (Status s = found(probe, c, root, sb > 0); !s.ok()) return s;
        continue;
      }
      if (!c.pairs || ga.g == 0 || gb.g == 0) continue;
      const double t = hermiteDip(ga, gb, b - a, sa);
      if (t < 0) continue;
      const double mid = a + t * (b - a);
      if (Status s = probe.moveTo(mid); !s.ok()) return s;
      const RootSample gm = c.f(probe);
      if (gm.g == 0 || sign(gm.g) == sa) continue;  // the cubic dipped, g does not
      if (Status s = refine(probe, c.f, a, ga, mid, gm, toleranceDeg, root); !s.ok()) return s;
      if (Status s = found(probe, c, root, sa < 0); !s.ok()) return s;
      if (Status s = refine(probe, c.f, mid, gm, b, gb, toleranceDeg, root); !s.ok()) return s;
      if (Status s = found(probe, c, root, sa > 0); !s.ok()) return s;
    }
  }
  return Status::success();
}

}  // namespace linkage
