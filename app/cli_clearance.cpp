// linkage-cli clearance: the distance between two moving things (two points, or a point and a
// slot of another body) over a turn of the crank, every local minimum and the closest approach
// (linkage/clearance.h).
#include <iostream>

#include "cli_common.h"
#include "cli_parser.h"
#include "linkage/clearance.h"
#include "linkage/io/numbers.h"
#include "linkage/timing_text.h"

namespace linkage::cli {

namespace {

const char* kHelp = R"(usage: linkage-cli clearance MODEL --between A B [--min MM] [--steps N]

The distance from a point to another part of MODEL over one turn of the crank: every local
minimum, found to 1e-9 degree of crank by root finding on the distance's exact derivative, and
the closest approach. A and B name the parts, one of them a point:

  body.point   a point
  body.P-Q     the segment between two points of a body (a needle, a blade): the distance to
               it between its ends, and beyond them to the nearer end
  body.slot    a slot as drawn: to its line or arc between its ends, beyond them to the nearer
               end

(a name is a point first, then a slot, then a segment). A segment or slot belongs to another
body than the point. Where the point crosses a segment's or slot's line (or circle) the
crossing is noted on standard error with where along the part it is (from its first end) and
whether it is on the part itself, where the two meet (distance 0).

  --between A B  the two parts
  --min MM       the least clearance allowed: exit 4 when the closest is under it
  --steps N      sampling intervals that bracket the minima (default 360)

Output, CSV: event,crank_deg,distance_mm; a "min" row per local minimum in crank order (crank
angles in [0, 360)), then "closest,CRANK,DIST", the least of them. 17 significant digits. On
standard error, what was measured ("from the point hook.K to the segment needlebar.N-G").

Exit status: 0 success, 4 the closest is under --min (the rows are still written), 2 bad
input (the message names the argument), 3 the crank cannot turn fully.
)";

constexpr int kTooClose = 4;

std::optional<ClearancePart> part(const Mechanism& m, const std::string& text) {
  std::string why;
  const std::optional<ClearancePart> p = parseClearancePart(m, text, &why);
  if (!p) error("--between " + text + ": " + why);
  return p;
}

// Where the point crosses the segment's or slot's line, and whether the two meet there: on the
// part, its distance from the first end; beyond an end, how far beyond it.
void noteCrossings(const Mechanism& m, const ClearancePart& other, const Clearance& c) {
  const std::string first = other.isSlot() ? "its first end" : m.pointLabel(other.point);
  const std::string second = other.isSlot() ? "its second end" : m.pointLabel(other.end);
  for (const ClearanceCrossing& x : c.crossings) {
    const std::string where =
        x.onPart        ? formatShown(x.alongMm, 1) + " mm from " + first
        : x.alongMm < 0 ? formatShown(-x.alongMm, 1) + " mm beyond " + first
                        : formatShown(x.alongMm - c.partLengthMm, 1) + " mm beyond " + second;
    note((x.onPart ? "meets " : "crosses the line of ") + m.partDescription(other) + " at crank " +
         formatShown(x.crankDeg) + " deg, " + where);
  }
}

// A point guided along the part's line: where it is on the part (distance 0) over the turn.
void noteRunsAlong(const Mechanism& m, const ClearancePart& point, const ClearancePart& other,
                   const Clearance& c) {
  std::string on;
  for (const AngleInterval& i : c.onPart)
    on += std::string(on.empty() ? "" : ", ") + formatShown(i.fromDeg) + " to " +
          formatShown(i.toDeg > 360 ? i.toDeg - 360 : i.toDeg) +
          (i.toDeg > 360 ? " (through 360)" : "");
  note(m.partLabel(point) + " runs along the line of " + m.partDescription(other) +
       (c.onPart.empty() ? ", beyond its ends all the turn"
                         : ": on it (distance 0) from crank " + on + " deg"));
}

struct Options {
  std::string model;
  std::pair<std::string, std::string> between;
  std::optional<double> min;
  int steps = 360;
};

// The options, read into `o`.
CLI::App* addOptions(Parser& parser, Options& o) {
  CLI::App& c = parser.command("clearance", kHelp);
  addModel(c, o.model);
  required(addTextPair(c, "--between", o.between, "A B"));
  addNumber(c, "--min", o.min, NumberRule::NotNegative);
  addWhole(c, "--steps", o.steps, 4, 1'000'000);
  return &c;
}

int clearance(const Options& o) {
  std::optional<Mechanism> m = openDrivenModel(o.model);
  if (!m) return kBadInput;
  const std::optional<ClearancePart> a = part(*m, o.between.first), b = part(*m, o.between.second);
  if (!a || !b) return kBadInput;
  Kinematics k;
  if (int e = prepare(k, *m); e != kOk) return e;
  ClearanceOptions opt;
  opt.steps = o.steps;
  const Clearance c = findClearance(k, *a, *b, opt);
  if (!c.status.ok()) {
    error("--between " + o.between.first + " " + o.between.second + ": " + c.status.message);
    return exitFor(c.status);
  }
  std::string out = "event,crank_deg,distance_mm\n";
  for (const ClearanceEvent& e : c.minima)
    out += "min," + formatNumber(e.crankDeg) + "," + formatNumber(e.distance) + "\n";
  out +=
      "closest," + formatNumber(c.closest.crankDeg) + "," + formatNumber(c.closest.distance) + "\n";
  std::cout << out << std::flush;
  const ClearancePart& point = a->isPoint() ? *a : *b;
  const ClearancePart& other = a->isPoint() ? *b : *a;
  note("from " + m->partDescription(point) + " to " + m->partDescription(other) +
       (other.isPoint() ? "" : " as drawn (beyond its ends, to the nearer end)"));
  if (!other.isPoint()) noteCrossings(*m, other, c);
  if (c.runsAlong) noteRunsAlong(*m, point, other, c);
  if (!c.periodic)
    note("the motion does not repeat after one turn: the ends of the turn count as well");
  if (o.min && c.closest.distance < *o.min) {
    error("the closest approach, " + formatShown(c.closest.distance) + " mm at crank " +
          formatShown(c.closest.crankDeg) + " deg, is under --min " + formatShown(*o.min));
    return kTooClose;
  }
  return kOk;
}

}  // namespace

Command clearanceCommand(Parser& parser) {
  auto o = std::make_shared<Options>();
  return {addOptions(parser, *o), [o] { return clearance(*o); }};
}

}  // namespace linkage::cli
