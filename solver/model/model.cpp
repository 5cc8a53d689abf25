#include "linkage/model.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace linkage {

namespace {

std::uint32_t newOwner() {
  static std::atomic<std::uint32_t> next{1};
  return next++;
}

template <class T, class IdT>
bool listed(const std::vector<IdT>& ids, const T& id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

// Moves the elements `gone` says to `out`, with their indices, keeping the others' order.
template <class T, class Pred>
void take(std::vector<T>& v, Pred gone, std::vector<Removal::At<T>>& out) {
  std::vector<T> kept;
  kept.reserve(v.size());
  for (size_t i = 0; i < v.size(); ++i) {
    if (gone(v[i]))
      out.push_back({i, std::move(v[i])});
    else
      kept.push_back(std::move(v[i]));
  }
  v = std::move(kept);
}

template <class T>
void putBack(std::vector<T>& v, const std::vector<Removal::At<T>>& in) {
  for (const auto& e : in) v.insert(v.begin() + static_cast<std::ptrdiff_t>(e.index), e.value);
}
template <class T, class IdT>
T* findById(std::vector<T>& v, IdT id) {
  auto it = std::find_if(v.begin(), v.end(), [&](const T& e) { return e.id == id; });
  return it == v.end() ? nullptr : &*it;
}
// The cycle diagram's parts that follow what is gone: rows, windows and clearances on a gone
// point, slot or body, and the conflicts naming a window that goes.
void takeTiming(Timing& t, const std::vector<PointId>& goneP, const std::vector<SlotId>& goneS,
                const std::vector<BodyId>& goneB, Removal& r) {
  auto measureGone = [&](const LimitMeasure& x) {
    return listed(goneP, x.point) || listed(goneB, x.body);
  };
  take(t.outputs, measureGone, r.timingOutputs);
  take(
      t.windows, [&](const TimingWindow& w) { return measureGone(w.output); }, r.timingWindows);
  auto windowGone = [&](const std::string& name) {
    return std::any_of(r.timingWindows.begin(), r.timingWindows.end(),
                       [&](const auto& w) { return w.value.name == name; });
  };
  take(
      t.conflicts,
      [&](const TimingConflict& c) { return windowGone(c.first) || windowGone(c.second); },
      r.timingConflicts);
  take(
      t.clearances,
      [&](const ClearanceWatch& c) {
        return listed(goneP, c.point) || listed(goneP, c.other.point) ||
               listed(goneP, c.other.end) || listed(goneS, c.other.slot);
      },
      r.clearances);
}

}  // namespace

Mechanism::Mechanism() : owner_(newOwner()) {}

namespace {

std::string beyond(double v, double most, const char* bound, const char* what) {
  if (!std::isfinite(v)) return std::string("not a number: a ") + what + " is a finite number";
  if (v < 0) return std::string("a ") + what + " is 0 or more";
  if (v <= most) return {};
  return std::string("a ") + what + " beyond " + bound +
         ": no link of a machine has that, and its forces would overflow or drown the others' "
         "in rounding";
}

}  // namespace

std::string massRefusal(double kg) {
  return beyond(kg, kMaxMassKg, "1e6 kg (a thousand tonnes)", "mass");
}

std::string inertiaRefusal(double kgMm2) {
  return beyond(kgMm2, kMaxInertiaKgMm2, "1e15 kg mm^2 (a thousand tonnes 31.6 m from its centre)",
                "moment of inertia");
}

BodyId Mechanism::addBody(std::string name, bool isGround) {
  Body b;
  b.id = make<BodyId>();
  b.name = std::move(name);
  b.ground = isGround;
  bodies.push_back(std::move(b));
  return bodies.back().id;
}

PointId Mechanism::addPoint(BodyId bodyId, std::string name, Vec2 pos) {
  points.push_back(Point{make<PointId>(), bodyId, std::move(name), pos, std::nullopt});
  return points.back().id;
}

SlotId Mechanism::addSlot(BodyId bodyId, std::string name, Vec2 p0, Vec2 p1) {
  slots.push_back(Slot{make<SlotId>(), bodyId, std::move(name), p0, p1, std::nullopt, {}});
  return slots.back().id;
}

SlotId Mechanism::addArcSlot(BodyId bodyId, std::string name, Vec2 p0, Vec2 mid, Vec2 p1) {
  slots.push_back(Slot{make<SlotId>(), bodyId, std::move(name), p0, p1, mid, {}});
  return slots.back().id;
}

const RecordMember* recordMember(const Record& r, std::string_view key) {
  for (const RecordMember& m : r)
    if (m.key == key) return &m;
  return nullptr;
}

bool Joint::sameFields(const Joint& o) const {
  if (numbers.size() != o.numbers.size() || records != o.records) return false;
  for (size_t k = 0; k < numbers.size(); ++k)
    if (numbers[k] != o.numbers[k] && !(std::isnan(numbers[k]) && std::isnan(o.numbers[k])))
      return false;
  return true;
}

JointId Mechanism::addJoint(Joint j) {
  j.id = make<JointId>();
  joints.push_back(std::move(j));
  return joints.back().id;
}

LoadId Mechanism::addLoad(Load l) {
  l.id = make<LoadId>();
  loads.push_back(std::move(l));
  return loads.back().id;
}

JointId Mechanism::addPin(PointId a, PointId b) {
  return addJoint(Joint{{}, JointType::Pin, a, b, {}, {}, {}, {}, {}});
}

JointId Mechanism::addSlider(PointId a, SlotId s) {
  return addJoint(Joint{{}, JointType::Slider, a, {}, s, {}, {}, {}, {}});
}

JointId Mechanism::addPinInSlot(PointId a, SlotId s) {
  return addJoint(Joint{{}, JointType::PinInSlot, a, {}, s, {}, {}, {}, {}});
}

JointId Mechanism::addGear(PointId a, PointId b, double ratio, BodyId carrier) {
  return addJoint(Joint{{}, JointType::Gear, a, b, {}, carrier, {ratio}, {}, {}});
}

Removal Mechanism::remove(const std::vector<BodyId>& bodyIds, const std::vector<PointId>& pointIds,
                          const std::vector<SlotId>& slotIds,
                          const std::vector<JointId>& jointIds) {
  Removal r;
  auto pointGone = [&](const Point& p) {
    return listed(pointIds, p.id) || listed(bodyIds, p.body);
  };
  auto slotGone = [&](const Slot& s) { return listed(slotIds, s.id) || listed(bodyIds, s.body); };
  std::vector<PointId> goneP;
  std::vector<SlotId> goneS;
  for (const Point& p : points)
    if (pointGone(p)) goneP.push_back(p.id);
  for (const Slot& s : slots)
    if (slotGone(s)) goneS.push_back(s.id);
  take(
      joints,
      [&](const Joint& j) {
        return listed(jointIds, j.id) || listed(goneP, j.a) || listed(goneP, j.b) ||
               listed(goneS, j.slot) || listed(bodyIds, j.carrier);
      },
      r.joints);
  take(points, pointGone, r.points);
  take(slots, slotGone, r.slots);
  take(
      bodies, [&](const Body& b) { return listed(bodyIds, b.id); }, r.bodies);
  take(
      outputs, [&](const PointId& p) { return listed(goneP, p); }, r.outputs);
  take(
      loads, [&](const Load& l) { return listed(goneP, l.point) || listed(bodyIds, l.body); },
      r.loads);
  takeTiming(timing, goneP, goneS, bodyIds, r);
  const bool driverGone =
      driver && std::any_of(r.joints.begin(), r.joints.end(),
                            [&](const auto& j) { return j.value.id == driver->joint; });
  if (driverGone) {
    r.driver = driver;
    driver.reset();
  }
  return r;
}

void Mechanism::restore(const Removal& r) {
  putBack(bodies, r.bodies);
  putBack(points, r.points);
  putBack(slots, r.slots);
  putBack(joints, r.joints);
  putBack(outputs, r.outputs);
  putBack(loads, r.loads);
  putBack(timing.outputs, r.timingOutputs);
  putBack(timing.windows, r.timingWindows);
  putBack(timing.conflicts, r.timingConflicts);
  putBack(timing.clearances, r.clearances);
  if (r.driver) driver = r.driver;
}

void Timing::replaceWindow(size_t i, TimingWindow w) {
  for (TimingConflict& c : conflicts)
    for (std::string* n : {&c.first, &c.second})
      if (*n == windows[i].name) *n = w.name;
  windows[i] = std::move(w);
}

void Timing::removeWindow(size_t i) {
  const std::string name = windows[i].name;
  windows.erase(windows.begin() + static_cast<std::ptrdiff_t>(i));
  conflicts.erase(
      std::remove_if(conflicts.begin(), conflicts.end(),
                     [&](const TimingConflict& c) { return c.first == name || c.second == name; }),
      conflicts.end());
}

bool Load::activeAt(double crankDeg) const {
  if (!fromDeg || !toDeg) return true;
  // Angles modulo 360 in [0, 360); a window whose end is below its start wraps past 360.
  auto wrap = [](double a) {
    const double w = std::fmod(a, 360.0);
    return w < 0 ? w + 360 : w;
  };
  const double a = wrap(crankDeg), from = wrap(*fromDeg), to = wrap(*toDeg);
  if (*toDeg - *fromDeg >= 360) return true;
  return from <= to ? (a >= from && a <= to) : (a >= from || a <= to);
}

const Body* Mechanism::body(BodyId id) const {
  return const_cast<Mechanism*>(this)->body(id);
}
const Point* Mechanism::point(PointId id) const {
  return const_cast<Mechanism*>(this)->point(id);
}
const Slot* Mechanism::slot(SlotId id) const {
  return const_cast<Mechanism*>(this)->slot(id);
}
const Joint* Mechanism::joint(JointId id) const {
  return const_cast<Mechanism*>(this)->joint(id);
}
Body* Mechanism::body(BodyId id) {
  return findById(bodies, id);
}
Point* Mechanism::point(PointId id) {
  return findById(points, id);
}
Slot* Mechanism::slot(SlotId id) {
  return findById(slots, id);
}
Joint* Mechanism::joint(JointId id) {
  return findById(joints, id);
}
const Load* Mechanism::load(LoadId id) const {
  return const_cast<Mechanism*>(this)->load(id);
}
Load* Mechanism::load(LoadId id) {
  return id ? findById(loads, id) : nullptr;
}

const Body* Mechanism::bodyNamed(const std::string& n) const {
  for (const Body& b : bodies)
    if (b.name == n) return &b;
  return nullptr;
}

const Point* Mechanism::pointNamed(BodyId b, const std::string& n) const {
  for (const Point& p : points)
    if (p.body == b && p.name == n) return &p;
  return nullptr;
}

const Slot* Mechanism::slotNamed(BodyId b, const std::string& n) const {
  for (const Slot& s : slots)
    if (s.body == b && s.name == n) return &s;
  return nullptr;
}

const Body* Mechanism::ground() const {
  for (const Body& b : bodies)
    if (b.ground) return &b;
  return nullptr;
}

std::string Mechanism::pointLabel(PointId id) const {
  const Point* p = point(id);
  if (!p) return "?";
  const Body* b = body(p->body);
  return (b ? b->name : std::string("?")) + "." + p->name;
}

std::string Mechanism::slotLabel(SlotId id) const {
  const Slot* s = slot(id);
  if (!s) return "?";
  const Body* b = body(s->body);
  return (b ? b->name : std::string("?")) + "." + s->name;
}

std::string Mechanism::partLabel(const ClearancePart& part) const {
  if (part.isSlot()) return slotLabel(part.slot);
  if (!part.isSegment()) return pointLabel(part.point);
  const Point* e = point(part.end);
  return pointLabel(part.point) + "-" + (e ? e->name : std::string("?"));
}

std::string Mechanism::partDescription(const ClearancePart& part) const {
  return std::string(part.isSlot()      ? "the slot "
                     : part.isSegment() ? "the segment "
                                        : "the point ") +
         partLabel(part);
}

int Mechanism::jointIndex(JointId id) const {
  for (size_t i = 0; i < joints.size(); ++i)
    if (joints[i].id == id) return static_cast<int>(i);
  return -1;
}

std::optional<PointId> Mechanism::findPoint(const std::string& dotted) const {
  // Body names may themselves contain dots; the point name is what follows the last one.
  size_t dot = dotted.rfind('.');
  if (dot == std::string::npos) return std::nullopt;
  const Body* b = bodyNamed(dotted.substr(0, dot));
  if (!b) return std::nullopt;
  const Point* p = pointNamed(b->id, dotted.substr(dot + 1));
  if (!p) return std::nullopt;
  return p->id;
}

// A plane moved moves its bodies in space: another mechanism for the solver.
static bool samePlanes(const Mechanism& a, const Mechanism& b) {
  if (a.planes.has_value() != b.planes.has_value()) return false;
  if (!a.planes) return true;
  if (a.planes->size() != b.planes->size()) return false;
  for (size_t i = 0; i < a.planes->size(); ++i) {
    const Plane &p = (*a.planes)[i], &q = (*b.planes)[i];
    if (p.name != q.name || p.origin != q.origin || p.xAxis != q.xAxis || p.yAxis != q.yAxis)
      return false;
  }
  return true;
}

bool sameTopology(const Mechanism& a, const Mechanism& b, std::vector<BodyId>& reshaped) {
  reshaped.clear();
  if (a.bodies.size() != b.bodies.size() || a.points.size() != b.points.size() ||
      a.slots.size() != b.slots.size() || a.joints.size() != b.joints.size() ||
      a.driver.has_value() != b.driver.has_value() || !samePlanes(a, b))
    return false;
  for (size_t i = 0; i < a.bodies.size(); ++i)
    if (a.bodies[i].id != b.bodies[i].id || a.bodies[i].ground != b.bodies[i].ground ||
        a.bodies[i].plane != b.bodies[i].plane)
      return false;
  auto reshape = [&](BodyId id) {
    if (std::find(reshaped.begin(), reshaped.end(), id) == reshaped.end()) reshaped.push_back(id);
  };
  for (size_t i = 0; i < a.points.size(); ++i) {
    const Point &p = a.points[i], &q = b.points[i];
    if (p.id != q.id || p.body != q.body) return false;
    if (p.pos != q.pos || p.third != q.third) reshape(p.body);
  }
  for (size_t i = 0; i < a.slots.size(); ++i) {
    const Slot &p = a.slots[i], &q = b.slots[i];
    if (p.id != q.id || p.body != q.body) return false;
    if (p.arc() != q.arc()) return false;
    if (p.p0 != q.p0 || p.p1 != q.p1 || p.mid != q.mid || p.z != q.z) reshape(p.body);
  }
  for (size_t i = 0; i < a.joints.size(); ++i) {
    const Joint &p = a.joints[i], &q = b.joints[i];
    if (p.id != q.id || p.type != q.type || p.a != q.a || p.b != q.b || p.slot != q.slot ||
        p.carrier != q.carrier || !p.sameFields(q))
      return false;
  }
  if (a.driver &&
      (a.driver->joint != b.driver->joint || a.driver->direction != b.driver->direction ||
       a.driver->startDeg != b.driver->startDeg))
    return false;
  return true;
}

}  // namespace linkage
