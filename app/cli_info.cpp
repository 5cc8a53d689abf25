// linkage-cli info: what the program makes of a mechanism (structure, assembly) before analysis.
#include <algorithm>
#include <array>
#include <iostream>

#include "cli_common.h"
#include "cli_parser.h"
#include "linkage/elements.h"
#include "linkage/grashof.h"
#include "linkage/groups.h"
#include "linkage/io/model_lookup.h"
#include "linkage/io/numbers.h"
#include "linkage/slot_travel.h"

namespace linkage::cli {

std::string describeTravel(const Mechanism& m, const SlotTravel& t);  // cli_slots.cpp

namespace {
const char* kHelp = R"(usage: linkage-cli info MODEL

Describes MODEL (a .linkage.json file or an example name): bodies, joints, driver, the degrees
of freedom (Gruebler count and the rank of the joint equations), redundant joints, and how far
the drawing had to move to close, and Grashof's class of every four-bar loop (frame, input,
coupler, output as the structure solves them; lengths between pins as drawn). Exit status 0,
or 2 when the mechanism cannot be used (the message says why and where).
)";

// "four-bar loop ground-crank-coupler-rocker: frame 60, input 20, coupler 70, output 50 mm:
// crank-rocker (s + l = 90 < p + q = 110)".
void printFourBarLoops(const Mechanism& m) {
  for (const FourBarLoop& l : fourBarLoops(m)) {
    std::string names;
    for (BodyId b : l.bodies) names += (names.empty() ? "" : "-") + m.body(b)->name;
    std::array<double, 4> s = l.lengths;
    std::sort(s.begin(), s.end());
    const char* rel = l.kind == GrashofClass::ChangePoint ? " = " : l.margin > 0 ? " < " : " > ";
    std::cout << "four-bar loop " << names << ": frame " << formatNumber(l.lengths[0], 6)
              << ", input " << formatNumber(l.lengths[1], 6) << ", coupler "
              << formatNumber(l.lengths[2], 6) << ", output " << formatNumber(l.lengths[3], 6)
              << " mm: " << toString(l.kind) << " (s + l = " << formatNumber(s[0] + s[3], 6) << rel
              << "p + q = " << formatNumber(s[1] + s[2], 6) << ")\n";
  }
}
// The structural decomposition, group by group from the ground outwards, and how it is solved.
void printGroups(const Mechanism& m, const Kinematics& k) {
  const AssurDecomposition d = decomposeAssur(m);
  for (size_t i = 0; i < d.groups.size(); ++i) {
    std::cout << "group " << i + 1 << ": " << toString(d.groups[i].kind);
    for (BodyId b : d.groups[i].bodies) std::cout << " " << m.body(b)->name;
    std::cout << "\n";
  }
  for (BodyId b : d.unresolved) std::cout << "no group: " << m.body(b)->name << "\n";
  if (k.valid())
    std::cout << "solve: "
              << (k.closedForm() ? "in closed form, group by group"
                                 : "by Newton on all coordinates (the general solve)")
              << "\n";
}

// Every block and pin in a slot: its travel over a turn against the slot's ends.
void printSlotTravel(const Mechanism& m, const Kinematics& k) {
  const SlotTravels t = slotTravel(k);
  if (!t.status.ok()) {
    if (!t.joints.empty() || !m.slots.empty())
      std::cout << "slot travel: not known (" << t.status.message << ")\n";
    return;
  }
  for (const SlotTravel& j : t.joints)
    std::cout << "slot travel: " << describeTravel(m, j) << (j.inside ? "" : " (leaves the slot)")
              << "\n";
}

int info(const std::string& model) {
  std::optional<Mechanism> m = openModel(model);
  if (!m) return kBadInput;
  std::cout << "name: " << m->name << "\n";
  std::cout << "bodies: " << m->bodies.size() << ", joints: " << m->joints.size() << "\n";
  for (const Joint& j : m->joints) std::cout << "  " << jointLabel(*m, j.id) << "\n";
  if (m->driver)
    std::cout << "driver: " << jointLabel(*m, m->driver->joint) << " at "
              << formatNumber(m->driver->rpm, 6) << " rpm "
              << (m->driver->direction == Direction::Cw ? "cw" : "ccw") << "\n";
  else
    std::cout << "driver: none\n";
  Kinematics k;
  const int e = prepare(k, *m);
  // At the assembled pose when there is one: a drawing in line is singular where it is drawn,
  // not where it is assembled. Else at the drawing, for what the failure leaves to say.
  Status compiled;
  const StructureReport s = k.valid() ? k.structure() : analyzeDrawing(*m, compiled);
  if (compiled.ok() && (s.coordinates > 0 || e == kOk)) {
    std::cout << "coordinates: " << s.coordinates << ", joint equations: " << s.jointEquations
              << "\n";
    std::cout << "degrees of freedom: " << s.mobility << " (Gruebler count " << s.gruebler
              << ", rank " << s.rank << ")\n";
    for (JointId j : s.redundantJoints) std::cout << "redundant: " << jointLabel(*m, j) << "\n";
  }
  if (e == kOk)
    std::cout << "assembly: moved up to " << formatShown(k.assembly().maxMove, k.size()) << " mm\n";
  printGroups(*m, k);
  printFourBarLoops(*m);
  if (e == kOk && m->driver) printSlotTravel(*m, k);
  return e;
}

}  // namespace

Command infoCommand(Parser& parser) {
  auto model = std::make_shared<std::string>();
  CLI::App& c = parser.command("info", kHelp);
  addModel(c, *model);
  return {&c, [model] { return info(*model); }};
}

}  // namespace linkage::cli
