// linkage-cli balance: counterweights that minimise the peak of the shaking force, exactly.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>

#include "cli_common.h"
#include "cli_parser.h"
#include "linkage/balance.h"
#include "linkage/io/model_file.h"
#include "linkage/io/numbers.h"
#include "linkage/space.h"

namespace linkage::cli {

namespace {

const char* kHelp =
    R"(usage: linkage-cli balance MODEL --counterweight BODY [--counterweight BODY ...]
                           --minimize fx|fy|fz|force [--max-kgmm M] [--steps N]
                           [--out BALANCED.linkage.json]

Finds the counterweights on the given bodies (each pinned to the ground) that minimise the peak
over the whole cycle (continuous, not only at the samples) of |shaking fx|, |shaking fy| or
|shaking force| of MODEL at its driver's speed, the counterweights' own weight included. A
counterweight is a point mass m at u from the point where its body is pinned to the ground (u
fixed in the body, |u| at most the body's farthest drawn point from there: R); its static moment
s = m u (kg mm) shakes the frame as the body turns, its weight m g pulls on it. The programme in
(s, m) is convex (|s| <= R m is a cone): linear rows on sampled angles and tangents of the cone
(COIN-OR CLP), refined by exchange on the peaks' exact angles until the peak and the programme's
lower bound agree. No counterweight is one of its choices: the peak after is never above the
peak before. Writes CSV, with a header row:

  quantity,body,value,angle_deg
  counterweight,BODY,KGMM,ANGLE_DEG         static moment (kg mm), angle of u in the body's
                                            sketch frame
  counterweight_kg,BODY,KG,                 its mass
  counterweight_radius_mm,BODY,MM,          |u|: at most R (less under gravity where a heavier
                                            mass nearer the pivot does better)
  peak_before,,N,CRANK_DEG                  the peak and where it is
  peak_after,,N,CRANK_DEG                   with the counterweights as --out writes them

and on standard error the optimality gap (the peak after less the programme's bound).

A machine in space (planes, docs/spatial.md): the shaking force is the world's, in 3D (fx, fy,
fz its components, force its magnitude); each counterweight turns in its body's plane, so it
reaches only the force's components in that plane. Where every counterweight's plane is
parallel, the force along their normal is beyond their reach: a note on standard error gives
that normal and the part's peak with the counterweights and before. A planar machine has no fz
(refused); the note gives the weight along the drawing's normal when gravity has a z.

  --counterweight BODY  a body to put a counterweight on (repeatable)
  --minimize WHAT       fx, fy, fz (in space) or force
  --max-kgmm M          each counterweight's static moment at most M kg mm (0: none; the peak
                        as it is)
  --steps N             samples per turn of the first programme (default 360, at least 8)
  --out FILE            also write MODEL with the counterweights added to their bodies' masses

Exit status: 0 success, 2 bad input (options, file, a body not pinned to the ground), 3 the
mechanism cannot turn through the cycle, 1 the --out file could not be written (the CSV is
written before).
)";

struct Options {
  std::string model, out, measure;
  std::vector<std::string> bodies;
  BalanceOptions balance;
};

// The options, read into `o`.
CLI::App* addOptions(Parser& parser, Options& o) {
  CLI::App& c = parser.command("balance", kHelp);
  addModel(c, o.model);
  required(addTexts(c, "--counterweight", o.bodies));
  required(addWord(c, "--minimize", o.measure, {"fx", "fy", "fz", "force"}));
  addNumber(c, "--max-kgmm", o.balance.maxKgMm, NumberRule::NotNegative);
  addWhole(c, "--steps", o.balance.steps, 8, 1'000'000);
  addText(c, "--out", o.out);
  return &c;
}

BalanceMeasure measureNamed(const std::string& name) {
  if (name == "fx") return BalanceMeasure::Fx;
  if (name == "fy") return BalanceMeasure::Fy;
  if (name == "fz") return BalanceMeasure::Fz;
  return BalanceMeasure::Force;
}

std::string table(const Mechanism& m, const BalanceResult& r) {
  std::string out = "quantity,body,value,angle_deg\n";
  for (const Counterweight& c : r.counterweights) {
    const std::string body = m.body(c.body)->name;
    out += "counterweight," + body + "," + formatNumber(c.kgMm()) + "," +
           formatNumber(c.angleDeg()) + "\n";
    out += "counterweight_kg," + body + "," + formatNumber(c.kg) + ",\n";
    out += "counterweight_radius_mm," + body + "," + formatNumber(c.radiusMm()) + ",\n";
  }
  out += "peak_before,," + formatNumber(r.peakBefore) + "," + formatNumber(r.peakBeforeDeg) +
         "\npeak_after,," + formatNumber(r.peakAfter) + "," + formatNumber(r.peakAfterDeg) + "\n";
  return out;
}

std::string vector(const Vec3& v) {
  return "(" + formatShown(v.x(), 1) + ", " + formatShown(v.y(), 1) + ", " + formatShown(v.z(), 1) +
         ")";
}

// The peak after, the certified gap and the exchange's rounds; or that nothing shakes.
void notePeak(const BalanceResult& r) {
  if (!(r.peakBefore > 0)) {
    error(
        "note: the shaking force is nil over the whole cycle: nothing to balance, no "
        "counterweight placed");
    return;
  }
  // A peak after that is rounding next to the peak before is an exact cancellation: 0, at no
  // angle in particular.
  const bool cancelled = r.peakAfter <= 1e-9 * r.peakBefore;
  error("note: peak " +
        (cancelled
             ? std::string("0 N (cancelled over the whole cycle)")
             : formatShown(r.peakAfter) + " N at crank " + formatShown(r.peakAfterDeg) + " deg") +
        "; optimality gap " + formatNumber(r.gap(), 3) +
        " N (no counterweights within the bounds do better than " +
        formatShown(r.lowerBound, r.peakBefore) + " N), after " + std::to_string(r.exchanges) +
        " exchange(s)");
}

// What the counterweights leave out, said rather than hidden in the peak.
void noteUnreached(const Mechanism& m, const BalanceResult& r) {
  const std::string peaks =
      formatShown(r.unreachedPeak, r.peakBefore) + " N" +
      (r.unreachedPeak > 0 && isSpatial(m) ? " at crank " + formatShown(r.unreachedPeakDeg) + " deg"
                                           : std::string()) +
      " (before: " + formatShown(r.unreachedPeakBefore, r.peakBefore) + " N)";
  if (!isSpatial(m)) {
    if (r.unreachedPeak > 0 || r.unreachedPeakBefore > 0)
      error(
          "note: the balance is of the shaking force in the drawing's plane; along its normal "
          "the frame bears the weight (gravity's z), which no counterweight turning in the "
          "plane lowers: " +
          peaks);
    return;
  }
  if (!r.unreached) {
    error(
        "note: the counterweights' planes are not all parallel: every direction of the "
        "shaking force is within their reach");
    return;
  }
  error("note: every counterweight turns in a plane of normal " + vector(*r.unreached) +
        " (world): the shaking force along it is beyond their reach (only their weight adds to "
        "it): its peak " +
        peaks);
}

int balance(Options& o) {
  o.balance.measure = measureNamed(o.measure);
  std::optional<Mechanism> m = openDrivenModel(o.model);
  if (!m) return kBadInput;
  for (const std::string& name : o.bodies) {
    const Body* b = m->bodyNamed(name);
    if (!b) {
      error("--counterweight: no body '" + name + "'");
      return kBadInput;
    }
    o.balance.bodies.push_back(b->id);
  }
  Kinematics k;
  if (int e = prepare(k, *m); e != kOk) return e;
  const BalanceResult r = balanceShaking(k, o.balance);
  if (!r.status.ok()) {
    error(r.status.message);
    return r.status.code == StatusCode::BadModel ? kBadInput : exitFor(r.status);
  }
  std::fputs(table(*m, r).c_str(), stdout);
  notePeak(r);
  noteUnreached(*m, r);
  if (!o.out.empty()) {
    addCounterweights(*m, r.counterweights);
    const WriteResult w = saveMechanismFile(*m, o.out);
    if (!w.ok) {
      // (The writer's message names the file already.)
      error(w.error.rfind(o.out, 0) == 0 ? w.error : o.out + ": " + w.error);
      return kFailure;
    }
  }
  return kOk;
}

}  // namespace

Command balanceCommand(Parser& parser) {
  auto o = std::make_shared<Options>();
  return {addOptions(parser, *o), [o] { return balance(*o); }};
}

}  // namespace linkage::cli
