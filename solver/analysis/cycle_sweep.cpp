// Scalar quantities over the cycle: see analysis/cycle_sweep.h.
#include "analysis/cycle_sweep.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace linkage {

namespace {

// The owned root channels of one track, in the order findRoots is given them.
struct Channels {
  std::vector<std::unique_ptr<RootChannel>> all;
  RootChannel* add(RootFunction f) {
    all.push_back(std::make_unique<RootChannel>());
    all.back()->f = std::move(f);
    return all.back().get();
  }
};

bool repeats(const CycleTrack& t) {
  const CycleReading &a = t.samples.front(), &b = t.samples.back();
  double vmax = 0, gmax = 0;
  for (const CycleReading& s : t.samples) {
    vmax = std::max(vmax, std::abs(s.value));
    gmax = std::max(gmax, std::abs(s.d1));
  }
  return std::abs(b.value - a.value) <= 1e-9 * vmax + 1e-12 &&
         std::abs(b.d1 - a.d1) <= 1e-9 * gmax + 1e-12;
}

// Builds the channels a track asks for, with their samples.
void addChannels(CycleTrack& t, Channels& c, std::vector<RootChannel*>& order,
                 std::vector<RootChannel*>& mine) {
  // A quantity that does not move crosses nothing: its sign changes would be rounding.
  if (!t.moves()) return;
  const CycleQuantity q = t.quantity;
  auto channel = [&](RootFunction f, auto sampleOf) {
    RootChannel* r = c.add(std::move(f));
    r->value = [q](const Kinematics& k) { return q(k).value; };
    for (const CycleReading& s : t.samples) r->samples.push_back(sampleOf(s));
    if (t.periodic) r->samples.back() = r->samples.front();
    order.push_back(r);
    mine.push_back(r);
  };
  if (t.extremes)
    channel(
        [q](const Kinematics& k) {
          const CycleReading r = q(k);
          return RootSample{r.d1, r.d2};
        },
        [](const CycleReading& s) {
          return RootSample{s.d1, s.d2};
        });
  for (double level : t.levels)
    channel(
        [q, level](const Kinematics& k) {
          const CycleReading r = q(k);
          return RootSample{r.value - level, r.d1};
        },
        [level](const CycleReading& s) {
          return RootSample{s.value - level, s.d1};
        });
  for (double level : t.slopeLevels)
    for (double sgn : {1.0, -1.0})
      channel(
          [q, level, sgn](const Kinematics& k) {
            const CycleReading r = q(k);
            return RootSample{r.d1 - sgn * level, r.d2};
          },
          [level, sgn](const CycleReading& s) {
            return RootSample{s.d1 - sgn * level, s.d2};
          });
}

}  // namespace

bool CycleTrack::moves() const {
  for (const CycleReading& s : samples)
    if (std::abs(s.d1) > noise) return true;
  return false;
}

double secondsPerDegree(const Kinematics& k) {
  return M_PI / 180 / k.omega();
}

CycleSweep sweepCycle(const Kinematics& k0, const std::vector<CycleTrack*>& tracks, int steps,
                      double toleranceDeg) {
  CycleSweep out;
  if (steps < 4) {
    out.status = Status::badModel("a cycle needs at least 4 sampling steps");
    return out;
  }
  Kinematics k = k0;
  k.setAccelerations(true);
  if (out.status = k.moveTo(0); !out.status.ok()) return out;
  Kinematics probe = k;
  for (CycleTrack* t : tracks) t->samples.clear();
  for (int i = 0; i <= steps; ++i) {
    out.crank.push_back(i * 360.0 / steps);
    if (out.status = k.moveTo(out.crank.back()); !out.status.ok()) return out;
    for (CycleTrack* t : tracks) t->samples.push_back(t->quantity(k));
  }
  Channels owned;
  std::vector<RootChannel*> order;
  std::vector<std::vector<RootChannel*>> per(tracks.size());
  bool periodic = true;
  for (size_t i = 0; i < tracks.size(); ++i) {
    tracks[i]->periodic = repeats(*tracks[i]);
    if (tracks[i]->onSampled) tracks[i]->onSampled(*tracks[i]);
    periodic = periodic && tracks[i]->periodic;
    addChannels(*tracks[i], owned, order, per[i]);
  }
  if (out.status = findRoots(probe, out.crank, order, periodic, toleranceDeg); !out.status.ok())
    return out;
  for (size_t i = 0; i < tracks.size(); ++i) {
    CycleTrack& t = *tracks[i];
    size_t c = 0;
    t.stationary.clear();
    t.crossings.assign(t.levels.size(), {});
    t.slopeCrossings.assign(t.slopeLevels.size(), {});
    if (!t.moves()) continue;
    if (t.extremes) t.stationary = per[i][c++]->roots;
    for (auto& x : t.crossings) x = per[i][c++]->roots;
    for (auto& x : t.slopeCrossings) {
      x = per[i][c++]->roots;
      const std::vector<Root>& neg = per[i][c++]->roots;
      x.insert(x.end(), neg.begin(), neg.end());
      std::sort(x.begin(), x.end(),
                [](const Root& a, const Root& b) { return a.crankDeg < b.crankDeg; });
    }
  }
  return out;
}

}  // namespace linkage
