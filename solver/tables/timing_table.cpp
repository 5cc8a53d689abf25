#include "linkage/tables/timing_table.h"

#include "linkage/io/numbers.h"

namespace linkage {

std::string timingTable(const CycleDiagram& d) {
  std::string out = "window,from_deg,to_deg\n";
  for (const WindowIntervals& w : d.windows)
    for (const AngleInterval& i : w.intervals)
      out += w.name + "," + formatNumber(i.fromDeg) + "," + formatNumber(i.toDeg) + "\n";
  for (const Conflict& c : d.conflicts)
    for (const AngleInterval& i : c.overlaps)
      out += "conflict:" + c.first + "+" + c.second + "," + formatNumber(i.fromDeg) + "," +
             formatNumber(i.toDeg) + "\n";
  return out;
}

}  // namespace linkage
