#include "cycle/cycle_entries.h"

#include <QCoreApplication>
#include <QStringList>
#include <algorithm>
#include <cmath>

#include "linkage/timing_text.h"

namespace linkage::ui {

namespace {

QString tr(const char* s) {
  return QCoreApplication::translate("CycleEntries", s);
}

bool fail(QString* why, const QString& text) {
  if (why) *why = text;
  return false;
}

QString q(const std::string& s) {
  return QString::fromStdString(s);
}

bool readConflict(const Timing& t, const QString& text, TimingConflict& c, QString* why) {
  const QStringList parts = text.split(',');
  if (parts.size() != 2 || parts[0].trimmed().isEmpty() || parts[1].trimmed().isEmpty())
    return fail(why, tr("\"%1\" is not two window names N1,N2").arg(text));
  c = {parts[0].trimmed().toStdString(), parts[1].trimmed().toStdString()};
  for (const std::string* n : {&c.first, &c.second})
    if (std::none_of(t.windows.begin(), t.windows.end(),
                     [&](const TimingWindow& w) { return w.name == *n; }))
      return fail(why, tr("no window named \"%1\": add it first").arg(q(*n)));
  if (c.first == c.second) return fail(why, tr("a window cannot conflict with itself"));
  return true;
}

bool readClearance(const Mechanism& m, const QString& text, ClearanceWatch& w, QString* why) {
  const QStringList parts = text.split(QChar(' '), Qt::SkipEmptyParts);
  if ((parts.size() != 2 && parts.size() != 4) || (parts.size() == 4 && parts[2] != "min"))
    return fail(why,
                tr("\"%1\" is not A B or A B min MM (A, B: body.point, body.P-Q for the segment "
                   "between two points, or body.slot)")
                    .arg(text));
  ClearancePart part[2];
  for (int i = 0; i < 2; ++i) {
    std::string bad;
    const std::optional<ClearancePart> p = parseClearancePart(m, parts[i].toStdString(), &bad);
    if (!p) return fail(why, q(bad));
    part[i] = *p;
  }
  // The point first, whichever way round it was typed.
  if (!part[0].isPoint()) std::swap(part[0], part[1]);
  if (!part[0].isPoint())
    return fail(why, tr("two segments or slots: one of the two must be a point"));
  w = {};
  w.point = part[0].point;
  w.other = part[1];
  if (parts.size() == 4) {
    bool ok = false;
    const double min = parts[3].toDouble(&ok);
    if (!ok || !std::isfinite(min) || min < 0)
      return fail(why, tr("\"%1\" after min is not a number >= 0 (mm)").arg(parts[3]));
    w.minMm = min;
  }
  return true;
}

template <class T>
void put(std::vector<T>& v, int index, T x) {
  if (index < 0)
    v.push_back(std::move(x));
  else
    v[index] = std::move(x);
}

}  // namespace

QString kindName(EntryKind k) {
  switch (k) {
    case EntryKind::Row:
      return tr("Row");
    case EntryKind::Window:
      return tr("Window");
    case EntryKind::Conflict:
      return tr("Conflict");
    case EntryKind::Clearance:
      return tr("Clearance");
  }
  return {};
}

QString kindHint(EntryKind k) {
  switch (k) {
    case EntryKind::Row:
      return tr("body.point:y  (or :x, :DX,DY, or body:angle)");
    case EntryKind::Window:
      return tr("NAME=body.point:y<VALUE  (or >, :x, body:angle)");
    case EntryKind::Conflict:
      return tr("WINDOW1,WINDOW2  (they must not overlap)");
    case EntryKind::Clearance:
      return tr(
          "body.point  and body.point, body.P-Q (the segment between two points of a "
          "body: a needle, a blade) or body.slot  [min MM]");
  }
  return {};
}

int entryCount(const Timing& t, EntryKind k) {
  switch (k) {
    case EntryKind::Row:
      return static_cast<int>(t.outputs.size());
    case EntryKind::Window:
      return static_cast<int>(t.windows.size());
    case EntryKind::Conflict:
      return static_cast<int>(t.conflicts.size());
    case EntryKind::Clearance:
      return static_cast<int>(t.clearances.size());
  }
  return 0;
}

QString entryText(const Mechanism& m, EntryKind k, int i) {
  const Timing& t = m.timing;
  switch (k) {
    case EntryKind::Row:
      return q(measureText(m, t.outputs[i]));
    case EntryKind::Window:
      return q(windowText(m, t.windows[i]));
    case EntryKind::Conflict:
      return q(t.conflicts[i].first + "," + t.conflicts[i].second);
    case EntryKind::Clearance: {
      const ClearanceWatch& c = t.clearances[i];
      QString s = q(m.pointLabel(c.point) + " " + m.partLabel(c.other));
      if (c.minMm) s += " min " + q(shortestText(*c.minMm));
      return s;
    }
  }
  return {};
}

bool setEntry(Mechanism& m, EntryKind k, int index, const QString& typed, QString* why) {
  const QString text = typed.trimmed();
  Timing t = m.timing;
  std::string bad;
  switch (k) {
    case EntryKind::Row: {
      std::optional<LimitMeasure> x = parseMeasure(m, text.toStdString(), &bad);
      if (!x) return fail(why, q(bad));
      put(t.outputs, index, *x);
      break;
    }
    case EntryKind::Window: {
      std::optional<TimingWindow> w = parseTimingWindow(m, text.toStdString(), &bad);
      if (!w) return fail(why, q(bad));
      if (index < 0)
        t.windows.push_back(*w);
      else
        t.replaceWindow(index, *w);
      break;
    }
    case EntryKind::Conflict: {
      TimingConflict c;
      if (!readConflict(t, text, c, why)) return false;
      put(t.conflicts, index, c);
      break;
    }
    case EntryKind::Clearance: {
      ClearanceWatch c;
      if (!readClearance(m, text, c, why)) return false;
      put(t.clearances, index, c);
      break;
    }
  }
  // What the parts alone cannot see: a window name given twice, a point's own slot, ...
  if (std::string p = timingProblem(m, t); !p.empty())
    return fail(why, q(p.substr(p.find(": ") == std::string::npos ? 0 : p.find(": ") + 2)));
  m.timing = std::move(t);
  return true;
}

void removeEntry(Mechanism& m, EntryKind k, int i) {
  Timing& t = m.timing;
  switch (k) {
    case EntryKind::Row:
      t.outputs.erase(t.outputs.begin() + i);
      break;
    case EntryKind::Window:
      t.removeWindow(static_cast<size_t>(i));
      break;
    case EntryKind::Conflict:
      t.conflicts.erase(t.conflicts.begin() + i);
      break;
    case EntryKind::Clearance:
      t.clearances.erase(t.clearances.begin() + i);
      break;
  }
}

QString entryTitle(const Mechanism& m, EntryKind k, int i) {
  const Timing& t = m.timing;
  switch (k) {
    case EntryKind::Row:
      return tr("the row %1").arg(entryText(m, k, i));
    case EntryKind::Window:
      return tr("the window %1").arg(q(t.windows[i].name));
    case EntryKind::Conflict:
      return tr("the conflict %1").arg(entryText(m, k, i));
    case EntryKind::Clearance:
      return tr("the clearance %1").arg(entryText(m, k, i));
  }
  return {};
}

}  // namespace linkage::ui
