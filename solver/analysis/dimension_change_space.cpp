// Exact changes of a machine in space's own dimensions (analysis/dimension_change_space.h).
#include "analysis/dimension_change_space.h"

#include <Eigen/Geometry>
#include <cmath>

#include "analysis/sensitivity_space.h"
#include "kinematics/kinematics_state.h"
#include "linkage/elements.h"
#include "linkage/space.h"

namespace linkage::internal {

namespace {

bool isPlaneOrigin(const Dimension& d) {
  return d.name.starts_with("planes.") && d.name.find(".origin.") != std::string::npos;
}

bool isGroundSlot(const Mechanism& m, const Dimension& d) {
  const Body* g = m.ground();
  if (!isSpatial(m) || !g) return false;
  for (const Dimension::SlotMove& s : d.slots)
    if (const Slot* slot = m.slot(s.slot); slot && slot->body == g->id) return true;
  return false;
}

// The planes' origins: `planes.NAME.origin.C`, C one of x, y, z.
void movePlane(Mechanism& m, const Dimension& d, double by) {
  const size_t at = d.name.rfind(".origin.");
  const std::string name = d.name.substr(7, at - 7);
  const int c = d.name.back() - 'x';
  for (Plane& f : *m.planes)
    if (f.name == name) f.origin[c] += by;
}

// A straight ground slot's angle (degrees) then offset, in its block's plane (as
// groundSlotInSpace measures them).
Status moveGroundSlot(Mechanism& m, Slot& s, double turnDeg, double offset) {
  const PlaneClasses pc = planeClasses(m);
  const int cls = groundSlotClass(m, pc, s);
  if (cls < 0 || s.arc()) return Status::success();
  const Vec3 n = pc.frames[cls].normal();
  const Vec3 w0(s.p0.x(), s.p0.y(), s.z.size() > 0 ? s.z[0] : 0.0);
  const Vec3 w1(s.p1.x(), s.p1.y(), s.z.size() > 1 ? s.z[1] : 0.0);
  const Vec3 along = Eigen::AngleAxisd(turnDeg * M_PI / 180, n) * (w1 - w0);
  const Vec3 shift = offset * n.cross(along.normalized());
  const Vec3 e0 = w0 + shift, e1 = w0 + along + shift;
  s.p0 = e0.head<2>();
  s.p1 = e1.head<2>();
  if (!s.z.empty() || e0.z() != 0 || e1.z() != 0) s.z = {e0.z(), e1.z()};
  return Status::success();
}

// A ground arc's centre moved in the world and its radius changed about it, in its plane.
Status moveGroundArc(Mechanism& m, Slot& s, const Vec3& shift, double dr) {
  std::vector<Vec3> w = slotInWorld(s);
  Vec3 c;
  double r;
  if (!circleThrough(w[0], w[1], w[2], c, r)) return Status::success();
  if (!(r + dr > 0))
    return Status::badModel(m.slotLabel(s.id) + ".radius: an arc's radius must stay above 0");
  for (Vec3& p : w) p = c + shift + (r + dr) / r * (p - c);
  s.p0 = w[0].head<2>();
  s.mid = w[1].head<2>();
  s.p1 = w[2].head<2>();
  if (!s.z.empty() || w[0].z() != 0 || w[1].z() != 0 || w[2].z() != 0)
    s.z = {w[0].z(), w[1].z(), w[2].z()};
  return Status::success();
}

// The ground slots' own dimensions changed: a straight one's angle and offset, an arc's centre
// and radius.
Status moveGroundSlots(Mechanism& m, const std::vector<Dimension>& dims,
                       const std::vector<double>& delta) {
  for (Slot& s : m.slots) {
    const std::string pre = m.slotLabel(s.id) + ".";
    double turn = 0, offset = 0, radius = 0;
    Vec3 shift = Vec3::Zero();
    for (size_t k = 0; k < dims.size(); ++k) {
      if (delta[k] == 0 || !isGroundSlot(m, dims[k]) || dims[k].slots[0].slot != s.id) continue;
      const std::string what = dims[k].name.substr(pre.size());
      if (what.starts_with("centre."))
        shift[what.back() - 'x'] += delta[k];
      else
        (what == "angle" ? turn : what == "radius" ? radius : offset) += delta[k];
    }
    if (s.arc() && (radius != 0 || !shift.isZero(0))) {
      if (Status st = moveGroundArc(m, s, shift, radius); !st.ok()) return st;
    } else if (turn != 0 || offset != 0) {
      moveGroundSlot(m, s, turn, offset);
    }
  }
  return Status::success();
}

}  // namespace

Status changeInSpace(Mechanism& m, const std::vector<Dimension>& dims,
                     const std::vector<double>& delta) {
  if (!isSpatial(m)) return Status::success();  // none of these dimensions: the planar path
  if (Status st = moveGroundSlots(m, dims, delta); !st.ok()) return st;
  for (size_t k = 0; k < dims.size(); ++k) {
    if (delta[k] == 0 || dims[k].depths.empty()) continue;
    if (isPlaneOrigin(dims[k])) {
      movePlane(m, dims[k], delta[k]);
      continue;
    }
    for (const auto& [p, per] : dims[k].depths)
      if (Point* q = m.point(p)) q->third = q->third.value_or(0.0) + per * delta[k];
  }
  return Status::success();
}

namespace {

// The bodies of the state's system redrawn at coordinates q: each moving body's points, slot
// ends and centre of mass (in its plane's coordinates, through its class's frame) by its rigid
// move from the
// drawing; a body that q leaves where it is drawn (to rounding) keeps its numbers to the bit.
// So the new drawing is closed: its rods' drawn lengths are the solve's.
void redraw(Mechanism& m, const System& sys, const Eigen::VectorXd& q) {
  const PlaneClasses pc = planeClasses(m);
  for (int k = 0; k < sys.nBodies; ++k) {
    Body* b = m.body(sys.bodyIds[k]);
    if (!b) continue;
    const PlaneInClass& at = pc.of(b->plane);
    const Rot R = Rot::of(q[3 * k + 2]);
    const Vec2 r(q[3 * k], q[3 * k + 1]);
    auto moved = [&](const Vec2& p) {
      return at.fromClass(r + R * (at.toClass(p) - sys.frameOrigin[k]));
    };
    double most = 0;
    for (const Point& p : m.points)
      if (p.body == b->id) most = std::max(most, (moved(p.pos) - p.pos).norm());
    if (most <= 1e-15 * sys.size) continue;
    for (Point& p : m.points)
      if (p.body == b->id) p.pos = moved(p.pos);
    for (Slot& s : m.slots)
      if (s.body == b->id)
        for (Vec2* e : {&s.p0, &s.p1}) *e = moved(*e);
    for (Slot& s : m.slots)
      if (s.body == b->id && s.mid) *s.mid = moved(*s.mid);
    // Its mass goes with it (a centre of mass is drawn in sketch coordinates, as its points).
    if (b->mass) {
      b->mass->com = moved(b->mass->com);
      for (PointMass& c : b->mass->counterweights) c.at = moved(c.at);
    }
  }
}

}  // namespace

std::vector<RodLength> rodLengths(const Mechanism& m, const std::vector<Dimension>& dims,
                                  const std::vector<double>& delta) {
  std::vector<RodLength> out;
  for (const Joint& j : m.joints) {
    if (kindOf(j).role != Role::Distance) continue;
    const Point *a = m.point(j.a), *b = m.point(j.b);
    if (!a || !b) continue;
    RodLength r{j.id, (worldOf(m, *a) - worldOf(m, *b)).norm()};
    for (size_t k = 0; k < dims.size(); ++k)
      if (dims[k].lengthOf == j.id) r.length += delta[k];
    out.push_back(r);
  }
  return out;
}

Status keepRodLengths(Mechanism& m, const std::vector<RodLength>& rods, const std::string& what) {
  bool differ = false;
  for (const RodLength& r : rods) {
    const Joint* j = m.joint(r.rod);
    if (!(r.length > 0))
      return Status::badModel(what + ": ball rod " + m.pointLabel(j->a) + "-" + m.pointLabel(j->b) +
                              " would be no longer than 0");
    differ = differ || (worldOf(m, *m.point(j->a)) - worldOf(m, *m.point(j->b))).norm() != r.length;
  }
  if (!differ) return Status::success();
  Kinematics k;
  if (Status s = k.load(m); !s.ok()) return Status::badModel(what + ": " + s.message);
  KinematicsState st = state(k);
  // The rods' rows, from their drawn lengths to the wanted ones in steps that Newton follows
  // (halved until it does): the machine carried along on its branch.
  std::vector<std::pair<Row*, double>> rows;  // and its drawn length
  for (Row& row : st.sys.cons)
    for (const RodLength& r : rods)
      if (row.kind == Primitive::Distance3 && row.joint >= 0 && m.joints[row.joint].id == r.rod)
        rows.push_back({&row, row.c[0]});
  const Eigen::VectorXd start = st.coordinates(st.cur()).q;
  Eigen::VectorXd q = start;
  bool closed = false;
  for (int steps = 1; steps <= 256 && !closed; steps *= 4) {
    q = start;
    closed = true;
    for (int i = 1; i <= steps && closed; ++i) {
      for (auto& [row, drawn] : rows)
        for (const RodLength& r : rods)
          if (m.joints[row->joint].id == r.rod) row->c[0] = drawn + (r.length - drawn) * i / steps;
      closed = st.newton.solve(st.sys, q, st.cur().phi, st.opt.newton).converged;
    }
  }
  if (!closed)
    return Status::badModel(what + ": the machine does not close with its ball rods at their " +
                            "lengths at the drawing's crank angle");
  redraw(m, st.sys, q);
  return Status::success();
}

}  // namespace linkage::internal
