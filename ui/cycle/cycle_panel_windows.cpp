// The Cycle dock's windows made by choosing (issue 26): the window form under the line, the
// points picked on the canvas for it, and the thresholds dragged on the diagram. Every change
// goes through the entries' own reading (cycle/cycle_entries.h: the text a user would type), so
// that a window chosen is refused for the same reasons, and saved the same, as one typed.
#include <QComboBox>
#include <QLabel>
#include <QTreeWidget>
#include <cmath>

#include "cycle/cycle_panel.h"
#include "cycle/window_form.h"
#include "document/document.h"
#include "figures/qcp.h"
#include "linkage/timing_text.h"

namespace linkage::ui {

namespace {

constexpr int kKindRole = Qt::UserRole, kIndexRole = Qt::UserRole + 1;

// A threshold chosen by the program (dragged, or put in the stroke) in hundredths of the
// output's unit: what a designer reads and the file keeps, not the pixel's 15 digits.
double roundLevel(double v) {
  return std::round(v * 100) / 100;
}

QString q(const std::string& s) {
  return QString::fromStdString(s);
}

QString windowResult(const std::vector<AngleInterval>& v) {
  if (v.empty()) return CyclePanel::tr("never");
  if (v.size() == 1 && v[0].fromDeg == 0 && v[0].toDeg == 360) return CyclePanel::tr("always");
  QStringList parts;
  for (const AngleInterval& x : v)
    parts << QStringLiteral("%1°–%2°").arg(x.fromDeg, 0, 'f', 2).arg(x.toDeg, 0, 'f', 2);
  return parts.join("; ");
}

}  // namespace

// The form is shown while windows are what the dock adds (the kind box says Window; a window
// chosen in the list chooses it); otherwise the diagram keeps the height.
void CyclePanel::connectForm() {
  auto shown = [this] {
    form_->setVisible(static_cast<EntryKind>(kind_->currentData().toInt()) == EntryKind::Window);
  };
  shown();
  connect(kind_, &QComboBox::currentIndexChanged, this, shown);
  connect(form_, &WindowForm::edited, this, &CyclePanel::formEdited);
  connect(form_, &WindowForm::addRequested, this, &CyclePanel::addFromForm);
  connect(form_, &WindowForm::newRequested, this, [this] {
    setFormTarget(-1);
    formEdited(false);  // the new window's crank angles
  });
  connect(form_, &WindowForm::pickRequested, this, &CyclePanel::pickPointRequested);
  // A window chosen in the list (or clicked again) is the one the form edits and whose
  // threshold is drawn solid.
  auto chosen = [this](QTreeWidgetItem* i) {
    if (!filling_ && i &&
        static_cast<EntryKind>(i->data(0, kKindRole).toInt()) == EntryKind::Window)
      setFormTarget(i->data(0, kIndexRole).toInt());
  };
  connect(list_, &QTreeWidget::currentItemChanged, this, chosen);
  connect(list_, &QTreeWidget::itemClicked, this, chosen);
}

// After each change of the design: the form offers what the mechanism has and shows the window
// it edits as the document now holds it (an undo puts the form back too); a window taken away
// leaves its fields as a new one.
void CyclePanel::formFollowsDesign() {
  if (!doc_) return;
  const Mechanism& m = doc_->design();
  form_->offer(m);
  // Another mechanism (a file opened, a new document): nothing of the last one is shown.
  if (m.owner() != formOwner_) {
    formOwner_ = m.owner();
    form_->load(-1, TimingWindow{}, m);
    form_->setResult({});
  }
  const int i = form_->target();
  if (i >= static_cast<int>(m.timing.windows.size()))
    form_->startNew();
  else if (i >= 0)
    form_->load(i, m.timing.windows[i], m);
  selectWindowItem(form_->target());
}

// The list's row of window i made current (none for -1), without it asking for the form.
void CyclePanel::selectWindowItem(int i) {
  filling_ = true;
  QTreeWidgetItem* found = nullptr;
  for (int r = 0; r < list_->topLevelItemCount() && i >= 0; ++r) {
    QTreeWidgetItem* item = list_->topLevelItem(r);
    if (static_cast<EntryKind>(item->data(0, kKindRole).toInt()) == EntryKind::Window &&
        item->data(0, kIndexRole).toInt() == i)
      found = item;
  }
  list_->setCurrentItem(found);
  filling_ = false;
}

void CyclePanel::setFormTarget(int window, bool reveal) {
  if (!doc_) return;
  const Mechanism& m = doc_->design();
  if (window >= 0 && window < static_cast<int>(m.timing.windows.size())) {
    form_->load(window, m.timing.windows[window], m);
    form_->setResult(resultText(EntryKind::Window, window));
    if (reveal) kind_->setCurrentIndex(kind_->findData(static_cast<int>(EntryKind::Window)));
  } else {
    form_->startNew();
  }
  selectWindowItem(form_->target());
  if (diagram()) rebuildFigure();  // the window edited is drawn solid
}

// The range of an output over the cycle: its row's, or that of a diagram of it alone.
std::optional<std::pair<double, double>> CyclePanel::strokeOf(const LimitMeasure& x) const {
  if (!doc_ || !doc_->solved() || !doc_->motionStatus().ok() || !doc_->design().driver)
    return std::nullopt;
  const std::string name = measureText(doc_->design(), x);
  if (!stale() && diagram())
    for (const CycleRow& r : diagram_.rows)
      if (r.output.name == name) return std::pair{r.min, r.max};
  const CycleDiagram d = cycleDiagram(doc_->kinematics(), {{name, x}}, {}, {});
  if (!d.status.ok() || d.rows.empty()) return std::nullopt;
  return std::pair{d.rows[0].min, d.rows[0].max};
}

// A field of the form changed: a new window's crank angles are shown; the window chosen in the
// list is edited (one undo step). A new output whose stroke the threshold misses (the window
// would always or never hold) gets its threshold at mid-stroke.
void CyclePanel::formEdited(bool outputChanged) {
  if (!doc_) return;
  const Mechanism& m = doc_->design();
  QString why;
  std::optional<TimingWindow> w = form_->window(m, &why);
  if (!w) {
    form_->setResult(why);
    return;
  }
  if (outputChanged)
    if (const auto s = strokeOf(w->output); s && !(w->level > s->first && w->level < s->second)) {
      w->level = roundLevel((s->first + s->second) / 2);
      form_->setLevel(w->level);
    }
  const int i = form_->target();
  if (i < 0) {
    showDraftResult(*w);
    return;
  }
  if (i >= static_cast<int>(m.timing.windows.size()) || *w == m.timing.windows[i]) return;
  if (!editEntry(EntryKind::Window, i, q(windowText(m, *w)), &why)) {
    setError(why);
    form_->load(i, doc_->design().timing.windows[i], doc_->design());
  }
}

void CyclePanel::showDraftResult(const TimingWindow& w) {
  if (!doc_ || !doc_->solved() || !doc_->motionStatus().ok() || !doc_->design().driver) {
    form_->setResult({});
    return;
  }
  const Mechanism& m = doc_->design();
  const CycleDiagram d =
      cycleDiagram(doc_->kinematics(), {},
                   {{w.name, {measureText(m, w.output), w.output}, w.below, w.level}}, {});
  form_->setResult(d.status.ok() ? windowResult(d.windows.at(0).intervals) : q(d.status.message));
}

void CyclePanel::addFromForm() {
  if (!doc_) return;
  const Mechanism& m = doc_->design();
  QString why;
  const std::optional<TimingWindow> w = form_->window(m, &why);
  const int n = static_cast<int>(m.timing.windows.size());
  if (!w || !addEntry(EntryKind::Window, q(windowText(m, *w)), &why)) {
    setError(why);
    return;
  }
  setFormTarget(n);  // the window added is the one the form edits now
}

void CyclePanel::pointPicked(PointId p) {
  form_->setPicking(false);
  if (!doc_ || !doc_->design().point(p)) return;
  form_->choosePoint(doc_->design(), p);
  // Then the axis and the comparison, as the pick's hint said.
  form_->axisBox()->setFocus(Qt::OtherFocusReason);
}

void CyclePanel::pickEnded() {
  form_->setPicking(false);
}

std::optional<QPointF> CyclePanel::levelPixel(int window, double crankDeg) const {
  if (!diagram()) return std::nullopt;
  return levels_->pixelOf(window, crankDeg);
}

void CyclePanel::beginLevelDrag(int window) {
  if (!doc_ || window >= static_cast<int>(doc_->design().timing.windows.size())) return;
  // Chosen for the form, which is not shown for it: the diagram must not move under the mouse.
  if (form_->target() != window) setFormTarget(window, false);
  levelDrag_ = window;
  preview_ = doc_->design().timing;
}

void CyclePanel::dragLevel(double pixelY) {
  if (!preview_ || levelDrag_ >= static_cast<int>(preview_->windows.size())) return;
  const double v = roundLevel(levels_->levelAt(levelDrag_, pixelY));
  if (v == preview_->windows[levelDrag_].level) return;
  preview_->windows[levelDrag_].level = v;
  form_->setLevel(v);
  schedule();  // the diagram, the list and the form follow at the throttle's pace
}

// The release: the level reached is the window's, one undo step (none when it did not move).
void CyclePanel::endLevelDrag() {
  const int w = levelDrag_;
  levelDrag_ = -1;
  if (!preview_ || !doc_) return;
  const TimingWindow x = preview_->windows.at(w);
  preview_.reset();
  const Mechanism& m = doc_->design();
  if (w >= static_cast<int>(m.timing.windows.size())) return;
  QString why;
  if (x != m.timing.windows[w] && editEntry(EntryKind::Window, w, q(windowText(m, x)), &why))
    return;
  if (!why.isEmpty()) setError(why);
  form_->setLevel(m.timing.windows[w].level);
  markStale();  // back to the document's
}

}  // namespace linkage::ui
