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

namespace linkage::cli {

namespace {

const char* kHelp =
    R"(usage: linkage-cli balance MODEL --counterweight BODY [--counterweight BODY ...]
                           --minimize fx|fy|force [--max-kgmm M] [--steps N]
                           [--out BALANCED.linkage.json]

Finds the counterweights on the given bodies (each pinned to the ground) that minimise the peak
over the whole cycle (continuous, not only at the samples) of |shaking fx|, |shaking fy| or
|shaking force| of MODEL at its driver's speed. A counterweight is a point mass whose static
moment s = m u (kg mm) is measured from the point where its body is pinned to the ground, u
fixed in the body; its own weight is left out. The shaking force is linear in the static
moments: a linear programme (COIN-OR CLP) on sampled angles, refined by exchange on the peaks'
exact angles until the peak and the programme's lower bound agree. Writes CSV:

  counterweight,BODY,KGMM,ANGLE_DEG    (ANGLE_DEG: of u in the body's sketch frame)
  peak_before,,VALUE                   (N)
  peak_after,,VALUE                    (N)

and on standard error the optimality gap (the peak after less the programme's bound) and,
under gravity, the peak with the counterweights' own weight (as --out writes them as masses,
they weigh: a constant force on the frame that the balance leaves out).

  --counterweight BODY  a body to put a counterweight on (repeatable)
  --minimize WHAT       fx, fy or force
  --max-kgmm M          each counterweight's static moment at most M kg mm (0: none; the peak
                        as it is)
  --steps N             samples per turn of the first programme (default 360, at least 8)
  --out FILE            also write MODEL with the counterweights added as masses (a point mass
                        at the radius of the body's farthest point from its pivot)

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
  required(addWord(c, "--minimize", o.measure, {"fx", "fy", "force"}));
  addNumber(c, "--max-kgmm", o.balance.maxKgMm, NumberRule::NotNegative);
  addWhole(c, "--steps", o.balance.steps, 8, 1'000'000);
  addText(c, "--out", o.out);
  return &c;
}

BalanceMeasure measureNamed(const std::string& name) {
  if (name == "fx") return BalanceMeasure::Fx;
  if (name == "fy") return BalanceMeasure::Fy;
  return BalanceMeasure::Force;
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
  std::string out;
  for (const Counterweight& c : r.counterweights)
    out += "counterweight," + m->body(c.body)->name + "," + formatNumber(c.kgMm()) + "," +
           formatNumber(c.angleDeg()) + "\n";
  out += "peak_before,," + formatNumber(r.peakBefore) + "\npeak_after,," +
         formatNumber(r.peakAfter) + "\n";
  std::fwrite(out.data(), 1, out.size(), stdout);
  error("note: peak " + formatNumber(r.peakAfter, 10) + " N at crank " +
        formatNumber(r.peakAfterDeg, 10) + " deg; optimality gap " + formatNumber(r.gap(), 3) +
        " N (no counterweights within the bound do better than " + formatNumber(r.lowerBound, 10) +
        " N), after " + std::to_string(r.exchanges) + " exchange(s)");
  if (m->gravity && std::any_of(r.counterweights.begin(), r.counterweights.end(),
                                [](const Counterweight& c) { return c.kgMm() > 0; })) {
    Status why;
    const std::optional<double> weighed = peakWithWeight(k, o.balance, r, &why);
    error(weighed ? "note: under gravity the counterweights also weigh, which the balance leaves "
                    "out; as masses at their bodies' farthest points (as --out writes them) the "
                    "peak is " +
                        formatNumber(*weighed, 10) + " N"
                  : "note: the peak with the counterweights' weight is not known: " + why.message);
  }
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
