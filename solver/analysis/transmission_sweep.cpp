// sweepTransmission (linkage/transmission.h): the angles over a turn, their exact extremes, and
// the stretches outside the band.
//
// The stretches are found on a grid of the samples and every local extreme: between two
// neighbours of that grid the angle is monotonic, so it crosses a bound at most once there and
// a crossing always shows as a change of sign, however briefly the angle leaves the band.
#include <algorithm>
#include <cmath>

#include "analysis/transmission_track.h"
#include "linkage/transmission.h"

namespace linkage {

namespace {

// The stretches where `g` (a band channel: mu - lo, or hi - mu) is negative, from its roots.
void stretches(const RootChannel& c, bool below, bool periodic,
               std::vector<TransmissionStretch>& out) {
  // Exactly on the bound at crank 0 counts with the side the angle goes to (as findRoots does).
  const auto firstSide = std::find_if(c.samples.begin(), c.samples.end(),
                                      [](const RootSample& x) { return x.g != 0; });
  const bool outsideAtStart = firstSide != c.samples.end() && firstSide->g < 0;
  bool outside = outsideAtStart;
  const size_t first = out.size();
  double from = 0;
  for (const Root& r : c.roots) {
    if (!r.rising) {
      from = r.crankDeg;
      outside = true;
    } else if (outside) {
      out.push_back({from, r.crankDeg, below});
      outside = false;
    }
  }
  if (!outside) return;
  // Still outside at the end: a periodic turn joins this stretch with the one from crank 0.
  const bool fromStart = out.size() > first && out[first].fromDeg == 0 && outsideAtStart;
  if (periodic && fromStart && from > 0) {
    out[first] = {from, out[first].toDeg + 360, below};
  } else if (!fromStart || !periodic) {
    out.push_back({from, 360, below});
  }
}

Status findStretches(const Kinematics& start, const TransmissionJoint& t,
                     const std::vector<double>& crank, const std::vector<double>& mu,
                     const TransmissionOptions& opt, bool periodic, TransmissionSummary& s) {
  // The grid: samples and extremes, ascending, with the angle at each.
  std::vector<std::pair<double, double>> grid;
  for (size_t i = 0; i < crank.size(); ++i) grid.emplace_back(crank[i], mu[i]);
  for (const TransmissionExtreme& e : s.extremes) grid.emplace_back(e.crankDeg, e.deg);
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end(),
                         [](const auto& a, const auto& b) { return a.first == b.first; }),
             grid.end());
  std::vector<double> at;
  RootChannel lo, hi;
  const TransmissionBand band = opt.band;
  lo.f = [t, band](const Kinematics& k) {
    const TransmissionReading r = transmissionAngle(k, t);
    return RootSample{r.deg - band.lo, r.perDeg};
  };
  hi.f = [t, band](const Kinematics& k) {
    const TransmissionReading r = transmissionAngle(k, t);
    return RootSample{band.hi - r.deg, -r.perDeg};
  };
  // The slopes at the grid are left 0: they only choose the first Newton step, and an extreme's
  // is 0 anyway.
  for (const auto& [deg, value] : grid) {
    at.push_back(deg);
    lo.samples.push_back({value - band.lo, 0});
    hi.samples.push_back({band.hi - value, 0});
  }
  lo.pairs = hi.pairs = false;  // monotonic between neighbours: one crossing at most
  Kinematics probe = start;
  if (Status st = findRoots(probe, at, {&lo, &hi}, periodic, opt.toleranceDeg); !st.ok()) return st;
  stretches(lo, true, periodic, s.outside);
  stretches(hi, false, periodic, s.outside);
  std::sort(s.outside.begin(), s.outside.end(),
            [](const auto& a, const auto& b) { return a.fromDeg < b.fromDeg; });
  return Status::success();
}

}  // namespace

bool TransmissionSweep::inBand() const {
  for (const TransmissionSummary& s : summaries)
    if (!s.inBand()) return false;
  return true;
}

TransmissionSweep sweepTransmission(const Kinematics& k0, const TransmissionOptions& opt) {
  TransmissionSweep out;
  out.band = opt.band;
  if (opt.steps < 4 || !(opt.toleranceDeg > 0) || !std::isfinite(opt.band.lo) ||
      !std::isfinite(opt.band.hi) || !(opt.band.lo < opt.band.hi)) {
    out.status = Status::failure(StatusCode::BadModel,
                                 "a transmission sweep needs at least 4 steps, a positive "
                                 "tolerance and a band with its low end below its high end");
    return out;
  }
  if (!k0.valid()) {
    out.status = Status::failure(StatusCode::BadModel, "no mechanism is loaded");
    return out;
  }
  if (!(k0.omega() > 0) || !std::isfinite(k0.omega())) {
    out.status =
        Status::failure(StatusCode::BadModel, "the driver's speed is not a positive number");
    return out;
  }
  out.joints = transmissionJoints(k0.mechanism());
  Kinematics k = k0;
  k.setAccelerations(true);
  if (out.status = k.moveTo(0); !out.status.ok()) return out;
  const Kinematics start = k;
  std::vector<TransmissionTrack> tracks;
  for (const TransmissionJoint& t : out.joints) tracks.emplace_back(k0.mechanism(), t);
  for (int i = 0; i <= opt.steps; ++i) {
    const double crank = i * 360.0 / opt.steps;
    if (out.status = k.moveTo(crank); !out.status.ok()) break;
    out.crankDeg.push_back(crank);
    for (TransmissionTrack& t : tracks) t.sample(k);
  }
  for (TransmissionTrack& t : tracks) out.values.push_back(t.mu);
  if (!out.status.ok()) return out;
  bool periodic = true;
  for (const TransmissionTrack& t : tracks)
    periodic = periodic && std::abs(t.mu.back() - t.mu.front()) <= 1e-9;
  std::vector<RootChannel*> channels;
  for (TransmissionTrack& t : tracks) {
    if (periodic) t.closePeriod();
    for (RootChannel* c : t.channels()) channels.push_back(c);
  }
  Kinematics probe = start;
  if (out.status = findRoots(probe, out.crankDeg, channels, periodic, opt.toleranceDeg);
      !out.status.ok())
    return out;
  for (size_t j = 0; j < tracks.size(); ++j) {
    out.summaries.push_back(tracks[j].summary(periodic));
    out.status = findStretches(start, out.joints[j], out.crankDeg, tracks[j].mu, opt, periodic,
                               out.summaries.back());
    if (!out.status.ok()) {
      out.summaries.clear();
      return out;
    }
  }
  return out;
}

}  // namespace linkage
