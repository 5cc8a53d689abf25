#include "closed_form.h"

#include <cmath>

namespace linkage {

namespace {

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// A known body's state: pose, and first and second derivatives in the driver angle.
struct State {
  Vec2 r = Vec2::Zero(), v = Vec2::Zero(), a = Vec2::Zero();
  double th = 0, w = 0, al = 0;
  Rot R;

  // Position, velocity and acceleration of the body's local point s.
  Vec2 pos(const Vec2& s) const { return r + R * s; }
  Vec2 vel(const Vec2& s) const { return v + w * perp(R * s); }
  Vec2 acc(const Vec2& s) const {
    const Vec2 g = R * s;
    return a + al * perp(g) - w * w * g;
  }
};

State stateOf(int body, const Eigen::VectorXd& q, const Eigen::VectorXd& dq,
              const Eigen::VectorXd& ddq, const std::vector<Rot>* rot = nullptr) {
  State s;
  if (body < 0) return s;
  const int k = 3 * body;
  s.r = Vec2(q[k], q[k + 1]);
  s.th = q[k + 2];
  s.R = rot ? (*rot)[body] : Rot{std::cos(s.th), std::sin(s.th)};
  s.v = Vec2(dq[k], dq[k + 1]);
  s.w = dq[k + 2];
  s.a = Vec2(ddq[k], ddq[k + 1]);
  s.al = ddq[k + 2];
  return s;
}

// Writes a body whose angle, rates and one point's motion are known; keeps its rotation.
void place(int body, double th, double w, double al, const Vec2& s, const Vec2& P, const Vec2& vP,
           const Vec2& aP, Eigen::VectorXd& q, Eigen::VectorXd& dq, Eigen::VectorXd& ddq,
           std::vector<Rot>& rot) {
  rot[body] = placeBody(body, th, w, al, s, P, vP, aP, q, dq, ddq);
}

double angleOf(const Vec2& v) {
  return std::atan2(v.y(), v.x());
}

// Continues an angle from its previous value instead of wrapping it into (-pi, pi].
double continued(double raw, double previous) {
  return previous + std::remainder(raw - previous, 2 * M_PI);
}

// Solves [a b] x = rhs for the two columns a, b; false when they are (nearly) parallel: a dead
// point, left to the general solver to explain.
bool solve2(const Vec2& a, const Vec2& b, const Vec2& rhs, double& x, double& y) {
  const double det = cross(a, b);
  if (!(std::abs(det) > 1e-10 * a.norm() * b.norm())) return false;
  x = cross(rhs, b) / det;
  y = cross(a, rhs) / det;
  return true;
}

// Where body b's local point s would be after h more radians of crank, on its smooth path:
// second-order Taylor from the previous position, rates and accelerations.
Vec2 predicted(int b, const Vec2& s, double h, const Eigen::VectorXd& q, const Eigen::VectorXd& dq,
               const Eigen::VectorXd& ddq) {
  const State st = stateOf(b, q, dq, ddq);
  return st.pos(s) + h * st.vel(s) + (0.5 * h * h) * st.acc(s);
}

}  // namespace

std::optional<ClosedFormPlan> ClosedFormPlan::build(const Mechanism& m, const System& sys,
                                                    const Eigen::VectorXd& q) {
  if (!sys.hasDriver || sys.nRows != sys.nCoords() || sys.nJointRows + 1 != sys.nCoords())
    return std::nullopt;  // holds, redundant or missing equations: the general solve
  const int nj = static_cast<int>(m.joints.size());
  // The compiled rows of each joint.
  std::vector<const Constraint*> pin(nj, nullptr), line(nj, nullptr);
  std::vector<bool> isSlider(nj, false), used(nj, false);
  const Constraint* driver = nullptr;
  for (const Constraint& c : sys.cons) {
    if (c.kind == RowKind::Pin) pin[c.joint] = &c;
    if (c.kind == RowKind::Line) line[c.joint] = &c;
    if (c.kind == RowKind::Angle) isSlider[c.joint] = true;
    if (c.kind == RowKind::Driver) driver = &c;
  }
  std::vector<bool> known(sys.nBodies, false);
  auto isKnown = [&](int b) { return b < 0 || known[b]; };
  // Joints of body b not used yet whose other side is known.
  auto toKnown = [&](int b, std::vector<int>& out) {
    out.clear();
    for (int j = 0; j < nj; ++j) {
      if (used[j]) continue;
      const Constraint* c = pin[j] ? pin[j] : line[j];
      if (!c) continue;
      if ((c->bi == b && isKnown(c->bj)) || (c->bj == b && isKnown(c->bi))) out.push_back(j);
    }
  };
  auto pinOn = [&](const Constraint* c, int b) { return c->bi == b ? c->si : c->sj; };
  auto pinOther = [&](const Constraint* c, int b) { return c->bi == b ? c->sj : c->si; };
  auto otherBody = [&](const Constraint* c, int b) { return c->bi == b ? c->bj : c->bi; };

  ClosedFormPlan plan;
  bool crankDone = false;
  int remaining = sys.nBodies;
  std::vector<int> k1j, k2j;
  while (remaining > 0) {
    bool progress = false;
    if (!crankDone) {
      const Constraint* p = pin[driver->joint];
      const int unknownSide = !isKnown(driver->bi) ? driver->bi : driver->bj;
      const int knownSide = unknownSide == driver->bi ? driver->bj : driver->bi;
      if (isKnown(knownSide) && !isKnown(unknownSide)) {
        toKnown(unknownSide, k1j);
        if (k1j.size() == 1 && k1j[0] == driver->joint) {
          Group g;
          g.kind = Kind::Crank;
          g.b1 = unknownSide;
          g.k1 = knownSide;
          g.p1 = pinOn(p, unknownSide);
          g.p1k = pinOther(p, unknownSide);
          g.sign = unknownSide == driver->bi ? sys.sigma : -sys.sigma;
          plan.groups_.push_back(g);
          used[driver->joint] = true;
          known[unknownSide] = true;
          crankDone = progress = true;
          --remaining;
        }
      }
    }
    for (int b1 = 0; b1 < sys.nBodies && !progress; ++b1) {
      if (known[b1]) continue;
      toKnown(b1, k1j);
      // RP: a pin and a pin-in-slot (point on b1) to known bodies.
      if (k1j.size() == 2) {
        for (int order = 0; order < 2 && !progress; ++order) {
          const int jp = k1j[order], js = k1j[1 - order];
          if (!pin[jp] || !line[js] || isSlider[js] || line[js]->bi != b1) continue;
          Group g;
          g.kind = Kind::RP;
          g.b1 = b1;
          g.k1 = otherBody(pin[jp], b1);
          g.p1 = pinOn(pin[jp], b1);
          g.p1k = pinOther(pin[jp], b1);
          g.c1 = line[js]->si;
          g.k2 = line[js]->bj;
          g.u = line[js]->sj;
          g.n = line[js]->nj;
          plan.groups_.push_back(g);
          used[jp] = used[js] = true;
          known[b1] = true;
          progress = true;
          --remaining;
        }
        if (progress) break;
      }
      if (k1j.size() != 1 || !pin[k1j[0]]) continue;
      // A dyad: b1 pinned to b2, b2 with exactly one joint to known bodies.
      for (int j = 0; j < nj && !progress; ++j) {
        const Constraint* c = pin[j];
        if (used[j] || !c || (c->bi != b1 && c->bj != b1)) continue;
        const int b2 = otherBody(c, b1);
        if (b2 < 0 || known[b2]) continue;
        toKnown(b2, k2j);
        if (k2j.size() != 1) continue;
        const int j2 = k2j[0];
        Group g;
        g.b1 = b1;
        g.b2 = b2;
        g.k1 = otherBody(pin[k1j[0]], b1);
        g.p1 = pinOn(pin[k1j[0]], b1);
        g.p1k = pinOther(pin[k1j[0]], b1);
        g.c1 = pinOn(c, b1);
        g.c2 = pinOn(c, b2);
        if (pin[j2]) {
          g.kind = Kind::RRR;
          g.k2 = otherBody(pin[j2], b2);
          g.p2 = pinOn(pin[j2], b2);
          g.p2k = pinOther(pin[j2], b2);
        } else if (isSlider[j2] && line[j2]->bi == b2) {
          g.kind = Kind::RRP;
          g.k2 = line[j2]->bj;
          g.q2 = line[j2]->si;
          g.u = line[j2]->sj;
          g.n = line[j2]->nj;
        } else {
          continue;
        }
        plan.groups_.push_back(g);
        used[k1j[0]] = used[j] = used[j2] = true;
        known[b1] = known[b2] = true;
        progress = true;
        remaining -= 2;
      }
    }
    // A core body held by three conditions, its blocks eliminated (core_group.h).
    for (int c = 0; c < sys.nBodies && !progress; ++c) {
      if (known[c]) continue;
      CoreGroup core;
      core.core = c;
      std::vector<int> joints, blocks;
      int rows = 0;
      bool usable = true;
      for (int j = 0; j < nj && usable; ++j) {
        if (used[j]) continue;
        const Constraint* p = pin[j];
        const Constraint* l = line[j];
        if (p && (p->bi == c || p->bj == c)) {
          const int other = otherBody(p, c);
          CoreLink link;
          link.s = pinOn(p, c);
          if (isKnown(other)) {
            link.pin = true;
            link.known = other;
            link.ks = pinOther(p, c);
            rows += 2;
            joints.push_back(j);
          } else {
            // A block: this pin and one slider in a known slot, nothing else.
            std::vector<int> rest;
            for (int j2 = 0; j2 < nj; ++j2) {
              if (used[j2] || j2 == j) continue;
              const Constraint* c2 = pin[j2] ? pin[j2] : line[j2];
              if (c2 && (c2->bi == other || c2->bj == other)) rest.push_back(j2);
            }
            if (rest.size() != 1 || !isSlider[rest[0]] || line[rest[0]]->bi != other ||
                !isKnown(line[rest[0]]->bj))
              continue;  // not a block: a joint for a later group
            const Constraint* sl = line[rest[0]];
            link.known = sl->bj;
            link.ks = sl->sj - (sl->si - pinOther(p, c));  // the line the pin point keeps to
            link.n = sl->nj;
            link.block = other;
            link.blockPin = pinOther(p, c);
            rows += 1;
            joints.push_back(j);
            joints.push_back(rest[0]);
            blocks.push_back(other);
          }
          core.links.push_back(link);
        } else if (l && l->bi == c && !isSlider[j] && isKnown(l->bj)) {
          CoreLink link;
          link.known = l->bj;
          link.s = l->si;
          link.ks = l->sj;
          link.n = l->nj;
          rows += 1;
          joints.push_back(j);
          core.links.push_back(link);
        } else if (l && (l->bi == c || l->bj == c) && isKnown(otherBody(l, c))) {
          usable = false;  // a slider or a slot of its own on a known body: not this kind
        }
      }
      if (!usable || rows != 3) continue;
      core.detSign = coreDetSign(core, sys, q);
      if (core.detSign == 0) return std::nullopt;
      Group g;
      g.kind = Kind::Core;
      g.b1 = c;
      g.core = static_cast<int>(plan.cores_.size());
      plan.cores_.push_back(core);
      plan.groups_.push_back(g);
      for (int j : joints) used[j] = true;
      known[c] = true;
      for (int b : blocks) known[b] = true;
      remaining -= 1 + static_cast<int>(blocks.size());
      progress = true;
    }
    if (!progress) return std::nullopt;
  }
  for (int j = 0; j < nj; ++j)
    if (!used[j]) return std::nullopt;

  // Local directions and the drawn branches, from the assembled configuration.
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(q.size());
  for (Group& g : plan.groups_) {
    if (g.kind == Kind::Crank || g.kind == Kind::Core) continue;
    g.dir1 = angleOf(g.c1 - g.p1);
    const State k1 = stateOf(g.k1, q, zero, zero);
    const State b1 = stateOf(g.b1, q, zero, zero);
    const Vec2 P1 = k1.pos(g.p1k), C = b1.pos(g.c1);
    if (g.kind == Kind::RRR) {
      g.dir2 = angleOf(g.c2 - g.p2);
      const Vec2 P2 = stateOf(g.k2, q, zero, zero).pos(g.p2k);
      g.sign = cross(P2 - P1, C - P1) >= 0 ? 1 : -1;
    } else {
      g.d = -perp(g.n);  // the slot's direction: n was made as perp(direction)
      const State k2 = stateOf(g.k2, q, zero, zero);
      const Vec2 n = k2.R * g.n;
      const Vec2 foot = P1 + n.dot(C - P1) * n;  // C is on the (shifted) line: project P1 on it
      g.sign = (k2.R * g.d).dot(C - foot) >= 0 ? 1 : -1;
    }
  }
  return plan;
}

bool ClosedFormPlan::solve(const System& sys, double prevPhi, double phi, Eigen::VectorXd& q,
                           Eigen::VectorXd& dq, Eigen::VectorXd& ddq) const {
  // In place: each group writes only its own bodies, after reading their previous angles.
  rot_.resize(sys.nBodies);
  for (const Group& g : groups_) {
    if (g.kind == Kind::Core) {
      const CoreGroup& core = cores_[g.core];
      if (!solveCore(core, sys, q, phi - prevPhi, q, dq, ddq)) return false;
      rot_[core.core] = Rot{std::cos(q[3 * core.core + 2]), std::sin(q[3 * core.core + 2])};
      for (const CoreLink& l : core.links)
        if (l.block >= 0) rot_[l.block] = l.known >= 0 ? rot_[l.known] : Rot{};
      continue;
    }
    const State k1 = stateOf(g.k1, q, dq, ddq, &rot_);
    const Vec2 P1 = k1.pos(g.p1k), vP1 = k1.vel(g.p1k), aP1 = k1.acc(g.p1k);
    if (g.kind == Kind::Crank) {
      const double th = k1.th + g.sign * phi;
      place(g.b1, th, k1.w + g.sign, k1.al, g.p1, P1, vP1, aP1, q, dq, ddq, rot_);
      continue;
    }
    const double d1 = (g.c1 - g.p1).norm();
    // The joint C as the smooth motion would carry it: if that lands on the other side of the
    // branch line than the drawn branch, the motion crosses a singular position (a change
    // point, or a dead point ahead), where the intersection formula would reflect onto the
    // other branch. The general solve takes over there and reports it.
    const Vec2 Cpred = predicted(g.b1, g.c1, phi - prevPhi, q, dq, ddq);
    Vec2 C, u1 = Vec2::Zero();
    double w1 = 0, al1 = 0;
    if (g.kind == Kind::RRR) {
      const State k2 = stateOf(g.k2, q, dq, ddq, &rot_);
      const Vec2 P2 = k2.pos(g.p2k), vP2 = k2.vel(g.p2k), aP2 = k2.acc(g.p2k);
      const double d2 = (g.c2 - g.p2).norm();
      const Vec2 e = P2 - P1;
      const double L = e.norm();
      if (!(L > 0)) return false;
      const Vec2 eh = e / L;
      const double a = (d1 * d1 - d2 * d2 + L * L) / (2 * L);
      const double h2 = d1 * d1 - a * a;
      if (!(h2 >= 0)) return false;
      if (g.sign * cross(eh, Cpred - P1) < 0) return false;
      C = P1 + a * eh + g.sign * std::sqrt(h2) * perp(eh);
      u1 = C - P1;
      const Vec2 u2 = C - P2;
      double w2, al2;
      if (!solve2(perp(u1), -perp(u2), vP2 - vP1, w1, w2)) return false;
      solve2(perp(u1), -perp(u2), aP2 - aP1 - w2 * w2 * u2 + w1 * w1 * u1, al1, al2);
      const double th2 = continued(angleOf(u2) - g.dir2, q[3 * g.b2 + 2]);
      place(g.b2, th2, w2, al2, g.p2, P2, vP2, aP2, q, dq, ddq, rot_);
    } else {
      // The line C must keep to: the slot (through U, normal n), shifted by the block's offset.
      const State k2 = stateOf(g.k2, q, dq, ddq, &rot_);
      const Vec2 n = k2.R * g.n, dir = k2.R * g.d, U = k2.pos(g.u);
      const Vec2 w = g.kind == Kind::RRP ? Vec2(k2.R * (g.q2 - g.c2)) : Vec2::Zero();
      const double delta = n.dot(U - w - P1);
      const double lam2 = d1 * d1 - delta * delta;
      if (!(lam2 >= 0)) return false;
      const Vec2 foot = P1 + delta * n;
      if (g.sign * dir.dot(Cpred - foot) < 0) return false;
      C = foot + g.sign * std::sqrt(lam2) * dir;
      u1 = C - P1;
      // C = U + s dir - w, with the block turning with k2 (w' = w_k2 perp(w)).
      const double s = dir.dot(C + w - U);
      const Vec2 Ru = k2.R * g.u;
      const Vec2 vU = k2.v + k2.w * perp(Ru);
      const Vec2 V0 = vU + s * k2.w * perp(dir) - k2.w * perp(w);
      double sd, sdd;
      if (!solve2(perp(u1), -dir, V0 - vP1, w1, sd)) return false;
      const Vec2 aU = k2.a + k2.al * perp(Ru) - k2.w * k2.w * Ru;
      const Vec2 A0 = aU + 2 * sd * k2.w * perp(dir) + s * (k2.al * perp(dir) - k2.w * k2.w * dir) -
                      (k2.al * perp(w) - k2.w * k2.w * w);
      solve2(perp(u1), -dir, A0 - aP1 + w1 * w1 * u1, al1, sdd);
      if (g.kind == Kind::RRP) {
        const Vec2 vC = V0 + sd * dir;
        const Vec2 aC = A0 + sdd * dir;
        place(g.b2, k2.th, k2.w, k2.al, g.c2, C, vC, aC, q, dq, ddq, rot_);
      }
    }
    const double th1 = continued(angleOf(u1) - g.dir1, q[3 * g.b1 + 2]);
    place(g.b1, th1, w1, al1, g.p1, P1, vP1, aP1, q, dq, ddq, rot_);
  }
  return true;
}

}  // namespace linkage
