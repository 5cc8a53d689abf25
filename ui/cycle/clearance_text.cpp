#include "cycle/clearance_text.h"

#include <QCoreApplication>
#include <QStringList>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace linkage::ui {

namespace {

QString tr(const char* s) {
  return QCoreApplication::translate("ClearanceText", s);
}

QString q(const std::string& s) {
  return QString::fromStdString(s);
}

// At most a micron apart the two meet: four significant digits of a millimetre show no less.
constexpr double kMeetMm = 1e-6;

QString deg(double d, int decimals) {
  return QString::number(d, 'f', decimals) + QStringLiteral("°");
}

QString mm(double v) {
  return QString::number(v, 'g', 4) + QStringLiteral(" mm");
}

QString intervals(const std::vector<AngleInterval>& v, int decimals) {
  QStringList out;
  for (const AngleInterval& i : v)
    out << (i.toDeg - i.fromDeg >= 360 - 1e-9
                ? tr("all the turn")
                : deg(i.fromDeg, decimals) + QStringLiteral("–") +
                      deg(i.toDeg > 360 ? i.toDeg - 360 : i.toDeg, decimals));
  return out.join(QStringLiteral(", "));
}

// The crank angles where the two meet: the minima at distance 0 (a point running along the
// part's line has its intervals instead).
std::vector<double> meetings(const Clearance& c) {
  std::vector<double> out;
  if (c.runsAlong) return out;
  for (const ClearanceEvent& e : c.minima)
    if (e.distance <= kMeetMm) out.push_back(e.crankDeg);
  return out;
}

// The crossing of the part's line at that crank angle, if there is one.
const ClearanceCrossing* crossingAt(const Clearance& c, double crankDeg) {
  for (const ClearanceCrossing& x : c.crossings)
    if (std::abs(x.crankDeg - crankDeg) <= 1e-6) return &x;
  return nullptr;
}

QString endName(const Mechanism& m, const ClearancePart& part, bool first) {
  if (part.isSlot()) return first ? tr("its first end") : tr("its second end");
  return q(m.pointLabel(first ? part.point : part.end));
}

// Where along the part a crossing is: on it from its first end, or beyond one of its ends.
QString whereAlong(const Mechanism& m, const ClearancePart& part, const Clearance& c,
                   const ClearanceCrossing& x) {
  auto n = [](double v) { return QString::number(v, 'f', 2); };
  if (x.onPart) return tr("%1 mm from %2").arg(n(x.alongMm), endName(m, part, true));
  if (x.alongMm < 0) return tr("%1 mm beyond %2").arg(n(-x.alongMm), endName(m, part, true));
  return tr("%1 mm beyond %2").arg(n(x.alongMm - c.partLengthMm), endName(m, part, false));
}

}  // namespace

QString clearanceLabel(const Mechanism& m, const ClearanceWatch& w) {
  const QString other = w.other.isPoint() ? q(m.pointLabel(w.other.point)) : partName(m, w.other);
  return q(m.pointLabel(w.point)) + QStringLiteral(" – ") + other;
}

QString partName(const Mechanism& m, const ClearancePart& part) {
  const QString name = q(m.partLabel(part));
  if (part.isSlot()) return tr("slot %1").arg(name);
  if (part.isSegment()) return tr("segment %1").arg(name);
  return tr("point %1").arg(name);
}

QString clearanceDescription(const Mechanism& m, const ClearanceWatch& w) {
  const QString from = q(m.pointLabel(w.point)), to = partName(m, w.other);
  if (w.other.isPoint())
    return tr("From the point %1 to the %2 alone (to measure to the part of a body between "
              "two of its points, a needle or a blade, name the segment: body.P-Q).")
        .arg(from, to);
  return tr("From the point %1 to the %2 as drawn: beyond its ends, to the nearer end.")
      .arg(from, to);
}

QString clearanceFigures(const Mechanism& m, const ClearanceWatch& w, const Clearance& c,
                         int decimals) {
  const QString closest =
      tr("closest %1 at %2").arg(mm(c.closest.distance), deg(c.closest.crankDeg, decimals));
  if (c.runsAlong)
    return c.onPart.empty()
               ? tr("runs along its line, beyond its ends: %1").arg(closest)
               : tr("runs along its line, on it (0 mm) %1").arg(intervals(c.onPart, decimals));
  const std::vector<double> meet = meetings(c);
  if (meet.empty()) return closest;
  QStringList at;
  for (double d : meet) {
    const ClearanceCrossing* x = crossingAt(c, d);
    at << (x && x->onPart ? deg(d, decimals) + QStringLiteral(", ") + whereAlong(m, w.other, c, *x)
                          : deg(d, decimals));
  }
  return tr("0 mm, meets it at %1").arg(at.join(tr("; at ")));
}

QString clearanceNote(const Clearance& c, int decimals) {
  if (c.runsAlong && !c.onPart.empty()) return tr("on it %1").arg(intervals(c.onPart, decimals));
  const std::vector<double> meet = meetings(c);
  if (meet.empty())
    return tr("closest %1 at %2").arg(mm(c.closest.distance), deg(c.closest.crankDeg, decimals));
  QStringList at;
  for (double d : meet) at << deg(d, decimals);
  return tr("meets it at %1").arg(at.join(QStringLiteral(", ")));
}

QString clearanceCrossings(const Mechanism& m, const ClearanceWatch& w, const Clearance& c) {
  if (w.other.isPoint()) return {};
  std::vector<std::pair<double, QString>> lines;
  for (const ClearanceCrossing& x : c.crossings)
    lines.push_back(
        {x.crankDeg, (x.onPart ? tr("meets it at %1, %2") : tr("crosses its line at %1, %2"))
                         .arg(deg(x.crankDeg, 2), whereAlong(m, w.other, c, x))});
  // A touch without a crossing: the point reaches the part and turns back.
  for (double d : meetings(c))
    if (!crossingAt(c, d)) lines.push_back({d, tr("touches it at %1").arg(deg(d, 2))});
  std::sort(lines.begin(), lines.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  QStringList out;
  for (const auto& l : lines) out << l.second;
  return out.join(QLatin1Char('\n'));
}

}  // namespace linkage::ui
