#include "canvas/slot_warnings.h"

#include <algorithm>

#include "document/document.h"
#include "linkage/slot_travel.h"

namespace linkage::ui {

const std::vector<SlotWarning>& SlotWarnings::of(const Document& doc) {
  const Kinematics& k = doc.kinematics();
  const std::uint64_t revision = doc.motionStatus().ok() ? k.revision() : 0;
  if (revision == revision_) return warnings_;
  revision_ = revision;
  warnings_.clear();
  if (revision == 0 || !k.mechanism().driver) return warnings_;
  const SlotTravels travels = slotTravel(k);
  if (!travels.status.ok()) return warnings_;
  for (const SlotTravel& t : travels.joints) {
    if (t.inside) continue;
    // The farther of the two ends it passes.
    const bool past = t.past >= t.before;
    warnings_.push_back(
        {t.joint, t.slot, past ? t.past : t.before, past ? t.maxDeg : t.minDeg, past});
  }
  std::stable_sort(warnings_.begin(), warnings_.end(),
                   [](const SlotWarning& a, const SlotWarning& b) { return a.byMm > b.byMm; });
  return warnings_;
}

QString SlotWarnings::text(const Document& doc) {
  const std::vector<SlotWarning>& all = of(doc);
  if (all.empty()) return QString();
  const Mechanism& m = doc.kinematics().mechanism();
  const SlotWarning& w = all.front();
  const Joint* j = m.joint(w.joint);
  const bool block = j && j->type == JointType::Slider;
  QString s = QObject::tr("%1 '%2' leaves slot '%3' by %4 mm %5 at crank %6\u00b0")
                  .arg(block ? QObject::tr("block") : QObject::tr("pin"))
                  .arg(QString::fromStdString(j ? m.pointLabel(j->a) : std::string()))
                  .arg(QString::fromStdString(m.slotLabel(w.slot)))
                  .arg(w.byMm, 0, 'f', 2)
                  .arg(w.pastEnd ? QObject::tr("past its end") : QObject::tr("before its start"))
                  .arg(w.atDeg, 0, 'f', 1);
  if (all.size() > 1) s += QObject::tr(" (and %n more slot(s))", nullptr, int(all.size() - 1));
  return s;
}

}  // namespace linkage::ui
