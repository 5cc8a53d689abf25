// Gear and belt coupling: the body of b turns relative to the carrier `ratio` times as fast as
// the body of a does, both angles counted from the drawing:
//
//   theta_b - theta_c = ratio (theta_a - theta_c)         (c: the carrier; none: the ground)
//
//   file:     {"type": "gear", "a": "armshaft.U", "b": "hook.L", "ratio": 2, "carrier": "arm"}
//   rows:     Angles(theta_b - ratio theta_a + (ratio - 1) theta_c = 0)   1 equation, 3 bodies
//   checks:   ratio finite, non-zero and within 1e-6 to 1e6 in size; a and b on two bodies, neither
//             the carrier; each of a and b where its body is pinned to the carrier (a pin joins
//             that body to the carrier at that point).
//   in space: between bodies of planes that are not parallel (linkage/space.h) it is a bevel
//             pair: the same row, the carrier the ground (each angle about its own plane's
//             normal, as the file format counts it); the axes need not meet.
//   centre:   on the line of the centres A, B where the two bodies' velocities are equal:
//             (A - ratio B) / (1 - ratio): the pitch point of a gear pair (ratio < 0, between
//             the centres), outside them for a belt or an internal pair (ratio > 0), at
//             infinity for ratio 1 (the bodies translate relative to each other).
//   drawn:    ratio < 0, an external pair: pitch circles touching at the pitch point, radii
//             |ratio| d / (1 + |ratio|) about A and d / (1 + |ratio|) about B (d = |AB|);
//             ratio > 0: two pulleys with radii in the ratio, the larger d / 6, and the belt.
#include "elements/gear.h"

#include <cmath>
#include <vector>

#include "elements/dual.h"
#include "elements/frames.h"
#include "elements/rows.h"
#include "linkage/gear.h"
#include "linkage/space.h"

namespace linkage {

namespace {

constexpr const char* kForceColumns[] = {"fx_N", "fy_N"};

constexpr FieldSpec kFields[] = {{"a", FieldType::Point, 0, true},
                                 {"b", FieldType::Point, 1, true},
                                 {"ratio", FieldType::Number, 0, true},
                                 {"carrier", FieldType::Body, 0, false}};

BodyId carrierOf(const Mechanism& m, const Joint& j) {
  if (j.carrier) return j.carrier;
  const Body* g = m.ground();
  return g ? g->id : BodyId{};
}

// Is p (on its body) where that body is pinned to `carrier`: a revolute joint between the two
// bodies whose point on p's body is p, or at p's place.
bool pinnedThere(const Mechanism& m, const Point& p, BodyId carrier) {
  const double tol = 1e-9 * std::max(1.0, p.pos.cwiseAbs().maxCoeff());
  for (const Joint& k : m.joints) {
    if (kindOf(k).role != Role::Revolute) continue;
    const Point *x = m.point(k.a), *y = m.point(k.b);
    if (!x || !y) continue;
    for (const auto& [on, other] : {std::pair{x, y}, std::pair{y, x}})
      if (on->body == p.body && other->body == carrier &&
          (on->id == p.id || (on->pos - p.pos).norm() <= tol))
        return true;
  }
  return false;
}

// Appended in steps: "\"" + s trips GCC 12's -Wrestrict (a false alarm, its bug 105329).
std::string quoted(const std::string& s) {
  std::string q = "\"";
  q += s;
  q += '"';
  return q;
}

std::string check(const Mechanism& m, const Joint& j, const char*& where) {
  where = "ratio";
  const double ratio = gearRatio(j);
  if (!std::isfinite(ratio) || ratio == 0)
    return "expected a finite number other than 0 (the speed of b relative to a)";
  if (std::abs(ratio) > 1e6 || std::abs(ratio) < 1e-6)
    return "a ratio beyond 1e6 (or below 1e-6) in size is no gear: the equations would drown "
           "in rounding";
  const Point *a = m.point(j.a), *b = m.point(j.b);
  const BodyId c = carrierOf(m, j);
  const Body* cb = m.body(c);
  const std::string carrier = cb ? quoted(cb->name) : "(none)";
  where = "b";
  if (a->body == b->body) return "a and b are on one body: a gear couples two bodies";
  // Across planes that are not parallel it is a bevel pair: theta_b = ratio theta_a about the
  // ground; a moving carrier of planes at an angle is no gear train this program knows.
  const Plane &pa = planeOf(m, a->body), &pb = planeOf(m, b->body);
  if (j.carrier && (!parallel(pa, pb) || !parallel(pa, planeOf(m, j.carrier)))) {
    where = "carrier";
    return "a bevel pair (bodies of planes that are not parallel) turns about the ground only, "
           "and a carrier joins bodies of its own plane";
  }
  for (const auto& [p, field] : {std::pair{a, "a"}, std::pair{b, "b"}}) {
    where = field;
    if (p->body == c)
      return quoted(m.pointLabel(p->id)) + " is on the carrier " + carrier +
             " itself: a gear turns relative to its carrier";
    if (!pinnedThere(m, *p, c)) {
      const Body* pb = m.body(p->body);
      return quoted(m.pointLabel(p->id)) + " is not where body " + quoted(pb ? pb->name : "?") +
             " is pinned to the carrier " + carrier +
             ": a gear's centres are its bodies' pivots on the carrier";
    }
  }
  return {};
}

bool compile(const Mechanism& m, const Joint& j, const Frames& f, std::vector<Row>& rows,
             std::string& why) {
  const int c = f.body(carrierOf(m, j));
  if (c < -1) {
    why = "unknown carrier";
    return false;
  }
  Row r;
  r.kind = Primitive::Angles;
  r.body[0] = f.point(j.b)->body;
  r.body[1] = f.point(j.a)->body;
  r.body[2] = c;
  r.c[0] = 1;
  r.c[1] = -gearRatio(j);
  r.c[2] = gearRatio(j) - 1;
  rows.push_back(r);
  return true;
}

CentreData centre(const Mechanism& m, const Joint& j) {
  const Point *a = m.point(j.a), *b = m.point(j.b);
  CentreData c;
  c.rule = CentreRule::Weighted;
  c.bodies[0] = c.pBody[0] = a->body;
  c.bodies[1] = c.pBody[1] = b->body;
  c.p[0] = a->pos;
  c.p[1] = b->pos;
  c.ratio = gearRatio(j);
  return c;
}

void symbol(const Mechanism& m, const Joint& j, JointSymbol& s) {
  const Point *a = m.point(j.a), *b = m.point(j.b);
  s.bodies[0] = a ? a->body : BodyId{};
  s.bodies[1] = b ? b->body : BodyId{};
  s.carrier = carrierOf(m, j);
  if (!a || !b) return;
  const double d = (a->pos - b->pos).norm(), r = std::abs(gearRatio(j));
  if (d > 0) s.direction = (b->pos - a->pos) / d;
  s.belt = gearRatio(j) > 0;
  if (!s.belt) {
    s.radius[0] = r * d / (1 + r);
    s.radius[1] = d / (1 + r);
  } else {
    // Pulleys turn in the ratio of their radii: |ratio| = radius at a / radius at b; the
    // larger a sixth of the centre distance, clear of the cranks on the shafts.
    s.radius[0] = r >= 1 ? d / 6 : r * d / 6;
    s.radius[1] = r >= 1 ? d / (6 * r) : d / 6;
  }
}

void place(const Mechanism&, const Joint& j, const Pose& pose, JointSymbol& s) {
  s.at = pose.point(j.a);
  s.at2 = pose.point(j.b);
  for (int k = 0; k < 2; ++k) s.angle[k] = pose.body(s.bodies[k]).R.angle();
}

// The pin joining p's body to the carrier at p (see pinnedThere), or -1.
int pivotIndex(const Mechanism& m, const Point& p, BodyId carrier) {
  for (size_t i = 0; i < m.joints.size(); ++i) {
    const Joint& k = m.joints[i];
    if (kindOf(k).role != Role::Revolute) continue;
    const Point *x = m.point(k.a), *y = m.point(k.b);
    if (x && y &&
        ((x->body == p.body && y->body == carrier) || (y->body == p.body && x->body == carrier)))
      return static_cast<int>(i);
  }
  return -1;
}

// Its rows apply couples to the bodies of a, b and the carrier. A gear pair does it as the tooth
// force F at the pitch point (normal to the line of centres, its moment about a's centre the
// couple on a's body), -F on b's body there; a belt as the pull of a run, F along the run where
// it leaves a's pulley, -F where it meets b's (the drawn pulleys, radii in the ratio, the run
// their outer tangent; the pretension, which pulls the shafts together, is not in the model).
// Either way the shafts' pins carry what F pushes them by; the carrier then takes the pins' forces
// only. Written over T = double (react) and T = Dual (reactChange: its derivative).
template <class T>
struct Tooth {
  T at[2], force[2];
};

// F and where it acts, from the centres A and B at the pose, the couple M (N mm, on a's body
// about A), the ratio and the drawn centres' distance (the pulleys' size); false when A and B
// meet (coaxial: a couple is all there is).
template <class T>
bool tooth(const T A[2], const T B[2], T M, T ratio, T drawn, Tooth<T>& out) {
  using std::sqrt;
  const T ux0 = B[0] - A[0], uy0 = B[1] - A[1];
  const T d = sqrt(ux0 * ux0 + uy0 * uy0);
  if (!(value(d) > 0)) return false;
  const T u[2] = {ux0 / d, uy0 / d}, pu[2] = {-u[1], u[0]};
  const T r = value(ratio) < 0 ? -ratio : ratio;
  if (value(ratio) < 0) {
    const T toPitch = r * d / (T(1) + r);
    for (int i = 0; i < 2; ++i) out.at[i] = A[i] + toPitch * u[i];
    for (int i = 0; i < 2; ++i) out.force[i] = M / toPitch * pu[i];
    return true;
  }
  // The pulleys as symbol() draws them; the run tangent to both on the same side, n its normal
  // from the centres.
  const T r0 = value(r) >= 1 ? drawn / T(6) : r * drawn / T(6);
  const T r1 = value(r) >= 1 ? drawn / (T(6) * r) : drawn / T(6);
  const T along = (r0 - r1) / d, across = sqrt(T(1) - along * along);
  const T n[2] = {along * u[0] - across * pu[0], along * u[1] - across * pu[1]};
  for (int i = 0; i < 2; ++i) out.at[i] = A[i] + r0 * n[i];
  T run[2] = {B[0] + r1 * n[0] - out.at[0], B[1] + r1 * n[1] - out.at[1]};
  const T len = sqrt(run[0] * run[0] + run[1] * run[1]);
  for (T& x : run) x = x / len;
  const T arm = (out.at[0] - A[0]) * run[1] - (out.at[1] - A[1]) * run[0];  // cross(at - A, run)
  for (int i = 0; i < 2; ++i) out.force[i] = M / arm * run[i];
  return true;
}

// The pins that carry F: (joint index, the sign of F on the body of the pin's point a).
std::vector<std::pair<int, double>> pivots(const Mechanism& m, const Joint& j) {
  std::vector<std::pair<int, double>> out;
  const BodyId c = carrierOf(m, j);
  for (const auto& [p, sign] : {std::pair{m.point(j.a), 1.0}, std::pair{m.point(j.b), -1.0}}) {
    const int pin = pivotIndex(m, *p, c);
    if (pin < 0) continue;
    // The force on p's body from its pin changes by -(the coupling's force on that body).
    const bool onGearSide = m.point(m.joints[pin].a)->body == p->body;
    out.emplace_back(pin, -(onGearSide ? 1.0 : -1.0) * sign);
  }
  return out;
}

// A bevel pair transmits the couple about each axis and no more is computed: its tooth force's
// other components (radial, axial) are not in the model (docs/dynamics.md).
bool bevel(const Mechanism& m, const Joint& j) {
  return !parallel(planeOf(m, m.point(j.a)->body), planeOf(m, m.point(j.b)->body));
}

double drawnDistance(const Mechanism& m, const Joint& j) {
  return (m.point(j.b)->pos - m.point(j.a)->pos).norm();
}

void react(const Mechanism& m, int index, const Pose& pose, std::vector<JointReaction>& all) {
  const Joint& j = m.joints[index];
  JointReaction& r = all[index];
  if (bevel(m, j)) return;
  const Vec2 a = pose.point(j.a), b = pose.point(j.b);
  const double A[2] = {a.x(), a.y()}, B[2] = {b.x(), b.y()};
  Tooth<double> t;
  if (!tooth<double>(A, B, r.coupleNm * 1000, gearRatio(j), drawnDistance(m, j), t)) return;
  r.at = Vec2(t.at[0], t.at[1]);
  r.force = Vec2(t.force[0], t.force[1]);
  r.coupleNm = 0;
  for (const auto& [pin, sign] : pivots(m, j)) all[pin].force += sign * r.force;
}

void reactChange(const Mechanism& m, int index, const Pose& pose, const PoseChange& dpose,
                 std::vector<JointReaction>& all, std::vector<JointReaction>& change) {
  const Joint& j = m.joints[index];
  JointReaction &r = all[index], &dr = change[index];
  if (bevel(m, j)) return;
  const Vec2 a = pose.point(j.a), b = pose.point(j.b), da = dpose.point(j.a), db = dpose.point(j.b);
  const Dual A[2] = {{a.x(), da.x()}, {a.y(), da.y()}}, B[2] = {{b.x(), db.x()}, {b.y(), db.y()}};
  const Vec2 drawn = m.point(j.b)->pos - m.point(j.a)->pos;
  const double dDrawn =
      drawn.norm() > 0 ? drawn.normalized().dot(dpose.drawn(j.b) - dpose.drawn(j.a)) : 0.0;
  Tooth<Dual> t;
  if (!tooth<Dual>(A, B, Dual(r.coupleNm, dr.coupleNm) * Dual(1000),
                   Dual(gearRatio(j), dpose.ratio(j.id)), Dual(drawn.norm(), dDrawn), t))
    return;
  r.at = Vec2(t.at[0].v, t.at[1].v);
  dr.at = Vec2(t.at[0].d, t.at[1].d);
  r.force = Vec2(t.force[0].v, t.force[1].v);
  dr.force = Vec2(t.force[0].d, t.force[1].d);
  r.coupleNm = dr.coupleNm = 0;
  for (const auto& [pin, sign] : pivots(m, j)) {
    all[pin].force += sign * r.force;
    change[pin].force += sign * dr.force;
  }
}

}  // namespace

ElementKind gearElement(JointType t) {
  return {t,
          "gear",
          "couples the bodies of points \"a\" and \"b\"",
          Role::Coupling,
          1,
          kFields,
          check,
          compile,
          centre,
          symbol,
          place,
          kForceColumns,
          react,
          true,
          nullptr,
          reactChange};
}

}  // namespace linkage
