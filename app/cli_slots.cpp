// linkage-cli slots: how far every slider block and pin in a slot runs along its slot over a
// turn of the crank, against the slot's drawn ends (linkage/slot_travel.h).
#include <cmath>
#include <iostream>

#include "cli_common.h"
#include "cli_parser.h"
#include "linkage/elements.h"
#include "linkage/io/numbers.h"
#include "linkage/slot_travel.h"

namespace linkage::cli {

namespace {

const char* kHelp = R"(usage: linkage-cli slots MODEL [--steps N]

The travel of every slider block and pin in a slot of MODEL over one turn of the crank: its
position along the slot (mm from the slot's first end, an arc's along the arc) at its two
extremes, found to 1e-9 degree of crank by root finding on the exact velocity along the slot,
against the slot's drawn ends (0 and the slot's length).

  --steps N   sampling intervals that bracket the extremes (default 360)

Output, CSV: joint,min_mm,max_mm,slot_from_mm,slot_to_mm,inside; one row per joint in file
order, the joint named by its point (body.point), inside "yes" or "no". 17 significant digits.

Exit status: 0 every block stays in its slot, 4 one leaves it (the rows are still written;
standard error says by how much), 2 bad input, 3 the crank cannot turn fully.
)";

constexpr int kLeavesSlot = 4;

}  // namespace

// "slider.B in ground.guide: 12.5 to 61.25 mm of 0 to 80 mm": what `info` lists.
std::string describeTravel(const Mechanism& m, const SlotTravel& t) {
  const Joint* j = m.joint(t.joint);
  // Rounded for reading, 0 where a travel's end is rounding next to the slot's length.
  const double scale = std::abs(t.slotTo - t.slotFrom);
  auto mm = [scale](double v) { return formatShown(v, scale); };
  std::string s = m.pointLabel(j->a) + " in " + m.slotLabel(t.slot) + ": " + mm(t.min) + " to " +
                  mm(t.max) + " mm of " + mm(t.slotFrom) + " to " + mm(t.slotTo) + " mm";
  if (t.before > 0 && !t.inside) s += ", " + mm(t.before) + " mm before its start";
  if (t.past > 0 && !t.inside) s += ", " + mm(t.past) + " mm past its end";
  return s;
}

namespace {

struct Options {
  std::string model;
  int steps = 360;
};

int slots(const Options& o) {
  std::optional<Mechanism> m = openDrivenModel(o.model);
  if (!m) return kBadInput;
  Kinematics k;
  if (int e = prepare(k, *m); e != kOk) return e;
  SlotTravelOptions opt;
  opt.steps = o.steps;
  const SlotTravels r = slotTravel(k, opt);
  if (!r.status.ok()) {
    error(r.status.message);
    return exitFor(r.status);
  }
  std::string out = "joint,min_mm,max_mm,slot_from_mm,slot_to_mm,inside\n";
  for (const SlotTravel& t : r.joints)
    out += m->pointLabel(m->joint(t.joint)->a) + "," + formatNumber(t.min) + "," +
           formatNumber(t.max) + "," + formatNumber(t.slotFrom) + "," + formatNumber(t.slotTo) +
           (t.inside ? ",yes\n" : ",no\n");
  std::cout << out << std::flush;
  if (r.joints.empty()) note("no slider or pin-in-slot joint");
  for (const SlotTravel& t : r.joints)
    if (!t.inside) error("leaves its slot: " + describeTravel(*m, t));
  return r.allInside() ? kOk : kLeavesSlot;
}

}  // namespace

Command slotsCommand(Parser& parser) {
  auto o = std::make_shared<Options>();
  CLI::App& c = parser.command("slots", kHelp);
  addModel(c, o->model);
  addWhole(c, "--steps", o->steps, 4, 1'000'000);
  return {&c, [o] { return slots(*o); }};
}

}  // namespace linkage::cli
