// Compiling a Mechanism to a System (system/system.h): bodies and their lookups by id, frames at
// the centroid of each body's drawn geometry, each joint's rows (as its kind says:
// linkage/elements.h), the driver's row. Linear in the size of the mechanism.
#include <algorithm>
#include <cmath>

#include "elements/angles.h"
#include "elements/frames.h"
#include "linkage/elements.h"
#include "linkage/guide.h"
#include "system/system.h"

namespace linkage {

namespace {

// Beyond these, squares of lengths overflow or every length drowns in rounding: refuse rather
// than return numbers that mean nothing.
constexpr double kLargest = 1e12, kSmallest = 1e-9;  // mm

class Compiler : public Frames {
 public:
  Compiler(const Mechanism& m, Status& status) : m_(m), status_(status) {}

  int body(BodyId id) const override { return knownBody(id) ? sys_.bodyIndex(id) : -2; }
  const PointLocation* point(PointId p) const override { return sys_.point(p); }
  Vec2 local(int k, const Vec2& p) const override {
    return k >= 0 ? Vec2(p - sys_.frameOrigin[k]) : p;
  }
  const Slot* slot(SlotId id) const override {
    return id.owner == sys_.owner && id.value < slotById_.size() ? slotById_[id.value] : nullptr;
  }
  double size() const override { return sys_.size; }

  std::optional<System> run() {
    status_ = Status::success();
    sys_.owner = m_.owner();
    if (!bodies() || !geometry() || !joints() || !driver()) return std::nullopt;
    sys_.nRows = row_;
    return std::move(sys_);
  }

 private:
  bool fail(std::string msg) {
    status_ = Status::badModel(std::move(msg));
    return false;
  }

  // The ground, the moving bodies and lookups by id value.
  bool bodies() {
    // Entities copied in from another mechanism carry its ids, which nothing here can resolve.
    auto foreign = [&](const auto& v) {
      return std::any_of(v.begin(), v.end(),
                         [&](const auto& e) { return e.id.owner != sys_.owner; });
    };
    if (foreign(m_.bodies) || foreign(m_.points) || foreign(m_.slots) || foreign(m_.joints))
      return fail(
          "an entity carries an id of another mechanism: copy entities with their names, "
          "not their ids");
    int grounds = 0;
    for (const Body& b : m_.bodies) {
      if (b.ground) {
        ++grounds;
        sys_.groundId = b.id;
      } else {
        sys_.bodyIds.push_back(b.id);
      }
    }
    if (grounds != 1)
      return fail(grounds == 0 ? "no body is the ground" : "more than one body is the ground");
    sys_.nBodies = static_cast<int>(sys_.bodyIds.size());
    std::uint32_t maxBody = 0;
    for (const Body& b : m_.bodies) maxBody = std::max(maxBody, b.id.value);
    isBody_.assign(maxBody + 1, 0);
    for (const Body& b : m_.bodies) isBody_[b.id.value] = 1;
    sys_.bodyIndexById.assign(maxBody + 1, -1);
    for (int k = 0; k < sys_.nBodies; ++k) sys_.bodyIndexById[sys_.bodyIds[k].value] = k;
    std::uint32_t maxSlot = 0;
    for (const Slot& sl : m_.slots) maxSlot = std::max(maxSlot, sl.id.value);
    slotById_.assign(maxSlot + 1, nullptr);
    for (const Slot& sl : m_.slots) slotById_[sl.id.value] = &sl;
    return true;
  }

  bool knownBody(BodyId id) const {
    return id.owner == sys_.owner && id.value < isBody_.size() && isBody_[id.value];
  }
  PointLocation at(BodyId b, const Vec2& p) const {
    const int k = sys_.bodyIndex(b);
    return {k, local(k, p)};
  }

  // The size, frames at the centroids, the points in them and the weights of the movement norm.
  bool geometry() {
    std::vector<Vec2> sum(sys_.nBodies, Vec2::Zero());
    std::vector<int> count(sys_.nBodies, 0);
    Vec2 lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
    auto add = [&](BodyId body, const Vec2& p) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
      const int k = sys_.bodyIndex(body);
      if (k >= 0) {
        sum[k] += p;
        ++count[k];
      }
    };
    for (const Point& p : m_.points) {
      if (!knownBody(p.body)) return fail("point \"" + p.name + "\" belongs to no body");
      add(p.body, p.pos);
    }
    for (const Slot& s : m_.slots) {
      if (!knownBody(s.body)) return fail("slot \"" + s.name + "\" belongs to no body");
      std::string why;
      if (!guideOf(s, &why)) return fail("slot " + m_.slotLabel(s.id) + ": " + why);
      add(s.body, s.p0);
      add(s.body, s.p1);
      if (s.mid) add(s.body, *s.mid);
    }
    if (lo.allFinite() && std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff()) > kLargest)
      return fail("coordinates beyond 1e12 mm: the drawing is too large to compute with");
    sys_.size = (lo.allFinite() && hi.allFinite()) ? (hi - lo).norm() : 1.0;
    // The ground alone (the first pivot of a new drawing): nothing moves, so no rounding can
    // swamp a motion; a single point has no extent, and a millimetre stands for it.
    if (sys_.nBodies == 0) sys_.size = std::max(sys_.size, 1.0);
    if (sys_.nBodies > 0 && lo.allFinite() &&
        sys_.size < kSmallest * std::max(1.0, hi.cwiseAbs().maxCoeff()))
      return fail(
          "the drawing's extent is below 1e-9 of its size or distance from the origin "
          "(or all its points coincide): rounding would swamp it");
    sys_.frameOrigin.resize(sys_.nBodies);
    for (int k = 0; k < sys_.nBodies; ++k)
      sys_.frameOrigin[k] = count[k] ? Vec2(sum[k] / count[k]) : Vec2::Zero();
    weights();
    return true;
  }

  // Weights of the movement norm: the sum over a body's geometry of |dp|^2 is
  // n |dr|^2 + dtheta^2 sum |s|^2 about the centroid; a small floor keeps it positive definite.
  // And the points by id.
  void weights() {
    const double L = sys_.size;
    sys_.bodyWeightXY.assign(sys_.nBodies, 0.0);
    sys_.bodyWeightTheta.assign(sys_.nBodies, 0.0);
    auto weigh = [&](const PointLocation& loc) {
      if (loc.body < 0) return;
      sys_.bodyWeightXY[loc.body] += 1;
      sys_.bodyWeightTheta[loc.body] += loc.s.squaredNorm();
    };
    std::uint32_t maxId = 0;
    for (const Point& p : m_.points) maxId = std::max(maxId, p.id.value);
    sys_.points.assign(maxId + 1, PointLocation{});
    sys_.hasPoint.assign(maxId + 1, 0);
    for (const Point& p : m_.points) {
      sys_.points[p.id.value] = at(p.body, p.pos);
      sys_.hasPoint[p.id.value] = 1;
      weigh(sys_.points[p.id.value]);
    }
    for (const Slot& s : m_.slots) {
      weigh(at(s.body, s.p0));
      weigh(at(s.body, s.p1));
      if (s.mid) weigh(at(s.body, *s.mid));
    }
    for (int k = 0; k < sys_.nBodies; ++k) {
      sys_.bodyWeightXY[k] = std::max(sys_.bodyWeightXY[k], 1.0);
      sys_.bodyWeightTheta[k] += 1e-6 * L * L;
    }
  }

  // Each joint's rows, as its kind compiles them, once its references resolve and its kind's
  // checks hold; one body on both sides of a joint has nothing to join.
  bool joints() {
    sys_.jointIds.reserve(m_.joints.size());
    sys_.cons.reserve(2 * m_.joints.size() + 1);
    std::vector<Row> rows;
    for (size_t ji = 0; ji < m_.joints.size(); ++ji) {
      const Joint& j = m_.joints[ji];
      const ElementKind& kind = kindOf(j);
      sys_.jointIds.push_back(j.id);
      const std::string where = "joints[" + std::to_string(ji) + "]";
      if (!references(j, kind, where)) return false;
      const char* field = "a";
      if (std::string why = kind.check(m_, j, field); !why.empty())
        return fail(where + "." + field + ": " + why);
      rows.clear();
      std::string why;
      if (!kind.compile(m_, j, *this, rows, why)) return fail(where + ": " + why);
      for (Row& r : rows) {
        r.joint = static_cast<int>(ji);
        push(r);
      }
    }
    sys_.nJointRows = row_;
    return true;
  }

  // The points, slot and carrier the kind reads exist; the sides it joins are two bodies.
  bool references(const Joint& j, const ElementKind& kind, const std::string& where) {
    const PointLocation* a = sys_.point(j.a);
    if (!a) return fail(where + ".a: unknown point");
    int other = -3;
    if (kind.reads(FieldType::Point, 1)) {
      const PointLocation* b = sys_.point(j.b);
      if (!b) return fail(where + ".b: unknown point");
      other = b->body;
    }
    if (kind.reads(FieldType::Slot)) {
      const Slot* s = slot(j.slot);
      if (!s) return fail(where + ".slot: unknown slot");
      other = sys_.bodyIndex(s->body);
    }
    if (kind.reads(FieldType::Body) && j.carrier && !knownBody(j.carrier))
      return fail(where + ".carrier: unknown body");
    if (other == a->body) return fail(where + ": both sides are on one body");
    return true;
  }

  void push(Row c) {
    c.row = row_;
    row_ += c.rows();
    sys_.cons.push_back(c);
  }

  // theta_b - theta_a = sigma phi at the driver's pin: the body of b turns relative to a's.
  bool driver() {
    if (!m_.driver) return true;
    const int ji = m_.jointIndex(m_.driver->joint);
    if (ji < 0 || kindOf(m_.joints[ji]).role != Role::Revolute)
      return fail("driver: its joint must be a pin");
    const Joint& j = m_.joints[ji];
    sys_.hasDriver = true;
    sys_.sigma = angles::driveSign(m_.driver->direction == Direction::Cw);
    Row d;
    d.kind = Primitive::Angles;
    d.joint = ji;
    d.body[0] = sys_.point(j.b)->body;
    d.body[1] = sys_.point(j.a)->body;
    d.c[0] = 1;
    d.c[1] = -1;
    d.driven = sys_.sigma;
    sys_.driverRow = row_;
    push(d);
    sys_.rpm = m_.driver->rpm;
    sys_.startRad = m_.driver->startDeg * M_PI / 180.0;
    return true;
  }

  const Mechanism& m_;
  Status& status_;
  System sys_;
  int row_ = 0;
  std::vector<char> isBody_;
  std::vector<const Slot*> slotById_;
};

}  // namespace

std::optional<System> compile(const Mechanism& m, Status& status) {
  return Compiler(m, status).run();
}

}  // namespace linkage
