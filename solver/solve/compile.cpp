// Compiling a Mechanism to a System (solve/system.h): bodies and their lookups by id, frames at
// the centroid of each body's drawn geometry, the joints' rows (as their kinds say,
// joints/registry.h), the driver's row. Linear in the size of the mechanism.
#include <algorithm>
#include <cmath>

#include "joints/driver.h"
#include "joints/registry.h"
#include "solve/system.h"

namespace linkage {

namespace {

// Beyond these, squares of lengths overflow or every length drowns in rounding: refuse rather
// than return numbers that mean nothing.
constexpr double kLargest = 1e12, kSmallest = 1e-9;  // mm

class Compiler {
 public:
  Compiler(const Mechanism& m, Status& status) : m_(m), status_(status) {}

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
  const Slot* slot(SlotId id) const {
    return id.owner == sys_.owner && id.value < slotById_.size() ? slotById_[id.value] : nullptr;
  }
  PointLocation local(BodyId body, const Vec2& p) const {
    const int k = sys_.bodyIndex(body);
    return {k, k >= 0 ? Vec2(p - sys_.frameOrigin[k]) : p};
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
      if ((s.p1 - s.p0).norm() == 0) return fail("slot " + m_.slotLabel(s.id) + " has zero length");
      add(s.body, s.p0);
      add(s.body, s.p1);
    }
    if (lo.allFinite() && std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff()) > kLargest)
      return fail("coordinates beyond 1e12 mm: the drawing is too large to compute with");
    sys_.size = (lo.allFinite() && hi.allFinite()) ? (hi - lo).norm() : 1.0;
    if (lo.allFinite() && sys_.size < kSmallest * std::max(1.0, hi.cwiseAbs().maxCoeff()))
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
      sys_.points[p.id.value] = local(p.body, p.pos);
      sys_.hasPoint[p.id.value] = 1;
      weigh(sys_.points[p.id.value]);
    }
    for (const Slot& s : m_.slots) {
      weigh(local(s.body, s.p0));
      weigh(local(s.body, s.p1));
    }
    for (int k = 0; k < sys_.nBodies; ++k) {
      sys_.bodyWeightXY[k] = std::max(sys_.bodyWeightXY[k], 1.0);
      sys_.bodyWeightTheta[k] += 1e-6 * L * L;
    }
  }

  void push(Constraint c) {
    c.row = row_;
    row_ += c.rows();
    sys_.cons.push_back(c);
  }

  // Each joint's rows, as its kind says: the point a on body i, and point b or the slot (its
  // first end and its normal) on body j.
  bool joints() {
    sys_.jointIds.reserve(m_.joints.size());
    sys_.cons.reserve(2 * m_.joints.size() + 1);
    for (size_t ji = 0; ji < m_.joints.size(); ++ji) {
      const Joint& j = m_.joints[ji];
      const JointKind& kind = jointKind(j.type);
      sys_.jointIds.push_back(j.id);
      auto where = [&] { return "joints[" + std::to_string(ji) + "]"; };
      const PointLocation* a = sys_.point(j.a);
      if (!a) return fail(where() + ".a: unknown point");
      Constraint c;
      c.joint = static_cast<int>(ji);
      c.bi = a->body;
      c.si = a->s;
      if (kind.onSlot) {
        const Slot* s = slot(j.slot);
        if (!s) return fail(where() + ".slot: unknown slot");
        const PointLocation u = local(s->body, s->p0);
        c.bj = u.body;
        c.sj = u.s;
        c.nj = perp((s->p1 - s->p0).normalized());
      } else {
        const PointLocation* b = sys_.point(j.b);
        if (!b) return fail(where() + ".b: unknown point");
        c.bj = b->body;
        c.sj = b->s;
      }
      if (c.bj == c.bi) return fail(where() + ": both sides are on one body");
      for (int r = 0; r < kind.rowKinds; ++r) {
        c.kind = kind.rows[r];
        c.c = 0;  // Angle: both bodies are at angle 0 in the sketch
        push(c);
      }
    }
    sys_.nJointRows = row_;
    return true;
  }

  bool driver() {
    if (!m_.driver) return true;
    const int ji = m_.jointIndex(m_.driver->joint);
    if (ji < 0 || m_.joints[ji].type != JointType::Pin)
      return fail("driver: its joint must be a pin");
    const Joint& j = m_.joints[ji];
    Constraint d;
    d.kind = RowKind::Driver;
    d.joint = ji;
    d.bi = sys_.point(j.b)->body;  // theta_b - theta_a
    d.bj = sys_.point(j.a)->body;
    sys_.driverRow = row_;
    push(d);
    sys_.hasDriver = true;
    sys_.sigma = driveSign(m_.driver->direction == Direction::Cw);
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
