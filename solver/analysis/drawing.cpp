// The paint list: shapes from the mechanism's topology (which body is a bar, a plate, a block),
// positions from the kinematics at its pose.
#include "linkage/drawing.h"

#include "linkage/plane_view.h"
#include "linkage/space.h"

#include <algorithm>
#include <cmath>

#include "linkage/guide.h"

namespace linkage {

namespace {

// Whether the points and the slot a joint's kind reads are in the mechanism (a design being
// drawn is not checked).
bool resolves(const Mechanism& m, const Joint& j) {
  const ElementKind& k = kindOf(j);
  return m.contains(j.a) && (!k.reads(FieldType::Point, 1) || m.contains(j.b)) &&
         (!k.reads(FieldType::Slot) || m.contains(j.slot));
}

// Drawn as the block of a prismatic joint it is the point of.
bool slidesIn(const Mechanism& m, const Point& p) {
  return std::any_of(m.joints.begin(), m.joints.end(), [&](const Joint& j) {
    return kindOf(j).role == Role::Prismatic && j.a == p.id;
  });
}

// A slotted disk: every slot end at one distance from one of the body's points (the slots are
// chords of the disk) and the other points inside that circle.
bool discAbout(const Mechanism& m, const Body& b, Drawing::Body& d) {
  for (const Point& c : m.points) {
    if (c.body != b.id) continue;
    double rho = -1;
    bool round = true;
    for (const Slot& s : m.slots) {
      if (s.body != b.id) continue;
      for (const Vec2& e : {s.p0, s.p1}) {
        const double r = (e - c.pos).norm();
        if (rho < 0) rho = r;
        round = round && std::abs(r - rho) <= 1e-6 * rho;
      }
    }
    if (!round || !(rho > 0)) continue;
    for (const Point& p : m.points)
      if (p.body == b.id && (p.pos - c.pos).norm() > rho * (1 + 1e-9)) round = false;
    if (!round) continue;
    d.shape = Drawing::Shape::Disc;
    d.outline = {c.pos};
    d.radius = rho;
    return true;
  }
  return false;
}

Drawing::Body describeBody(const Mechanism& m, const Body& b, int number) {
  Drawing::Body d;
  d.id = b.id;
  d.number = number;
  d.name = b.name;
  std::vector<Vec2> geometry;
  const Point* only = nullptr;
  int points = 0, slots = 0;
  for (const Point& p : m.points)
    if (p.body == b.id) {
      geometry.push_back(p.pos);
      only = &p;
      ++points;
    }
  for (const Slot& s : m.slots)
    if (s.body == b.id) {
      geometry.push_back(s.p0);
      geometry.push_back(s.p1);
      if (s.mid) geometry.push_back(*s.mid);
      ++slots;
    }
  if (b.ground) {
    d.shape = Drawing::Shape::Ground;
    for (const Point& p : m.points)
      if (p.body == b.id) d.outline.push_back(p.pos);
    return d;
  }
  if (points == 1 && slots == 0) {
    d.shape = slidesIn(m, *only) ? Drawing::Shape::Block : Drawing::Shape::Dot;
    d.outline = {only->pos};
    return d;
  }
  if (slots > 0 && discAbout(m, b, d)) return d;
  d.outline = convexHull(geometry);
  if (d.outline.size() >= 3)
    d.shape = Drawing::Shape::Plate;
  else if (d.outline.size() == 2)
    d.shape = Drawing::Shape::Bar;
  else
    d.shape = Drawing::Shape::Dot;  // all its points in one place (or none)
  return d;
}

void extend(Drawing& d, const Vec2& p, bool& first) {
  if (!p.allFinite()) return;
  if (first) {
    d.min = d.max = p;
    first = false;
  }
  d.min = d.min.cwiseMin(p);
  d.max = d.max.cwiseMax(p);
}

Eigen::Vector3d homogeneous(const InstantCentres& ics, int i, int j) {
  const InstantCentre* c = ics.find(i, j);
  return c && c->determined ? c->h : Eigen::Vector3d::Zero();
}

// A centre or a Kennedy line's point (homogeneous: z 0 at infinity) from its class's frame
// into the view.
Eigen::Vector3d intoView(const PlaneView& view, const Eigen::Vector3d& h) {
  if (h.z() == 0) {
    const Vec2 d = view.directionFromClass(Vec2(h.x(), h.y()));
    return Eigen::Vector3d(d.x(), d.y(), 0);
  }
  const Vec2 p = view.fromClass(Vec2(h.x() / h.z(), h.y() / h.z()));
  return Eigen::Vector3d(p.x(), p.y(), 1);
}

// Seen on a plane, only the centres of its class, in its coordinates (those of other classes
// are in frames the view does not show; bodies of planes that are not parallel have none).
void keepViewed(Drawing& d, const PlaneView& view) {
  std::erase_if(d.centres, [&](const Drawing::Centre& c) {
    return c.across || c.planeClass != view.planeClass();
  });
  for (Drawing::Centre& c : d.centres) {
    if (c.determined) c.at = c.atInfinity ? view.directionFromClass(c.at) : view.fromClass(c.at);
    for (Drawing::KennedyLine& l : c.lines)
      for (Eigen::Vector3d& h : l.through) h = intoView(view, h);
  }
}

void placeCentres(Drawing& d, const Kinematics& k, const InstantCentres& ics) {
  const Mechanism& m = k.mechanism();
  // In space a joint's line is read from the mechanism as its class's frame sees it (made only
  // when a centre comes from a joint's line: a pin in a slot).
  std::vector<std::optional<Mechanism>> flat(ics.classes.frames.size());
  auto seenBy = [&](int cls) -> const Mechanism& {
    if (ics.classes.frames.size() < 2) return m;
    if (!flat[cls]) flat[cls] = flattenedTo(m, ics.classes, cls);
    return *flat[cls];
  };
  d.centres.resize(ics.centres.size());
  for (size_t n = 0; n < ics.centres.size(); ++n) {
    const InstantCentre& c = ics.centres[n];
    Drawing::Centre& out = d.centres[n];
    out.i = c.i;
    out.j = c.j;
    out.determined = c.determined;
    out.atInfinity = c.atInfinity();
    out.at = c.determined ? Vec2(c.h.x(), c.h.y()) : Vec2::Zero();
    out.status = c.status;
    out.across = c.across;
    out.planeClass = c.planeClass;
    out.lines.clear();
    const bool fromLines = c.status == CentreStatus::Kennedy ||
                           (c.status == CentreStatus::Primary && c.lines[0].joint);
    if (!c.determined || !fromLines) continue;
    for (const CentreLine& l : c.lines) {
      Drawing::KennedyLine line;
      line.k = l.k;
      if (l.k > 0) {
        line.through[0] = homogeneous(ics, c.i, l.k);
        line.through[1] = homogeneous(ics, l.k, c.j);
      } else if (const Joint* j = m.joint(l.joint)) {
        // A joint's own line (a pin in a slot: the normal to the slot through the pin).
        struct At : Pose {
          const Kinematics& k;
          explicit At(const Kinematics& kin) : k(kin) {}
          Vec2 point(PointId p) const override { return k.position(p); }
          Transform body(BodyId b) const override { return k.bodyTransform(b); }
        } pose(k);
        jointCentreLine(seenBy(c.planeClass), *j, pose, line.through);
      }
      out.lines.push_back(line);
    }
  }
}

// Puts every part where `at` says: at(PointId) a point's position, ends(SlotId) a slot's
// ends, pose(BodyId) a body's transform.
template <class At_, class Ends, class Pose_>
void place(Drawing& d, const Mechanism& m, At_ at, Ends ends, Pose_ pose, double crankDeg) {
  bool first = true;
  for (Drawing::Body& b : d.bodies) {
    b.pose = pose(b.id);
    for (const Vec2& p : b.outline) {
      extend(d, b.pose * p, first);
      if (b.radius > 0)
        for (const Vec2& e : {Vec2(1, 0), Vec2(0, 1)}) {
          extend(d, b.pose * p + b.radius * e, first);
          extend(d, b.pose * p - b.radius * e, first);
        }
    }
  }
  struct At : Pose {
    const At_& at_;
    const Pose_& pose_;
    At(const At_& a, const Pose_& p) : at_(a), pose_(p) {}
    Vec2 point(PointId p) const override { return at_(p); }
    Transform body(BodyId b) const override { return pose_(b); }
  } poseView(at, pose);
  for (size_t i = 0; i < d.joints.size(); ++i) {
    const Joint& j = m.joints[d.jointIndex[i]];
    kindOf(j).place(m, j, poseView, d.joints[i]);
    extend(d, d.joints[i].at, first);
    const Rot turn = Rot::of(d.joints[i].angle[0]);  // a cam's surface turns with the cam
    for (const Vec2& c : d.joints[i].curve) extend(d, d.joints[i].at + turn * c, first);
  }
  for (Drawing::Channel& c : d.channels) {
    std::tie(c.p0, c.p1) = ends(c.slot);
    extend(d, c.p0, first);
    extend(d, c.p1, first);
    if (!c.arc) continue;
    const Transform T = pose(c.body);
    const Slot* s = m.slot(c.slot);
    const std::optional<Guide> g = s ? guideOf(*s) : std::nullopt;
    if (!g) continue;
    c.centre = T * g->centre;
    c.radius = g->radius;
    c.a0 = g->a0 + T.R.angle();
    c.sweep = g->sweep;
    extend(d,
           c.centre + c.radius * Vec2(std::cos(c.a0 + c.sweep / 2), std::sin(c.a0 + c.sweep / 2)),
           first);
  }
  for (Drawing::Driver& r : d.drivers) {
    r.at = at(m.joint(r.joint)->a);
    r.crankDeg = crankDeg;
  }
  for (Drawing::Output& o : d.outputs) o.at = at(o.point);
}

// The shapes and parts of a mechanism, not yet placed.
Drawing describeShapes(const Mechanism& m) {
  Drawing d;
  std::vector<BodyId> order;
  std::vector<int> numbers;
  const bool numbered = textbookNumbers(m, order, numbers).ok();
  auto numberOf = [&](BodyId id) {
    for (size_t t = 0; numbered && t < order.size(); ++t)
      if (order[t] == id) return numbers[t];
    return 0;
  };
  if (const Body* g = m.ground()) d.bodies.push_back(describeBody(m, *g, 1));
  for (const Body& b : m.bodies)
    if (!b.ground) d.bodies.push_back(describeBody(m, b, numberOf(b.id)));
  for (size_t i = 0; i < m.joints.size(); ++i) {
    const Joint& j = m.joints[i];
    if (!resolves(m, j)) continue;
    JointSymbol sym;
    sym.joint = j.id;
    sym.type = j.type;
    kindOf(j).symbol(m, j, sym);
    d.joints.push_back(sym);
    d.jointIndex.push_back(static_cast<int>(i));
    if (m.driver && m.driver->joint == j.id) {
      Drawing::Driver r;
      r.joint = j.id;
      r.crank = sym.bodies[1];
      r.ccw = m.driver->direction == Direction::Ccw;
      d.drivers.push_back(r);
    }
  }
  for (const Slot& s : m.slots) {
    Drawing::Channel c;
    c.slot = s.id;
    c.body = s.body;
    c.arc = s.arc() && guideOf(s).has_value();
    d.channels.push_back(c);
  }
  for (PointId p : m.outputs)
    if (m.contains(p)) d.outputs.push_back(Drawing::Output{p, m.pointLabel(p)});
  return d;
}

}  // namespace

bool updateDrawing(Drawing& d, const Kinematics& k, const InstantCentres* ics,
                   const PlaneView* view) {
  if (!k.valid() || k.revision() != d.revision) return false;
  static const PlaneView none;
  const PlaneView& v = view ? *view : none;
  place(
      d, v.seen(k.mechanism()), [&](PointId p) { return v.point(k, p); },
      [&](SlotId s) {
        const Kinematics::Segment e = v.slotEnds(k, s);
        return std::make_pair(e.p0, e.p1);
      },
      [&](BodyId b) { return v.pose(k, b); }, k.crankDeg());
  if (ics && ics->status.ok()) {
    placeCentres(d, k, *ics);
    if (!v.mapsNothing()) keepViewed(d, v);
  } else {
    d.centres.clear();
  }
  return true;
}

Drawing describeSketch(const Mechanism& design, const PlaneView* view) {
  static const PlaneView none;
  const PlaneView& v = view ? *view : none;
  const Mechanism& m = v.seen(design);
  Drawing d = describeShapes(m);
  place(
      d, m, [&](PointId p) { return v.sketchPoint(design, p); },
      [&](SlotId s) {
        const Slot* q = m.slot(s);
        if (!q) return std::make_pair(Vec2(NAN, NAN), Vec2(NAN, NAN));
        const Transform T = v.sketchPose(q->body);
        return std::make_pair(T * q->p0, T * q->p1);
      },
      [&](BodyId b) { return v.sketchPose(b); }, 0.0);
  return d;
}

Drawing describeDrawing(const Kinematics& k, const InstantCentres* ics, const PlaneView* view) {
  if (!k.valid()) return Drawing{};
  static const PlaneView none;
  Drawing d = describeShapes((view ? *view : none).seen(k.mechanism()));
  d.revision = k.revision();
  updateDrawing(d, k, ics, view);
  return d;
}

}  // namespace linkage
