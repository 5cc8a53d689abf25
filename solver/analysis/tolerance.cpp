// Tolerances carried through the motion (linkage/tolerance.h): first order from the exact
// sensitivities, Monte Carlo by exact solves of changed designs on every core.
#include "linkage/tolerance.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

#include "analysis/dimensions_space.h"
#include "linkage/dimension_change.h"
#include "linkage/limits.h"
#include "linkage/sensitivity.h"
#include "linkage/space.h"

namespace linkage {

namespace {

// The named tolerances resolved: the design's dimensions (every one, for changeDimensions),
// which of them vary and by how much, the plays, and the columns handed to Sensitivity (the
// varied dimensions, then each play's x and y).
struct Resolved {
  // Read in the world (Sensitivity::Space::World, Kinematics::motionInSpace): a machine in space
  // or with a ball rod.
  bool world = false;
  std::vector<Dimension> all;
  std::vector<int> index;  // into all
  std::vector<double> T;
  std::vector<PinPlay> plays;
  std::vector<double> c;
  std::vector<Dimension> columns;
};

Status resolve(const Mechanism& m, const ToleranceSpec& spec, Resolved& r) {
  r.all = dimensions(m);
  r.world = internal::hasSpaceDimensions(m);
  for (const ToleranceSpec::Tol& t : spec.tolerances) {
    if (!(t.plusMinus >= 0) || !std::isfinite(t.plusMinus))
      return Status::badModel(t.dimension + ": a tolerance is a finite number >= 0");
    if (t.play) {
      PinPlay p;
      if (Status s = pinPlay(m, t.dimension, p); !s.ok()) return s;
      const Body* g = m.ground();
      if (isSpatial(m) && g && m.point(p.point)->body == g->id)
        return Status::badModel("pin " + t.dimension +
                                ": its play would move its point on the ground, whose x and y "
                                "are the world's, not its plane's: a play in space is of a pin "
                                "with a point on a moving body that no other joint holds");
      r.plays.push_back(p);
      r.c.push_back(t.plusMinus);
      continue;
    }
    auto it = std::find_if(r.all.begin(), r.all.end(),
                           [&](const Dimension& d) { return d.name == t.dimension; });
    if (it == r.all.end())
      return Status::badModel("unknown dimension " + t.dimension +
                              " (linkage-cli sensitivity lists the dimensions)");
    r.index.push_back(static_cast<int>(it - r.all.begin()));
    r.T.push_back(t.plusMinus);
    r.columns.push_back(*it);
  }
  for (const PinPlay& p : r.plays) {
    r.columns.push_back(p.x);
    r.columns.push_back(p.y);
  }
  return Status::success();
}

// Where the point is: in the world, or the drawing's x and y (z 0).
Vec3 positionOf(const Kinematics& k, PointId p, bool world) {
  if (world) return k.motionInSpace(p).position;
  const Vec2 at = k.position(p);
  return Vec3(at.x(), at.y(), 0);
}

Vec3 derivativeOf(const Sensitivity& s, const Kinematics& k, PointId p, int col, bool world) {
  if (world) return s.point3(k, p, col);
  const Vec2 d = s.point(k, p, col);
  return Vec3(d.x(), d.y(), 0);
}

Sensitivity::Space spaceOf(const Resolved& r) {
  return r.world ? Sensitivity::Space::World : Sensitivity::Space::Refuse;
}

// The first-order half-widths of a change of the point along `dir`, from the derivatives at s's
// pose (each column's d point / d p dotted with dir; a play's two columns a vector).
struct Linear {
  double worst = 0, rss = 0, sigma = 0;
};
template <class Derivative>
Linear linear(const Resolved& r, Derivative d) {
  Linear l;
  double rss2 = 0, var = 0;
  for (size_t k = 0; k < r.T.size(); ++k) {
    const double g = d(static_cast<int>(k)) * r.T[k];
    l.worst += std::abs(g);
    rss2 += g * g;
    var += g * g / 3;  // uniform in [-T, T]
  }
  for (size_t j = 0; j < r.plays.size(); ++j) {
    const int col = static_cast<int>(r.T.size() + 2 * j);
    const double g = std::hypot(d(col), d(col + 1)) * r.c[j];
    l.worst += g;
    rss2 += g * g;
    var += g * g / 4;  // uniform over the disc: E[(g . offset)^2] = |g|^2 c^2 / 4
  }
  l.rss = std::sqrt(rss2);
  l.sigma = std::sqrt(var);
  return l;
}

// The nominal rows: position and first order at each crank angle.
Status firstOrderRows(const Kinematics& k0, const Resolved& r, const ToleranceSpec& spec,
                      ToleranceResult& out) {
  Kinematics k = k0;
  Sensitivity s;
  if (Status st = s.prepare(k, r.columns, spaceOf(r)); !st.ok()) return st;
  const int axes = isSpatial(k0.mechanism()) ? 3 : 2;
  for (int i = 0; i < spec.steps; ++i) {
    ToleranceRow row;
    row.crankDeg = 360.0 * i / spec.steps;
    if (Status st = k.moveTo(row.crankDeg); !st.ok() && st.code != StatusCode::Singular) return st;
    row.nominal = positionOf(k, spec.point, r.world);
    row.firstOrder = s.at(k).ok();
    if (row.firstOrder)
      for (int c = 0; c < axes; ++c) {
        const Linear l =
            linear(r, [&](int col) { return derivativeOf(s, k, spec.point, col, r.world)[c]; });
        row.worst[c] = l.worst;
        row.rss[c] = l.rss;
        row.sigma[c] = l.sigma;
      }
    row.nonlinear = !row.firstOrder;
    out.rows.push_back(row);
  }
  return Status::success();
}

// The nominal stroke (y over the turn), its local extremes' angles, and its first order: the
// largest y's derivative less the least's, each at its own angle (the envelope theorem).
Status firstOrderStroke(const Kinematics& k0, const Resolved& r, const ToleranceSpec& spec,
                        ToleranceResult& out, std::vector<double>& extremeDeg) {
  const Limits lim = findLimits(k0, LimitMeasure::along(spec.point, Vec2(0, 1)));
  if (!lim.status.ok()) return lim.status;
  StrokeSpread& st = out.stroke;
  st.nominal = lim.stroke;
  st.minDeg = lim.minDeg;
  st.maxDeg = lim.maxDeg;
  for (const LocalExtreme& e : lim.extremes) extremeDeg.push_back(e.crankDeg);
  std::sort(extremeDeg.begin(), extremeDeg.end());
  Kinematics kMax = k0, kMin = k0;
  Sensitivity sMax, sMin;
  st.firstOrder = lim.moves && kMax.moveTo(lim.maxDeg).ok() && kMin.moveTo(lim.minDeg).ok() &&
                  sMax.prepare(kMax, r.columns, spaceOf(r)).ok() &&
                  sMin.prepare(kMin, r.columns, spaceOf(r)).ok() && sMax.at(kMax).ok() &&
                  sMin.at(kMin).ok();
  if (st.firstOrder) {
    const Linear l = linear(r, [&](int col) {
      return derivativeOf(sMax, kMax, spec.point, col, r.world).y() -
             derivativeOf(sMin, kMin, spec.point, col, r.world).y();
    });
    st.worst = l.worst;
    st.rss = l.rss;
    st.sigma = l.sigma;
  }
  st.nonlinear = !st.firstOrder;
  return Status::success();
}

// Random numbers of one sample: SplitMix64 from the run's seed and the sample's index, the same
// whichever thread draws it.
struct Draw {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
};

// The sample's design: every varied dimension changed uniformly in its tolerance, every play's
// point moved uniformly over its disc.
Status sampleDesign(const Mechanism& m, const Resolved& r, std::uint64_t seed, long long index,
                    Mechanism& out) {
  Draw rng{seed * 0xD1B54A32D192ED03ull + static_cast<std::uint64_t>(index)};
  std::vector<double> delta(r.all.size(), 0.0);
  for (size_t k = 0; k < r.T.size(); ++k) delta[r.index[k]] = (2 * rng.uniform() - 1) * r.T[k];
  out = m;
  if (Status s = changeDimensions(out, r.all, delta); !s.ok()) return s;
  for (size_t j = 0; j < r.plays.size(); ++j) {
    const double rad = r.c[j] * std::sqrt(rng.uniform()), turn = 2 * M_PI * rng.uniform();
    out.point(r.plays[j].point)->pos += rad * Vec2(std::cos(turn), std::sin(turn));
  }
  return Status::success();
}

// Narrows a local extreme of y (the world's, in space) near the current angle by Newton on its
// exact derivatives.
Status narrow(Kinematics& k, PointId p, bool world, double& y) {
  for (int it = 0; it < 30; ++it) {
    const double w = k.omega();
    double v = 0, a = 0;
    if (world) {
      const Kinematics::PointMotion3 m = k.motionInSpace(p);
      v = m.velocity.y() / w;
      a = m.acceleration.y() / (w * w);
    } else {
      v = k.velocity(p).y() / w;
      a = k.acceleration(p).y() / (w * w);
    }
    if (!(std::abs(a) > 0) || !std::isfinite(v)) break;
    const double step = std::clamp(-v / a * 180 / M_PI, -2.0, 2.0);
    if (Status s = k.moveTo(k.crankDeg() + step); !s.ok()) return s;
    if (std::abs(step) < 1e-10) break;
  }
  y = positionOf(k, p, world).y();
  return Status::success();
}

// What one sample gives: its positions at the rows' angles (when the band is asked) and its
// stroke; or why it is not used.
struct SampleRun {
  const Mechanism& m;
  const Kinematics& k0;  // the nominal at crank angle 0, accelerations on
  const Resolved& r;
  const ToleranceSpec& spec;
  std::vector<double> extremeDeg;
  double size = 1;

  // `stopDeg`: where a sample that cannot turn the crank stopped (NaN before it moved).
  Status run(long long index, std::vector<Vec3>& at, double& stroke, double& stopDeg) const {
    stopDeg = NAN;
    Mechanism design;
    if (Status s = sampleDesign(m, r, spec.seed, index, design); !s.ok()) return s;
    Kinematics k = k0;
    if (Status s = k.edit(design); !s.ok()) return s;
    const Status s = turn(k, at, stroke);
    if (!s.ok()) stopDeg = std::fmod(k.crankDeg(), 360.0);
    return s;
  }

  Status turn(Kinematics& k, std::vector<Vec3>& at, double& stroke) const {
    const Vec3 start = positionOf(k, spec.point, r.world);
    double lo = INFINITY, hi = -INFINITY;
    size_t e = 0;
    const int rows = spec.band ? spec.steps : 0;
    for (int i = 0; i <= rows; ++i) {
      const double deg = i == rows ? 360.0 : 360.0 * i / spec.steps;
      for (; spec.stroke && e < extremeDeg.size() && extremeDeg[e] < deg; ++e) {
        double y = 0;
        if (Status s = k.moveTo(extremeDeg[e]); !s.ok()) return s;
        if (Status s = narrow(k, spec.point, r.world, y); !s.ok()) return s;
        lo = std::min(lo, y);
        hi = std::max(hi, y);
      }
      if (Status s = k.moveTo(deg); !s.ok()) return s;
      if (i < rows) at[i] = positionOf(k, spec.point, r.world);
    }
    if ((positionOf(k, spec.point, r.world) - start).norm() > 1e-7 * size)
      return Status::failure(StatusCode::Unreachable,
                             "not back where it started after a turn (another branch)");
    stroke = hi - lo;
    return Status::success();
  }
};

// Sums over a chunk of samples, added in sample order: the same whatever thread ran it.
struct Chunk {
  std::vector<Vec3> sum, sum2, lo, hi;  // of (position - nominal), by row
  std::string firstFailure;
  double stopLo = INFINITY, stopHi = -INFINITY;  // where failed samples stopped
};
constexpr long long kChunk = 128;

void runChunk(const SampleRun& run, const ToleranceResult& nominal, long long c, Chunk& out,
              std::vector<double>& stroke, std::vector<char>& ok) {
  const size_t rows = run.spec.band ? nominal.rows.size() : 0;
  out.sum.assign(rows, Vec3::Zero());
  out.sum2 = out.sum;
  out.lo.assign(rows, Vec3::Constant(INFINITY));
  out.hi.assign(rows, Vec3::Constant(-INFINITY));
  std::vector<Vec3> at(rows);
  const long long end = std::min<long long>(run.spec.samples, (c + 1) * kChunk);
  for (long long i = c * kChunk; i < end; ++i) {
    double stopDeg = NAN;
    const Status s = run.run(i, at, stroke[i], stopDeg);
    ok[i] = s.ok();
    if (!s.ok()) {
      if (!std::isnan(stopDeg)) {
        out.stopLo = std::min(out.stopLo, stopDeg);
        out.stopHi = std::max(out.stopHi, stopDeg);
      }
      if (out.firstFailure.empty())
        out.firstFailure = "sample " + std::to_string(i) + ": " + s.message;
      continue;
    }
    for (size_t j = 0; j < rows; ++j) {
      const Vec3 d = at[j] - nominal.rows[j].nominal;
      out.sum[j] += d;
      out.sum2[j] += d.cwiseProduct(d);
      out.lo[j] = out.lo[j].cwiseMin(d);
      out.hi[j] = out.hi[j].cwiseMax(d);
    }
  }
}

// Whether a Monte Carlo band and spread say first order is not enough: the band leaves the
// worst case (which bounds every sample to first order) by more than 10 % of it, or the spread
// differs from first order's by more than 10 % and five standard errors.
bool beyondFirstOrder(double lo, double hi, double mean, double sd, double worst, double sigma,
                      int n, double eps) {
  if (std::max(hi, -lo) > 1.1 * worst + eps) return true;
  if (n < 30) return false;
  const double sampling = 5 * sigma / std::sqrt(n);  // five standard errors of mean and sd
  return std::abs(mean) > 0.1 * sigma + sampling + eps ||
         std::abs(sd - sigma) > 0.1 * sigma + sampling + eps;
}

void summarise(const std::vector<Chunk>& chunks, int n, double eps, ToleranceResult& out) {
  for (size_t j = 0; j < out.rows.size() && !chunks.empty() && !chunks[0].sum.empty(); ++j) {
    ToleranceRow& row = out.rows[j];
    Vec3 sum = Vec3::Zero(), sum2 = Vec3::Zero(), lo = Vec3::Constant(INFINITY),
         hi = Vec3::Constant(-INFINITY);
    for (const Chunk& c : chunks) {
      sum += c.sum[j];
      sum2 += c.sum2[j];
      lo = lo.cwiseMin(c.lo[j]);
      hi = hi.cwiseMax(c.hi[j]);
    }
    if (n == 0) continue;
    const Vec3 mean = sum / n;
    row.mean = row.nominal + mean;
    row.lo = row.nominal + lo;
    row.hi = row.nominal + hi;
    for (int c = 0; c < (out.space ? 3 : 2); ++c) {
      row.sd[c] = n > 1 ? std::sqrt(std::max(0.0, (sum2[c] - n * mean[c] * mean[c]) / (n - 1))) : 0;
      if (row.firstOrder &&
          beyondFirstOrder(lo[c], hi[c], mean[c], row.sd[c], row.worst[c], row.sigma[c], n, eps))
        row.nonlinear = true;
    }
  }
}

void strokeSummary(const std::vector<double>& stroke, const std::vector<char>& ok, double eps,
                   ToleranceResult& out) {
  StrokeSpread& st = out.stroke;
  double sum = 0, sum2 = 0, lo = INFINITY, hi = -INFINITY;
  for (size_t i = 0; i < stroke.size(); ++i) {
    if (!ok[i]) continue;
    const double d = stroke[i] - st.nominal;
    sum += d;
    sum2 += d * d;
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  const int n = out.used;
  if (n == 0) return;
  const double mean = sum / n;
  st.mean = st.nominal + mean;
  st.lo = st.nominal + lo;
  st.hi = st.nominal + hi;
  st.sd = n > 1 ? std::sqrt(std::max(0.0, (sum2 - n * mean * mean) / (n - 1))) : 0;
  if (st.firstOrder && beyondFirstOrder(lo, hi, mean, st.sd, st.worst, st.sigma, n, eps))
    st.nonlinear = true;
}

void monteCarlo(const SampleRun& run, ToleranceResult& out) {
  const long long n = run.spec.samples;
  const long long chunks = (n + kChunk - 1) / kChunk;
  std::vector<Chunk> sums(chunks);
  std::vector<double> stroke(n, 0.0);
  std::vector<char> ok(n, 0);
  int threads = run.spec.threads > 0 ? run.spec.threads
                                     : static_cast<int>(std::thread::hardware_concurrency());
  threads = static_cast<int>(std::clamp<long long>(threads, 1, std::max(1LL, chunks)));
  std::atomic<long long> next{0};
  auto work = [&] {
    for (long long c; (c = next++) < chunks;) runChunk(run, out, c, sums[c], stroke, ok);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  out.samples = static_cast<int>(n);
  out.used = static_cast<int>(std::count(ok.begin(), ok.end(), 1));
  out.failed = out.samples - out.used;
  double stopLo = INFINITY, stopHi = -INFINITY;
  for (const Chunk& c : sums) {
    if (out.firstFailure.empty()) out.firstFailure = c.firstFailure;
    stopLo = std::min(stopLo, c.stopLo);
    stopHi = std::max(stopHi, c.stopHi);
  }
  if (stopLo <= stopHi) {
    out.stopLoDeg = stopLo;
    out.stopHiDeg = stopHi;
  }
  const double eps = 1e-9 * run.size;
  summarise(sums, out.used, eps, out);
  if (run.spec.stroke) strokeSummary(stroke, ok, eps, out);
}

}  // namespace

Status toleranceSample(const Mechanism& m, const ToleranceSpec& spec, long long index,
                       Mechanism& out) {
  Resolved r;
  if (Status s = resolve(m, spec, r); !s.ok()) return s;
  return sampleDesign(m, r, spec.seed, index, out);
}

ToleranceResult tolerances(const Mechanism& m, const ToleranceSpec& spec) {
  ToleranceResult out;
  Resolved r;
  if (spec.steps < 4 || spec.samples < 0) {
    out.status = Status::badModel("tolerances need at least 4 steps and samples >= 0");
    return out;
  }
  if (out.status = resolve(m, spec, r); !out.status.ok()) return out;
  out.space = isSpatial(m);
  Kinematics k0;
  if (out.status = k0.load(m); !out.status.ok()) return out;
  if (out.status = k0.checkDetermined({spec.point}); !out.status.ok()) return out;
  k0.setAccelerations(true);
  if (out.status = firstOrderRows(k0, r, spec, out); !out.status.ok()) return out;
  std::vector<double> extremeDeg;
  if (spec.stroke)
    if (out.status = firstOrderStroke(k0, r, spec, out, extremeDeg); !out.status.ok()) return out;
  if (spec.samples > 0) {
    KinematicsOptions opt;
    opt.maxStepDeg = spec.sampleStepDeg;
    Kinematics ks(opt);
    if (out.status = ks.load(m); !out.status.ok()) return out;
    ks.setAccelerations(true);
    monteCarlo(SampleRun{m, ks, r, spec, extremeDeg, ks.size()}, out);
  }
  for (const ToleranceRow& row : out.rows)
    if (row.nonlinear) out.nonlinearDeg.push_back(row.crankDeg);
  return out;
}

}  // namespace linkage
