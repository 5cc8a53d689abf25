// What the user has selected: points, bodies, joints and slots, by id (never pointers into
// the solver). The canvas highlights it; the properties panel edits it; Delete removes it.
#pragma once

#include <QObject>
#include <algorithm>
#include <vector>

#include "linkage/model.h"

namespace linkage::ui {

class Selection : public QObject {
  Q_OBJECT

 public:
  std::vector<PointId> points;
  std::vector<BodyId> bodies;
  std::vector<JointId> joints;
  std::vector<SlotId> slots_;

  bool empty() const {
    return points.empty() && bodies.empty() && joints.empty() && slots_.empty();
  }
  int size() const { return int(points.size() + bodies.size() + joints.size() + slots_.size()); }
  template <class Id>
  bool contains(Id id) const {
    const auto& v = list(id);
    return std::find(v.begin(), v.end(), id) != v.end();
  }
  // Adds, or with `toggle` removes what is there; emits changed().
  template <class Id>
  void add(Id id, bool toggle = false) {
    auto& v = list(id);
    auto it = std::find(v.begin(), v.end(), id);
    if (it == v.end())
      v.push_back(id);
    else if (toggle)
      v.erase(it);
    emit changed();
  }
  void clear() {
    if (empty()) return;
    points.clear();
    bodies.clear();
    joints.clear();
    slots_.clear();
    emit changed();
  }
  // Forgets what a mechanism no longer holds (after an edit or an undo).
  void prune(const Mechanism& m);

 Q_SIGNALS:
  void changed();

 private:
  std::vector<PointId>& list(PointId) { return points; }
  std::vector<BodyId>& list(BodyId) { return bodies; }
  std::vector<JointId>& list(JointId) { return joints; }
  std::vector<SlotId>& list(SlotId) { return slots_; }
  const std::vector<PointId>& list(PointId) const { return points; }
  const std::vector<BodyId>& list(BodyId) const { return bodies; }
  const std::vector<JointId>& list(JointId) const { return joints; }
  const std::vector<SlotId>& list(SlotId) const { return slots_; }
};

}  // namespace linkage::ui
