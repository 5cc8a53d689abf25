// Spreads of a closest approach and a window's ends (linkage/cycle_spread.h).
#include "linkage/cycle_spread.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <thread>

#include "linkage/clearance_sensitivity.h"
#include "linkage/window_sensitivity.h"

namespace linkage {

namespace {

// The toleranced dimensions (in the order of dimensions(m)) and their tolerances.
Status toleranced(const Mechanism& m, const ToleranceSpec& spec, std::vector<Dimension>& dims,
                  std::vector<double>& T) {
  const std::vector<Dimension> all = dimensions(m);
  for (const ToleranceSpec::Tol& t : spec.tolerances) {
    if (t.play)
      return Status::badModel(t.dimension +
                              ": a pin's play is not carried to a clearance or a "
                              "window yet (the point's band carries it)");
    auto it = std::find_if(all.begin(), all.end(),
                           [&](const Dimension& d) { return d.name == t.dimension; });
    if (it == all.end()) return Status::badModel("no dimension '" + t.dimension + "'");
    dims.push_back(*it);
    T.push_back(t.plusMinus);
  }
  return Status::success();
}

void firstOrder(Spread& s, const std::vector<double>& d, const std::vector<double>& T) {
  for (size_t k = 0; k < d.size(); ++k) {
    s.worst += std::abs(d[k]) * T[k];
    s.rss += d[k] * T[k] * d[k] * T[k];
  }
  s.rss = std::sqrt(s.rss);
  s.lo = s.hi = s.mean = s.nominal;
}

// Each sample measured by `measure` (its values, in the nominal's order; false with why when it
// cannot be measured), gathered into out.values. The samples are solved on every core (each
// thread from its own copy of the nominal) and gathered in their order: the same figures on any
// number of threads.
using Measure = std::function<bool(const Kinematics&, std::vector<double>&, std::string&)>;
void monteCarlo(const Mechanism& m, const ToleranceSpec& spec, const Kinematics& nominal,
                const Measure& measure, SpreadResult& out) {
  const long long n = std::max(0LL, static_cast<long long>(spec.samples));
  const size_t width = out.values.size();
  std::vector<std::vector<double>> got(n);
  std::vector<std::string> why(n);
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int threads = static_cast<int>(
      std::clamp<long long>(spec.threads > 0 ? spec.threads : cores, 1, std::max(1LL, n)));
  std::vector<Kinematics> bases(threads, nominal);
  std::atomic<long long> next{0};
  auto work = [&](int t) {
    for (long long i; (i = next++) < n;) {
      Mechanism sample;
      Kinematics k = bases[t];
      std::vector<double> v;
      Status s = toleranceSample(m, spec, i, sample);
      if (s.ok()) s = k.edit(sample);
      if (!s.ok())
        why[i] = s.message;
      else if (measure(k, v, why[i]) && v.size() == width)
        got[i] = std::move(v);
      else if (why[i].empty())
        why[i] = "not measured";
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (std::thread& th : pool) th.join();
  std::vector<double> sum(width, 0.0), sum2(width, 0.0);
  for (long long i = 0; i < n; ++i) {
    ++out.samples;
    if (got[i].size() != width || width == 0) {
      if (out.firstFailure.empty())
        out.firstFailure = "sample " + std::to_string(i) + ": " + why[i];
      continue;
    }
    ++out.used;
    for (size_t j = 0; j < width; ++j) {
      Spread& x = out.values[j];
      x.lo = std::min(x.lo, got[i][j]);
      x.hi = std::max(x.hi, got[i][j]);
      sum[j] += got[i][j];
      sum2[j] += got[i][j] * got[i][j];
    }
  }
  for (size_t j = 0; j < width && out.used > 0; ++j) {
    Spread& x = out.values[j];
    x.mean = sum[j] / out.used;
    x.sd = std::sqrt(std::max(0.0, sum2[j] / out.used - x.mean * x.mean));
  }
}

}  // namespace

SpreadResult clearanceSpread(const Mechanism& m, const ToleranceSpec& spec,
                             const ClearanceWatch& w) {
  SpreadResult out;
  std::vector<Dimension> dims;
  std::vector<double> T;
  Kinematics k;
  if (!(out.status = toleranced(m, spec, dims, T)).ok() || !(out.status = k.load(m)).ok())
    return out;
  const ClearanceSensitivity s = clearanceSensitivity(k, w, dims);
  if (!(out.status = s.status).ok()) return out;
  Spread x;
  x.nominal = s.clearance.closest.distance;
  firstOrder(x, s.derivative, T);
  out.values = {x};
  const ClearancePart a = ClearancePart::of(w.point);
  monteCarlo(
      m, spec, k,
      [&](const Kinematics& ks, std::vector<double>& v, std::string& why) {
        const Clearance c = findClearance(ks, a, w.other);
        why = c.status.message;
        v = {c.closest.distance};
        return c.status.ok();
      },
      out);
  return out;
}

SpreadResult windowSpread(const Mechanism& m, const ToleranceSpec& spec, const std::string& name) {
  SpreadResult out;
  std::vector<Dimension> dims;
  std::vector<double> T;
  Kinematics k;
  if (!(out.status = toleranced(m, spec, dims, T)).ok() || !(out.status = k.load(m)).ok())
    return out;
  const WindowSensitivity s = windowSensitivity(k, name, dims);
  if (!(out.status = s.status).ok()) return out;
  for (const WindowEndSensitivity& i : s.intervals)
    for (const auto& [at, d] : {std::pair{i.fromDeg, &i.dFrom}, std::pair{i.toDeg, &i.dTo}}) {
      Spread x;
      x.nominal = at;
      firstOrder(x, *d, T);
      out.values.push_back(x);
    }
  monteCarlo(
      m, spec, k,
      [&](const Kinematics& ks, std::vector<double>& v, std::string& why) {
        const CycleDiagram c = cycleDiagram(ks, ks.mechanism().timing);
        why = c.status.message;
        for (const WindowIntervals& wi : c.windows)
          if (wi.name == name)
            for (const AngleInterval& i : wi.intervals) v.insert(v.end(), {i.fromDeg, i.toDeg});
        if (c.status.ok() && v.size() != out.values.size())
          why = "its window has " + std::to_string(v.size() / 2) + " intervals, the nominal " +
                std::to_string(out.values.size() / 2);
        return c.status.ok() && v.size() == out.values.size();
      },
      out);
  return out;
}

}  // namespace linkage
