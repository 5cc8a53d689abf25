// Compiling a Mechanism to a System (system/system.h): bodies and their lookups by id, frames at
// the centroid of each body's drawn geometry, each joint's rows (as its kind says:
// linkage/elements.h), the driver's row. Linear in the size of the mechanism.
#include <algorithm>
#include <cmath>
#include <map>

#include "elements/angles.h"
#include "elements/frames.h"
#include "linkage/elements.h"
#include "linkage/guide.h"
#include "linkage/space.h"
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
  const PointLocation* point(PointId p) const override {
    const PointLocation* at = sys_.point(p);
    if (!spatial_ || !at || at->body >= 0) return at;
    auto [it, fresh] = groundAt_.try_emplace({cls_, p.value});
    if (fresh) it->second = PointLocation{-1, classes_.project(cls_, world_[p.value])};
    return &it->second;
  }
  Vec2 local(int k, const Vec2& p) const override {
    return k >= 0 ? Vec2(p - sys_.frameOrigin[k]) : p;
  }
  const Slot* slot(SlotId id) const override {
    const Slot* s =
        id.owner == sys_.owner && id.value < slotById_.size() ? slotById_[id.value] : nullptr;
    return spatial_ && s ? inClass(*s) : s;
  }
  Vec2 position(PointId p) const override {
    const PointLocation* at = point(p);
    return at->body >= 0 ? Vec2(at->s + sys_.frameOrigin[at->body]) : at->s;
  }
  InSpace inSpace(PointId p) const override {
    const PointLocation* at = sys_.point(p);
    if (!spatial_) return {at->body, at->s, 0, 0.0};
    if (at->body >= 0) return {at->body, at->s, sys_.classOf[at->body], depth_[p.value]};
    double depth = 0;
    const Vec2 s = classes_.project(0, world_[p.value], &depth);
    return {-1, s, 0, depth};
  }
  double size() const override { return sys_.size; }

  std::optional<System> run() {
    status_ = Status::success();
    sys_.owner = m_.owner();
    if (!bodies() || !planes() || !geometry() || !joints() || !driver()) return std::nullopt;
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

  // The plane classes, each body's place in its class, each point's position there and in the
  // world. With no planes, every position is the drawing's own.
  bool planes() {
    spatial_ = isSpatial(m_);
    sys_.classOf.assign(sys_.nBodies, 0);
    placing_.assign(sys_.nBodies, PlaneInClass{});
    std::uint32_t maxId = 0;
    for (const Point& p : m_.points) maxId = std::max(maxId, p.id.value);
    classPos_.assign(maxId + 1, Vec2::Zero());
    if (spatial_) {
      if (std::string why = planesProblem(m_); !why.empty()) return fail(why);
      classes_ = planeClasses(m_);
      sys_.frames = classes_.frames;
      for (int k = 0; k < sys_.nBodies; ++k) {
        placing_[k] = classes_.of(m_.body(sys_.bodyIds[k])->plane);
        sys_.classOf[k] = placing_[k].cls;
      }
      world_.assign(maxId + 1, Vec3::Zero());
      depth_.assign(maxId + 1, 0.0);
    }
    for (const Point& p : m_.points) {
      const int k = sys_.bodyIndex(p.body);
      classPos_[p.id.value] = k >= 0 ? placing_[k].toClass(p.pos) : p.pos;
      if (!spatial_) continue;
      world_[p.id.value] = worldOf(m_, p);
      if (k >= 0) depth_[p.id.value] = placing_[k].depth + p.third.value_or(0.0);
    }
    sys_.pointDepth = depth_;
    return true;
  }

  // A slot as the current joint's class sees it: a moving body's mapped from its plane, the
  // ground's projected onto the class's frame.
  const Slot* inClass(const Slot& s) const {
    auto [it, fresh] = slotAt_.try_emplace({cls_, s.id.value}, s);
    if (fresh) it->second = inClassFrame(m_, classes_, s, cls_);
    return &it->second;
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
    Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
    auto extend = [&](const Vec3& w) {
      lo = lo.cwiseMin(w);
      hi = hi.cwiseMax(w);
    };
    auto add = [&](BodyId body, const Vec2& p) {
      if (!spatial_) extend(Vec3(p.x(), p.y(), 0));
      const int k = sys_.bodyIndex(body);
      if (k >= 0) {
        sum[k] += p;
        ++count[k];
      }
    };
    for (const Point& p : m_.points) {
      if (!knownBody(p.body)) return fail("point \"" + p.name + "\" belongs to no body");
      add(p.body, classPos_[p.id.value]);
      // In space the size is the world's extent (the classes' frames may be far apart).
      if (spatial_) extend(world_[p.id.value]);
    }
    for (const Slot& s : m_.slots) {
      if (!knownBody(s.body)) return fail("slot \"" + s.name + "\" belongs to no body");
      std::string why;
      if (!soundSlot(s, &why)) return fail("slot " + m_.slotLabel(s.id) + ": " + why);
      const Slot& c = spatial_ && sys_.bodyIndex(s.body) >= 0 ? *inClass(s) : s;
      add(s.body, c.p0);
      add(s.body, c.p1);
      if (c.mid) add(s.body, *c.mid);
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
      sys_.points[p.id.value] = at(p.body, classPos_[p.id.value]);
      sys_.hasPoint[p.id.value] = 1;
      weigh(sys_.points[p.id.value]);
    }
    for (const Slot& sl : m_.slots) {
      const Slot& s = spatial_ && sys_.bodyIndex(sl.body) >= 0 ? *inClass(sl) : sl;
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
      cls_ = jointClass(j, kind);
      const char* field = "a";
      if (std::string why = checkJoint(m_, j, field); !why.empty())
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

  // The class a joint is written in: its first moving body's (a's, else b's or the slot's).
  int jointClass(const Joint& j, const ElementKind& kind) const {
    if (!spatial_) return 0;
    for (const FieldSpec& f : kind.fields) {
      int k = -1;
      if (f.type == FieldType::Point) k = sys_.point(pointField(j, f))->body;
      if (f.type == FieldType::Slot) k = sys_.bodyIndex(slotById_[j.slot.value]->body);
      if (k >= 0) return sys_.classOf[k];
    }
    return 0;
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
    if (c.kind == Primitive::Cam) sys_.contactRows = true;
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
  bool spatial_ = false;
  int cls_ = 0;  // the class of the joint being compiled
  PlaneClasses classes_;
  std::vector<PlaneInClass> placing_;  // by body index
  std::vector<Vec2> classPos_;         // by point id value: in its body's class frame
  std::vector<Vec3> world_;            // by point id value (in space only)
  std::vector<double> depth_;          // by point id value: along its class's normal
  mutable std::map<std::pair<int, std::uint32_t>, PointLocation> groundAt_;
  mutable std::map<std::pair<int, std::uint32_t>, Slot> slotAt_;
  std::vector<char> isBody_;
  std::vector<const Slot*> slotById_;
};

}  // namespace

std::optional<System> compile(const Mechanism& m, Status& status) {
  return Compiler(m, status).run();
}

}  // namespace linkage
