// dq/dp = -J_q^-1 J_p at a pose (linkage/sensitivity.h). J_p, row by row: a row's residual
// depends on a dimension only through its constants (the local vectors s of its points, a slot's
// point u and normal n, a gear's coefficients), whose changes come from how the element kind
// compiled them (elements/*.cpp; rowMove) and the dimension's move of the drawing; with the
// frames held a sketch move is the same move of the local vector (frames are at angle 0 as
// drawn). Then the velocities': J q' + Phi_phi = 0 at every p, so J dq'/dp = -dV, dV the change
// of each row's rate V = J q' (q' held) along dq/dp and the constants' change (rowChange):
//
//   Coincident  Phi = p - q                  V = p' - q'           (p = r_i + R_i s_i, ...)
//   OnLine      Phi = n . (p - q)            V = n' . (p - q) + n . (p' - q')
//   OnCircle    Phi = (d . d - rho^2)/(2 rho) V = d . d' / rho      (an arc's centre and radius
//                                                                   from its three points' moves)
//   Angles      Phi = L (sum c_k theta_k ...) V = L (sum c_k w_k ...) (a gear's ratio: dc)
//   Distance3   Phi = (D . D - l^2)/(2 l)    V = D . D' / l        (a ball rod, D in the world:
//                                                                   its ends' depths, dl)
//   Cam         Phi = u . (p - q) - s(theta) V = u' . (p - q) + u . (p' - q') - s' theta'
//               (translating; q the lowest position of b, u the rise direction, in the guide)
//               Phi = L (sign (phi - phi0) - s(theta))   V = L (sign phi' - s' theta')
//               (oscillating; phi0 its turn to the lowest position, 0 as drawn)
//               s linear in the rises (cam::Program::perRise); q, u and phi0 move with the cam's
//               centre (the guide's pin at a), the slot, b, the block's point or the pivot's two
//               points and the base as the drawing's rules place the lowest position (camMove)
//
// each changed to first order by the bodies' changes (dr, dtheta) and the constants' (ds, dn, dc).
// In space each row is in its plane class's frame (analysis/sensitivity_space.h turns the
// drawing's moves into it); a ball rod's ends are lifted to the world (elements/distance3.h).
#include <Eigen/LU>
#include <cmath>

#include "analysis/sensitivity_space.h"
#include "elements/cam_row.h"
#include "kinematics/kinematics_state.h"
#include "linkage/cam_joint.h"
#include "linkage/elements.h"
#include "linkage/guide.h"
#include "linkage/sensitivity.h"
#include "system/system.h"

namespace linkage {

namespace {

struct Moves {  // one dimension's move of the drawing, by id value (Sensitivity::pointMove_)
  const std::vector<Vec3>& point;
  const Dimension& dim;
  const internal::SpaceMoves& space;
  const std::vector<internal::CamMove>* cams = nullptr;  // by joint index
  Vec3 kept(PointId p) const { return p.value < point.size() ? point[p.value] : Vec3::Zero(); }
  // In class cls's frame, and along its normal.
  Vec2 at(PointId p, int cls) const { return space.inClass(p, kept(p), cls); }
  double depth(PointId p, int cls) const { return space.depthIn(p, kept(p), cls); }
};

// The block's point of a slider in an arc slot is compiled as the point at the arc's centre,
// C' = p - rho (p - c) / |p - c|: its move for a move dp of p and dc, drho of the arc.
Vec2 arcBlockMove(const Mechanism& m, const Joint& j, const Moves& mv, int cls, const Vec2& dc,
                  double drho) {
  const Vec2 dp = mv.at(j.a, cls) - dc;
  const std::optional<Guide> g = guideOf(mv.space.slot(*m.slot(j.slot), cls));
  const Vec2 d = mv.space.drawn(*m.point(j.a), cls) - g->centre;
  const Vec2 u = d.normalized();
  return dp + dc - g->radius / d.norm() * (dp - u * u.dot(dp)) - drho * u;
}

// A straight slot's point u (its first end) and unit normal n as they move.
void slotMove(const Mechanism& m, const Joint& j, const Moves& mv, int cls, Vec2& du, Vec2& dn) {
  du = dn = Vec2::Zero();
  for (const Dimension::SlotMove& s : mv.dim.slots) {
    if (s.slot != j.slot) continue;
    const Slot slot = mv.space.slot(*m.slot(j.slot), cls);
    Vec2 d0, d1;
    mv.space.slotMove(*m.slot(j.slot), s, cls, d0, d1);
    const Vec2 t = slot.p1 - slot.p0;
    const double len = t.norm();
    const Vec2 e = t / len, dt = d1 - d0;
    du = d0;
    dn = perp((dt - e * e.dot(dt)) / len);
  }
}

// A row's constants as they move with a dimension: its local vectors s, a straight slot's
// normal n, its coefficients c; a ball rod's ends' depths and its length.
struct RowMove {
  Vec2 s[2] = {Vec2::Zero(), Vec2::Zero()};
  Vec2 n = Vec2::Zero();
  double c[3] = {0, 0, 0};
  double depth[2] = {0, 0}, l = 0;
  double rho = 0;                              // an arc slot's radius
  double turn = 0;                             // a cam's phi0
  const std::vector<double>* rises = nullptr;  // a cam's d(rises)
};

RowMove rowMove(const Mechanism& m, const Joint& j, const Row& r, const Moves& mv) {
  RowMove out;
  const Role role = kindOf(j).role;
  const int cls = mv.space.rowClass(r);
  switch (r.kind) {
    case Primitive::Coincident:
      if (role == Role::Prismatic) {  // a block in an arc: its point at the centre, the centre
        mv.space.arcMove(*m.slot(j.slot), mv.dim, cls, out.s[1], out.rho);
        out.s[0] = arcBlockMove(m, j, mv, cls, out.s[1], out.rho);
      } else {
        out.s[0] = mv.at(j.a, cls);
        out.s[1] = mv.at(j.b, cls);
      }
      break;
    case Primitive::OnLine:
      out.s[0] = mv.at(j.a, cls);
      slotMove(m, j, mv, cls, out.s[1], out.n);
      break;
    case Primitive::OnCircle:  // a pin in an arc: the centre and the radius
      out.s[0] = mv.at(j.a, cls);
      mv.space.arcMove(*m.slot(j.slot), mv.dim, cls, out.s[1], out.rho);
      break;
    case Primitive::Distance3:  // each end in its own class (elements/ball_rod.cpp)
      for (int e = 0; e < 2; ++e) {
        out.s[e] = mv.at(e ? j.b : j.a, r.frame[e]);
        out.depth[e] = mv.depth(e ? j.b : j.a, r.frame[e]);
      }
      out.l = mv.dim.lengthOf == j.id ? 1 : 0;
      break;
    case Primitive::Cam: {  // b, the lowest position and u (cam.cpp's compile), phi0
      const internal::CamMove& c = (*mv.cams)[r.joint];
      out.s[0] = c.b;
      out.s[1] = c.lowest;
      out.n = c.along;
      out.turn = c.turn;
      if (mv.dim.camOf == j.id) out.rises = &mv.dim.camRises;
      break;
    }
    case Primitive::Angles:
      // theta_b - ratio theta_a + (ratio - 1) theta_c: dc = (0, -1, 1) per unit ratio.
      if (!r.isDriver() && role == Role::Coupling && mv.dim.ratioOf == j.id) {
        out.c[1] = -1;
        out.c[2] = 1;
      }
      break;
    default:
      break;
  }
  return out;
}

// A body's pose, rates (d/dphi) and second rates, with first-order changes of the pose and the
// rates (zero for the ground; the second rates held): a point s of it (its position, rate and
// second rate) and their changes for a change ds of s.
struct Moving {
  const BodyView& b;
  Vec2 acc = Vec2::Zero();  // its frame origin's second rate, and its angle's
  double alpha = 0;
  Vec2 dr = Vec2::Zero(), dv = Vec2::Zero();
  double dtheta = 0, dw = 0;
  struct At {
    Vec2 p, dp, v, dv, a, da;
  };
  At at(const Vec2& s, const Vec2& ds) const {
    const Vec2 a = b.R * s, da = perp(a) * dtheta + b.R * ds;
    const double w = b.w;
    return {b.r + a,
            dr + da,
            b.v + w * perp(a),
            dv + dw * perp(a) + w * perp(da),
            acc + alpha * perp(a) - w * w * a,
            alpha * perp(da) - 2 * w * dw * a - w * w * da};
  }
};

// A row's residual and its first and second rates along the motion (Phi, V = J q' + Phi_phi,
// A = J q'' - gamma), changed to first order by the bodies' changes and the constants' (the
// second rates held): dPhi with no body change is J_p; dV with dq/dp (the rates held) the
// velocities' right-hand side; dA with dq/dp and dq'/dp the accelerations'.
struct RowChange {
  double phi[2] = {0, 0}, v[2] = {0, 0}, a[2] = {0, 0};
};

// n0 the line's normal in j's frame (a cam's rise direction), dn0 its move.
double lineChange(const Vec2& n0, const Vec2& dn0, const Moving::At& p, const Moving::At& q,
                  const Moving& j, int order) {
  const Vec2 d = p.p - q.p, dd = p.dp - q.dp, v = p.v - q.v, dv = p.dv - q.dv;
  const double w = j.b.w;
  const Vec2 n = j.b.R * n0, dn = perp(n) * j.dtheta + j.b.R * dn0;
  if (order == 0) return dn.dot(d) + n.dot(dd);
  const Vec2 n1 = w * perp(n), dn1 = j.dw * perp(n) + w * perp(dn);
  if (order == 1) return dn1.dot(d) + n1.dot(dd) + dn.dot(v) + n.dot(dv);
  const Vec2 a = p.a - q.a, da = p.da - q.da;
  const Vec2 n2 = j.alpha * perp(n) - w * w * n;
  const Vec2 dn2 = j.alpha * perp(dn) - 2 * w * j.dw * n - w * w * dn;
  return dn2.dot(d) + n2.dot(dd) + 2 * (dn1.dot(v) + n1.dot(dv)) + dn.dot(a) + n.dot(da);
}

// A ball rod's row: D = W_i - W_j in the world, each end lifted from its class frame; at the
// pose Phi = V = A = 0, so dPhi = D . dD / l - dl, dV = (dD . D' + D . dD') / l - (D . D') dl / l
// and dA = (2 D' . dD' + dD . D'' + D . dD'') / l.
void distance3Change(const System& sys, const Row& r, const Moving::At& p, const Moving::At& q,
                     const RowMove& mv, RowChange& out) {
  const Plane &fi = sys.frames[r.frame[0]], &fj = sys.frames[r.frame[1]];
  auto lift = [](const Plane& f, const Vec2& v) -> Vec3 {
    return v.x() * f.xAxis + v.y() * f.yAxis;
  };
  const Vec3 D = fi.origin + lift(fi, p.p) + r.depth[0] * fi.normal() - fj.origin - lift(fj, q.p) -
                 r.depth[1] * fj.normal();
  const Vec3 dD =
      lift(fi, p.dp) + mv.depth[0] * fi.normal() - lift(fj, q.dp) - mv.depth[1] * fj.normal();
  const Vec3 v = lift(fi, p.v) - lift(fj, q.v), dv = lift(fi, p.dv) - lift(fj, q.dv);
  const Vec3 a = lift(fi, p.a) - lift(fj, q.a), da = lift(fi, p.da) - lift(fj, q.da);
  const double l = r.c[0];
  out.phi[0] = D.dot(dD) / l - mv.l;
  // (D . v = 0 for the motion's own rates; not for any w a multiplier's derivative holds.)
  out.v[0] = (dD.dot(v) + D.dot(dv)) / l - D.dot(v) * mv.l / (l * l);
  out.a[0] = (2 * v.dot(dv) + dD.dot(a) + D.dot(da)) / l;
}

// A cam's row (cam_row.h) for follower i, cam c and guide g: the law's s, s', s'' change with
// theta (by dtheta = dtheta_c - dtheta_g) and the rises (perRise); the second rates held.
void camChange(const System& sys, const Row& r, const Moving& i, const Moving& c, const Moving& g,
               const RowMove& mv, RowChange& out) {
  const CamRow& k = *r.cam;
  const double theta = cam_row::theta(c.b, g.b);
  const cam::Displacement s = k.program.at(theta);
  const cam::Displacement h = mv.rises ? k.program.perRise(theta, *mv.rises) : cam::Displacement{};
  const double w = c.b.w - g.b.w, dw = c.dw - g.dw, alpha = c.alpha - g.alpha;
  const double dtheta = c.dtheta - g.dtheta;
  const double ds = h.s + s.v * dtheta, dv = h.v + s.a * dtheta, da = h.a + s.j * dtheta;
  const double law[3] = {ds, dv * w + s.v * dw, da * w * w + 2 * s.a * w * dw + dv * alpha};
  if (k.kind.oscillating) {
    const double L = sys.size, sign = k.kind.sign;
    out.phi[0] = L * (sign * (i.dtheta - g.dtheta - mv.turn) - law[0]);
    out.v[0] = L * (sign * (i.dw - g.dw) - law[1]);
    out.a[0] = -L * law[2];
    return;
  }
  const Moving::At p = i.at(r.s[0], mv.s[0]), q = g.at(r.s[1], mv.s[1]);
  for (int o = 0; o < 3; ++o)
    (o == 0 ? out.phi : o == 1 ? out.v : out.a)[0] = lineChange(k.along, mv.n, p, q, g, o) - law[o];
}

RowChange rowChange(const System& sys, const Row& r, const Moving& i, const Moving& j,
                    const Moving& k, const RowMove& mv) {
  RowChange out;
  if (r.kind == Primitive::Cam) {
    camChange(sys, r, i, j, k, mv, out);
    return out;
  }
  const Moving::At p = i.at(r.s[0], mv.s[0]), q = j.at(r.s[1], mv.s[1]);
  const Vec2 d = p.p - q.p, dd = p.dp - q.dp, v = p.v - q.v, dv = p.dv - q.dv;
  const Vec2 a = p.a - q.a, da = p.da - q.da;
  switch (r.kind) {
    case Primitive::Coincident:
      for (int e = 0; e < 2; ++e) out.phi[e] = dd[e], out.v[e] = dv[e], out.a[e] = da[e];
      break;
    case Primitive::OnLine:
      for (int o = 0; o < 3; ++o)
        (o == 0 ? out.phi : o == 1 ? out.v : out.a)[0] = lineChange(r.n, mv.n, p, q, j, o);
      break;
    case Primitive::OnCircle:  // Phi'' = (d' . d' + d . d'') / rho; V = A = 0 at the pose
      out.phi[0] = d.dot(dd) / r.c[0] - mv.rho;
      out.v[0] = (dd.dot(v) + d.dot(dv)) / r.c[0];
      out.a[0] = (2 * v.dot(dv) + dd.dot(a) + d.dot(da)) / r.c[0];
      break;
    case Primitive::Angles: {
      const Moving* m[3] = {&i, &j, &k};  // the ground's angle and rates are 0
      for (int c = 0; c < 3; ++c) {
        out.phi[0] += sys.size * (r.c[c] * m[c]->dtheta + mv.c[c] * m[c]->b.theta);
        out.v[0] += sys.size * (r.c[c] * m[c]->dw + mv.c[c] * m[c]->b.w);
        out.a[0] += sys.size * mv.c[c] * m[c]->alpha;
      }
      break;
    }
    case Primitive::Distance3:
      distance3Change(sys, r, p, q, mv, out);
      break;
    default:
      break;
  }
  return out;
}

// The rows' changes (rowChange) for one dimension, into the independent rows' places (`map`):
// `order` 0 (dPhi, no body change: J_p), 1 (dV, the pose's change dq) or 2 (dA, dq and dq').
void rowChanges(const Mechanism& m, const System& sys, const std::vector<BodyView>& views,
                const Eigen::VectorXd& ddq, const Moves& mv, int order, const Eigen::VectorXd& dq,
                const Eigen::VectorXd& dqd, const std::vector<int>& map,
                Eigen::Ref<Eigen::VectorXd> out) {
  std::vector<Moving> moving;
  moving.reserve(views.size());
  for (size_t b = 0; b < views.size(); ++b) {
    Moving x{views[b]};
    const int c = 3 * (static_cast<int>(b) - 1);
    if (b > 0 && ddq.size()) x.acc = ddq.segment<2>(c), x.alpha = ddq[c + 2];
    if (b > 0 && order >= 1) x.dr = dq.segment<2>(c), x.dtheta = dq[c + 2];
    if (b > 0 && order >= 2) x.dv = dqd.segment<2>(c), x.dw = dqd[c + 2];
    moving.push_back(x);
  }
  out.setZero();
  for (const Row& r : sys.cons) {
    if (r.kind == Primitive::Hold) continue;
    const RowChange ch = rowChange(sys, r, moving[r.body[0] + 1], moving[r.body[1] + 1],
                                   moving[r.body[2] + 1], rowMove(m, m.joints[r.joint], r, mv));
    const double* x = order == 0 ? ch.phi : order == 1 ? ch.v : ch.a;
    for (int e = 0; e < r.rows(); ++e)
      if (map[r.row + e] >= 0) out[map[r.row + e]] = x[e];
  }
}

bool isCam(const Joint& j) {
  return std::string_view(kindOf(j).name) == "cam";
}

// The point of the guide the cam's body is pinned to at a (its centre as the guide sees it;
// cam.cpp's pinnedAt), or none.
PointId guidePin(const Mechanism& m, const CamJoint& c, const Point& a) {
  for (const Joint& k : m.joints) {
    if (kindOf(k).role != Role::Revolute) continue;
    const Point *x = m.point(k.a), *y = m.point(k.b);
    if (!x || !y) continue;
    for (const auto& [on, other] : {std::pair{x, y}, std::pair{y, x}})
      if (on->body == c.cam && other->body == c.guide && (on->id == a.id || on->pos == a.pos))
        return other->id;
  }
  return {};
}

// A cam whose rows' constants are not derived here, named; "" when they are.
std::string camRefused(const Mechanism& m, const System& sys, const Joint& j) {
  const std::string name = "sensitivities through a cam (" + jointLabel(m, j.id) + ") ";
  if (sys.frames.size() > 1) return name + "on a machine in space are not computed yet";
  const std::optional<CamJoint> c = camJoint(m, j);
  if (!c) return name + "not sound are not computed";
  if (!guidePin(m, *c, *m.point(j.a))) return name + "pinned off its centre are not computed yet";
  const Joint* f = m.joint(c->followerJoint);
  if (!c->kind.oscillating && m.point(f->a)->body != c->follower)
    return name + "whose follower carries the slot are not computed yet";
  return "";
}

// A cam row's constants' moves for one dimension (internal::CamMove): the lowest position as
// the drawing's rules place it (cam.cpp's lowest, setCamBase's move) with the cam's centre a
// (the guide's pin), b, the follower's slot or pivot and the base moved. Translating: b runs on
// the line c + t u (c its drawn place, the slot's line carried by the block's point to b) and
// lies at base + roller from a (a flat face: at base along u); oscillating: b turned about the
// pivot by phi0 lies at base + roller (a flat face: base) from a. To first order.
internal::CamMove camMove(const Mechanism& m, const Joint& j, const Moves& mv) {
  internal::CamMove out;
  const CamJoint c = *camJoint(m, j);
  const Vec2 a = c.drawn.centre, b = c.drawn.b;
  const Vec2 da = mv.at(guidePin(m, c, *m.point(j.a)), 0);
  const double dR = mv.dim.camOf == j.id ? mv.dim.camBase : 0;
  const double R = c.kind.base + c.kind.roller;
  out.b = mv.at(j.b, 0);
  const Joint& f = *m.joint(c.followerJoint);
  if (c.kind.oscillating) {
    const Point &x = *m.point(f.a), &y = *m.point(f.b);
    const Point& onFollower = x.body == c.follower ? x : y;
    const Point& onGuide = x.body == c.follower ? y : x;
    const Vec2 w = (b - a).normalized();
    const Vec2 pivotMove = mv.at(onGuide.id, 0) - mv.at(onFollower.id, 0);
    out.turn = (dR - w.dot(pivotMove + out.b - da)) / w.dot(perp(b - c.drawn.pivot));
    // b at the new lowest position (out.b in the follower's frame, the frame carried onto the
    // guide's pivot and turned by out.turn): the face's normal there, in the follower's frame.
    const Vec2 low = pivotMove + out.b + out.turn * perp(b - c.drawn.pivot);
    if (c.kind.flat) out.faceTurn = cross(w, low - da) / (b - a).norm() - out.turn;
    return out;
  }
  const Slot& slot = *m.slot(f.slot);
  Vec2 d0 = Vec2::Zero(), d1 = Vec2::Zero();
  for (const Dimension::SlotMove& s : mv.dim.slots)
    if (s.slot == slot.id) mv.space.slotMove(slot, s, 0, d0, d1);
  const Vec2 t = slot.p1 - slot.p0, u = c.drawn.along;
  const double len = t.norm();
  const Vec2 e = t / len, dt = d1 - d0;
  const double tau = e.dot(m.point(f.a)->pos - slot.p0);
  out.along = u.dot(e) * (dt - e * e.dot(dt)) / len;
  const Vec2 dc = d0 + tau / len * dt + out.b - mv.at(f.a, 0);
  const double step = c.kind.flat ? dR - u.dot(dc - da) - out.along.dot(b - a)
                                  : (R * dR - (b - a).dot(dc - da)) / (b - a).dot(u);
  out.lowest = dc + step * u;
  return out;
}

// What prepare() cannot differentiate, named; "" when it can.
std::string unsupported(const Mechanism& m, const System& sys, Sensitivity::Space space) {
  const bool world = space == Sensitivity::Space::World;
  if (sys.frames.size() > 1 && !world)
    return "sensitivities of a spatial model (planes) are not computed here yet (a point's "
           "world x, y, z are: linkage-cli sensitivity --point)";
  for (const Row& r : sys.cons)
    if (r.kind == Primitive::Distance3 && !world)
      return "sensitivities through a ball rod (" + jointLabel(m, m.joints[r.joint].id) +
             ") are not computed here yet (a point's world x, y, z are: linkage-cli "
             "sensitivity --point)";
  for (const Joint& j : m.joints) {
    const Role role = kindOf(j).role;
    if (isCam(j)) {
      if (std::string why = camRefused(m, sys, j); !why.empty()) return why;
      continue;
    }
    if (role != Role::Revolute && role != Role::Prismatic && role != Role::PointOnCurve &&
        role != Role::Coupling && !(world && role == Role::Distance))
      return std::string("sensitivities through a ") + kindOf(j).name + " (" + jointLabel(m, j.id) +
             ") are not computed yet";
  }
  return "";
}

}  // namespace

Status Sensitivity::prepare(const Kinematics& k, std::vector<Dimension> dims, Space space) {
  dims_ = std::move(dims);
  pointMove_.clear();
  dq_.resize(0, 0);
  if (!k.valid()) return Status::badModel("no mechanism is loaded");
  const KinematicsState& s = internal::state(k);
  if (std::string why = unsupported(s.mech, s.sys, space); !why.empty())
    return Status::badModel(why);
  size_t ids = 0;
  for (const Point& p : s.mech.points) ids = std::max<size_t>(ids, p.id.value + 1);
  const internal::SpaceMoves sm(s.mech, s.sys);
  std::vector<Vec2> move(ids);
  std::vector<double> depth(ids);
  pointMove_.assign(dims_.size(), std::vector<Vec3>(ids, Vec3::Zero()));
  for (size_t d = 0; d < dims_.size(); ++d) {
    std::fill(move.begin(), move.end(), Vec2::Zero());
    std::fill(depth.begin(), depth.end(), 0.0);
    for (const auto& [p, by] : dims_[d].points)
      if (p.value < ids) move[p.value] += by;
    for (const auto& [p, by] : dims_[d].depths)
      if (p.value < ids) depth[p.value] += by;
    for (const Point& p : s.mech.points)
      pointMove_[d][p.id.value] = sm.kept(p, move[p.id.value], depth[p.id.value]);
  }
  camMove_.assign(dims_.size(), std::vector<internal::CamMove>(s.mech.joints.size()));
  for (size_t d = 0; d < dims_.size(); ++d)
    for (size_t j = 0; j < s.mech.joints.size(); ++j)
      if (isCam(s.mech.joints[j]))
        camMove_[d][j] = camMove(s.mech, s.mech.joints[j], {pointMove_[d], dims_[d], sm});
  return Status::success();
}

Status Sensitivity::at(const Kinematics& k) {
  const Status singular = Status::failure(
      StatusCode::Singular, "at a singular position the motion's derivatives are unbounded");
  if (!k.valid() || !k.derivativesValid() || pointMove_.size() != dims_.size()) return singular;
  const KinematicsState& s = internal::state(k);
  const System& sys = s.sys;
  std::vector<BodyView> views;
  makeViews(sys, k.q(), &k.dq(), views);
  // Accelerations switched off (KinematicsOptions): no acceleration sensitivities either.
  const bool acc = k.ddq().size() == sys.nCoords() && k.ddq().allFinite();
  const Eigen::VectorXd ddq = acc ? k.ddq() : Eigen::VectorXd();
  const std::vector<int>& map = s.newton.rowMap();
  const int n = sys.nCoords(), dims = static_cast<int>(dims_.size());
  // A caller after the values alone (a window's ends, a clearance) asks for no dimension:
  // Eigen's solve of an empty right-hand side offsets a null pointer (UBSan).
  if (dims == 0) {
    dq_.resize(n, 0);
    dqd_.resize(n, 0);
    dqdd_.resize(n, 0);
    return Status::success();
  }
  const internal::SpaceMoves space(s.mech, sys);
  Eigen::MatrixXd J(n, n), rhs(n, dims);
  evalJacobian(sys, views, map, J);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(J);
  // Phi = 0, J q' + Phi_phi = 0 and J q'' - gamma = 0 at every p: each rate's derivative from
  // the change of its equation with the lower rates' derivatives known.
  Eigen::MatrixXd* out[3] = {&dq_, &dqd_, &dqdd_};
  for (int order = 0; order < (acc ? 3 : 2); ++order) {
    for (int d = 0; d < dims; ++d) {
      const Eigen::VectorXd dq = order ? Eigen::VectorXd(dq_.col(d)) : Eigen::VectorXd();
      const Eigen::VectorXd dqd = order > 1 ? Eigen::VectorXd(dqd_.col(d)) : Eigen::VectorXd();
      rowChanges(s.mech, sys, views, ddq, {pointMove_[d], dims_[d], space, &camMove_[d]}, order, dq,
                 dqd, map, rhs.col(d));
    }
    *out[order] = -lu.solve(rhs);
    if (!out[order]->allFinite()) return singular;
  }
  if (!acc) dqdd_.setConstant(n, dims, std::nan(""));
  return Status::success();
}

double Sensitivity::angle(const Kinematics& k, BodyId b, int dim) const {
  const int i = internal::system(k).bodyIndex(b);
  return i < 0 ? 0.0 : dq_(3 * i + 2, dim);
}

double Sensitivity::angularVelocity(const Kinematics& k, BodyId b, int dim) const {
  const int i = internal::system(k).bodyIndex(b);
  return i < 0 ? 0.0 : k.omega() * dqd_(3 * i + 2, dim);
}

double Sensitivity::angularAcceleration(const Kinematics& k, BodyId b, int dim) const {
  const int i = internal::system(k).bodyIndex(b);
  return i < 0 ? 0.0 : k.omega() * k.omega() * dqdd_(3 * i + 2, dim);
}

Eigen::VectorXd Sensitivity::jacobianChange(const Kinematics& k, const Eigen::VectorXd& w,
                                            int dim) const {
  const KinematicsState& s = internal::state(k);
  std::vector<BodyView> views;
  makeViews(s.sys, k.q(), &w, views);
  // The rates' change at order 1 holds the rates (here w) and moves the pose by dq/dp: d(J w).
  Eigen::VectorXd out(s.sys.nCoords());
  const internal::SpaceMoves space(s.mech, s.sys);
  rowChanges(s.mech, s.sys, views, Eigen::VectorXd(),
             {pointMove_[dim], dims_[dim], space, &camMove_[dim]}, 1, Eigen::VectorXd(dq_.col(dim)),
             Eigen::VectorXd(), s.newton.rowMap(), out);
  return out;
}

Vec2 Sensitivity::point(const Kinematics& k, PointId p, int dim) const {
  const System& sys = internal::system(k);
  const PointLocation* loc = sys.point(p);
  const Vec2 own =
      p.value < pointMove_[dim].size() ? Vec2(pointMove_[dim][p.value].head<2>()) : Vec2::Zero();
  if (!loc || loc->body < 0) return own;
  const int c = 3 * loc->body;
  const Rot R = Rot::of(k.q()[c + 2]);
  const Vec2 a = R * loc->s;
  return Vec2(dq_(c, dim), dq_(c + 1, dim)) + dq_(c + 2, dim) * perp(a) + R * own;
}

Vec2 Sensitivity::point(const Kinematics& k, BodyId b, const Vec2& at, const Vec2& own,
                        int dim) const {
  const System& sys = internal::system(k);
  const int body = sys.bodyIndex(b);
  if (body < 0) return own;  // the ground's drawing is the world
  const int c = 3 * body;
  const Rot R = Rot::of(k.q()[c + 2]);
  const Vec2 a = R * (at - sys.frameOrigin[body]);
  return Vec2(dq_(c, dim), dq_(c + 1, dim)) + dq_(c + 2, dim) * perp(a) + R * own;
}

Vec2 Sensitivity::velocity(const Kinematics& k, PointId p, int dim) const {
  const System& sys = internal::system(k);
  const PointLocation* loc = sys.point(p);
  if (!loc || loc->body < 0) return Vec2::Zero();
  const int c = 3 * loc->body;
  const Rot R = Rot::of(k.q()[c + 2]);
  const Vec2 a = R * loc->s, own = pointMove_[dim][p.value].head<2>();
  const Vec2 da = dq_(c + 2, dim) * perp(a) + R * own;  // d(R s)
  const double w = k.dq()[c + 2];
  return k.omega() *
         (Vec2(dqd_(c, dim), dqd_(c + 1, dim)) + dqd_(c + 2, dim) * perp(a) + w * perp(da));
}

Vec2 Sensitivity::acceleration(const Kinematics& k, PointId p, int dim) const {
  const PointLocation* loc = internal::system(k).point(p);
  if (!loc || loc->body < 0) return Vec2::Zero();
  return acceleration(k, loc->body, loc->s, pointMove_[dim][p.value].head<2>(), dim);
}

Vec2 Sensitivity::acceleration(const Kinematics& k, BodyId b, const Vec2& at, int dim) const {
  const System& sys = internal::system(k);
  const int body = sys.bodyIndex(b);
  if (body < 0) return Vec2::Zero();
  return acceleration(k, body, at - sys.frameOrigin[body], Vec2::Zero(), dim);
}

// s: the point in its body's frame; own: its move in the sketch per unit of the dimension.
Vec2 Sensitivity::acceleration(const Kinematics& k, int body, const Vec2& s, const Vec2& own,
                               int dim) const {
  const int c = 3 * body;
  const Rot R = Rot::of(k.q()[c + 2]);
  const Vec2 a = R * s;
  const Vec2 da = dq_(c + 2, dim) * perp(a) + R * own;  // d(R s)
  const double w = k.dq()[c + 2], dw = dqd_(c + 2, dim), alpha = k.ddq()[c + 2];
  const double omega = k.omega();
  return omega * omega *
         (Vec2(dqdd_(c, dim), dqdd_(c + 1, dim)) + dqdd_(c + 2, dim) * perp(a) + alpha * perp(da) -
          2 * w * dw * a - w * w * da);
}

namespace {

// A class-frame derivative of a point of a moving body in the world (its depth's move only for
// the position); the ground's own move is already the world's.
Vec3 inWorld(const Kinematics& k, PointId p, const Vec2& v, double depth, const Vec3& ground) {
  const System& sys = internal::system(k);
  const PointLocation* loc = sys.point(p);
  if (!loc || loc->body < 0) return ground;
  const Plane& f = sys.frames[sys.classOf.empty() ? 0 : sys.classOf[loc->body]];
  return v.x() * f.xAxis + v.y() * f.yAxis + depth * f.normal();
}

}  // namespace

Vec3 Sensitivity::point3(const Kinematics& k, PointId p, int dim) const {
  const Vec3 own = p.value < pointMove_[dim].size() ? pointMove_[dim][p.value] : Vec3::Zero();
  return inWorld(k, p, point(k, p, dim), own.z(), own);
}

Vec3 Sensitivity::velocity3(const Kinematics& k, PointId p, int dim) const {
  return inWorld(k, p, velocity(k, p, dim), 0, Vec3::Zero());
}

Vec3 Sensitivity::acceleration3(const Kinematics& k, PointId p, int dim) const {
  return inWorld(k, p, acceleration(k, p, dim), 0, Vec3::Zero());
}

}  // namespace linkage
