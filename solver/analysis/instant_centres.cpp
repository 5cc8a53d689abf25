#include "linkage/instant_centres.h"
#include "linkage/space.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "kinematics/kinematics_state.h"
#include "linkage/elements.h"

namespace linkage {

namespace {

using Vec3 = Eigen::Vector3d;

// |a x b| of unit homogeneous vectors: 0 for the same point (either sign), the distance over L
// for nearby finite points, the sine of the angle for two directions.
double chordal(const Vec3& a, const Vec3& b) {
  return a.cross(b).norm();
}

// a x b and its norm, in scalars: the hot loop of Kennedy's passes, written so that the compiler
// keeps it in registers.
inline double crossNorm(const Vec3& a, const Vec3& b, Vec3& out) {
  const double x = a[1] * b[2] - a[2] * b[1];
  const double y = a[2] * b[0] - a[0] * b[2];
  const double z = a[0] * b[1] - a[1] * b[0];
  out = Vec3(x, y, z);
  return std::sqrt(x * x + y * y + z * z);
}

}  // namespace

const char* toString(CentreStatus s) {
  return s == CentreStatus::Primary   ? "primary"
         : s == CentreStatus::Kennedy ? "kennedy"
                                      : "velocity";
}

const char* toString(KennedyFailure f) {
  return f == KennedyFailure::None          ? ""
         : f == KennedyFailure::TooFewLines ? "fewer than two lines through known centres"
                                            : "the lines through known centres coincide";
}

const InstantCentre* InstantCentres::find(int i, int j) const {
  if (i == j) return nullptr;
  if (i > j) std::swap(i, j);
  auto at = [&](int num) {
    auto it = std::lower_bound(numbers.begin(), numbers.end(), num);
    return it != numbers.end() && *it == num ? static_cast<int>(it - numbers.begin()) : -1;
  };
  const int a = at(i), b = at(j), n = static_cast<int>(numbers.size());
  if (a < 0 || b < 0) return nullptr;
  const size_t p = static_cast<size_t>(a * n - a * (a + 1) / 2 + (b - a - 1));
  return p < centres.size() ? &centres[p] : nullptr;
}

int InstantCentres::numberOf(BodyId b) const {
  for (size_t t = 0; t < bodies.size(); ++t)
    if (bodies[t] == b) return numbers[t];
  return 0;
}

BodyId InstantCentres::bodyNumbered(int n) const {
  for (size_t t = 0; t < numbers.size(); ++t)
    if (numbers[t] == n) return bodies[t];
  return {};
}

Status textbookNumbers(const Mechanism& m, std::vector<BodyId>& bodies, std::vector<int>& numbers) {
  bodies.clear();
  numbers.clear();
  if (!m.ground()) return Status::badModel("no body is the ground");
  std::vector<std::pair<int, BodyId>> list;  // (number, body)
  auto refuse = [&](size_t i, const std::string& why) {
    Status s =
        Status::badModel("bodies[" + std::to_string(i) + "] '" + m.bodies[i].name + "' " + why);
    s.bodies.push_back(m.bodies[i].id);
    return s;
  };
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    const Body& b = m.bodies[i];
    if (!b.number) continue;
    const int num = *b.number;
    if (b.ground && num != 1)
      return refuse(i, "is the ground, which is number 1 for instant centres; its number is " +
                           std::to_string(num));
    if (!b.ground && num < 2)
      return refuse(i, "has number " + std::to_string(num) +
                           ": 1 is the ground's, the other bodies take 2 and up");
    for (const auto& [n, id] : list)
      if (n == num)
        return refuse(i, "has number " + std::to_string(num) + ", as has body '" +
                             m.body(id)->name + "': instant-centre numbers must be unique");
    list.emplace_back(num, b.id);
  }
  // The others take the smallest free numbers, in file order.
  auto taken = [&](int num) {
    return std::any_of(list.begin(), list.end(), [&](const auto& e) { return e.first == num; });
  };
  int next = 2;
  for (const Body& b : m.bodies) {
    if (b.number) continue;
    if (b.ground) {
      list.emplace_back(1, b.id);
      continue;
    }
    while (taken(next)) ++next;
    list.emplace_back(next++, b.id);
  }
  std::sort(list.begin(), list.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const auto& [n, id] : list) {
    numbers.push_back(n);
    bodies.push_back(id);
  }
  return Status::success();
}

// Each body's plane class, and in space the mechanism as each class's frame sees it (prepared
// once: a joint's centre data are read from it at every prepare, never per frame).
void InstantCentreSolver::planeClassesOf(const Mechanism& m, const System& sys) {
  classOf_.assign(n_, 0);
  flat_.clear();
  out_.classes = planeClasses(m);
  if (!isSpatial(m)) return;
  for (int t = 0; t < n_; ++t) classOf_[t] = sysIndex_[t] >= 0 ? sys.classOf[sysIndex_[t]] : -1;
  for (size_t c = 0; c < out_.classes.frames.size(); ++c)
    flat_.push_back(flattenedTo(m, out_.classes, static_cast<int>(c)));
}

int InstantCentreSolver::pair(int a, int b) const {
  if (a > b) std::swap(a, b);
  return a * n_ - a * (a + 1) / 2 + (b - a - 1);
}

// What each joint says about the centre of the two bodies it joins (its kind's rule), with its
// points and direction in body frames, and the pair it is about.
std::vector<std::pair<int, InstantCentreSolver::Primary>> InstantCentreSolver::primaries(
    const Mechanism& m, const System& sys) const {
  std::vector<std::pair<int, Primary>> found;
  auto local = [&](BodyId b, const Vec2& sketch, int& index) {
    index = sys.bodyIndex(b);
    return index >= 0 ? Vec2(sketch - sys.frameOrigin[index]) : sketch;
  };
  auto classOfBody = [&](BodyId b) {
    const int k = sys.bodyIndex(b);
    return k >= 0 ? classOf_[textbookOf_[k + 1]] : -1;
  };
  for (size_t ji = 0; ji < m.joints.size(); ++ji) {
    const Joint& j = m.joints[ji];
    CentreData c = kindOf(j).centre(m, j);
    if (!flat_.empty()) {
      // In space: a joint's centre is in the frame of its bodies' class, from its points as that
      // frame sees them; a joint across classes (a ball rod, a bevel pair) gives none.
      const int ca = classOfBody(c.bodies[0]), cb = classOfBody(c.bodies[1]);
      if (ca >= 0 && cb >= 0 && ca != cb) continue;
      c = kindOf(j).centre(flat_[std::max({ca, cb, 0})], j);
    }
    Primary p;
    p.rule = c.rule;
    p.joint = static_cast<int>(ji);
    for (int k = 0; k < 2; ++k)
      if (c.pBody[k]) p.p[k] = local(c.pBody[k], c.p[k], p.pBody[k]);
    if (c.nBody) {
      p.nBody = sys.bodyIndex(c.nBody);
      p.n = c.n;  // bodies are at angle 0 as drawn
    }
    p.ratio = c.ratio;
    const int ta = textbookOf_[sys.bodyIndex(c.bodies[0]) + 1];
    const int tb = textbookOf_[sys.bodyIndex(c.bodies[1]) + 1];
    if (ta == tb) continue;
    found.emplace_back(pair(ta, tb), p);
  }
  return found;
}

Status InstantCentreSolver::prepare(const Kinematics& k) {
  out_ = InstantCentres{};
  n_ = 0;
  if (!k.valid()) {
    out_.status = Status::badModel("no mechanism is loaded");
    return out_.status;
  }
  const Mechanism& m = k.mechanism();
  const System& sys = internal::system(k);
  revision_ = k.revision();
  out_.revision = revision_;
  jointIds_.clear();
  for (const Joint& j : m.joints) jointIds_.push_back(j.id);
  if (Status s = textbookNumbers(m, out_.bodies, out_.numbers); !s.ok()) {
    out_.status = s;
    return s;
  }
  n_ = static_cast<int>(out_.bodies.size());
  L_ = sys.size;
  sysIndex_.assign(n_, -1);
  textbookOf_.assign(sys.nBodies + 1, 0);
  for (int t = 0; t < n_; ++t) {
    sysIndex_[t] = sys.bodyIndex(out_.bodies[t]);
    textbookOf_[sysIndex_[t] + 1] = t;
  }
  planeClassesOf(m, sys);
  // The middle of the drawing: homogeneous coordinates about it, in units of L, are O(1).
  Vec2 lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  for (const Point& p : m.points) lo = lo.cwiseMin(p.pos), hi = hi.cwiseMax(p.pos);
  for (const Slot& s : m.slots)
    lo = lo.cwiseMin(s.p0).cwiseMin(s.p1), hi = hi.cwiseMax(s.p0).cwiseMax(s.p1);
  centre_ = lo.allFinite() && hi.allFinite() ? Vec2((lo + hi) / 2) : Vec2::Zero();

  std::vector<std::pair<int, Primary>> found = primaries(m, sys);
  std::stable_sort(found.begin(), found.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  const int pairs = n_ * (n_ - 1) / 2;
  pairIndex_.assign(n_ * n_, -1);
  for (int a = 0; a < n_; ++a)
    for (int b = 0; b < n_; ++b)
      if (a != b) pairIndex_[n_ * a + b] = pair(a, b);
  open_.reserve(pairs);
  work_.assign(pairs, Work{});
  primaries_.clear();
  for (const auto& [p, prim] : found) {
    if (work_[p].primaryCount == 0) work_[p].firstPrimary = static_cast<int>(primaries_.size());
    ++work_[p].primaryCount;
    primaries_.push_back(prim);
  }
  out_.centres.assign(pairs, InstantCentre{});
  for (int a = 0; a < n_; ++a)
    for (int b = a + 1; b < n_; ++b) {
      InstantCentre& c = out_.centres[pair(a, b)];
      c.i = out_.numbers[a];
      c.j = out_.numbers[b];
      c.bodyI = out_.bodies[a];
      c.bodyJ = out_.bodies[b];
      c.planeClass = std::max({classOf_[a], classOf_[b], 0});
      c.across = classOf_[a] >= 0 && classOf_[b] >= 0 && classOf_[a] != classOf_[b];
      work_[pair(a, b)].across = c.across;
    }
  out_.size = L_;
  cand_.reserve(n_ + 1);
  origin_.assign(sys.nBodies + 1, Vec2::Zero());
  cos_.assign(sys.nBodies + 1, 1.0);
  sin_.assign(sys.nBodies + 1, 0.0);
  twist_.assign(n_, Vec3::Zero());
  out_.disagreements.reserve(pairs);
  return Status::success();
}

inline Vec3 InstantCentreSolver::scaled(const Vec2& p) const {
  const Vec2 u = (p - centre_) / L_;
  return Vec3(u.x(), u.y(), 1.0).normalized();
}

inline Vec2 InstantCentreSolver::turn(int body, const Vec2& v) const {
  const int b = body + 1;
  return Vec2(cos_[b] * v.x() - sin_[b] * v.y(), sin_[b] * v.x() + cos_[b] * v.y());
}

inline Vec2 InstantCentreSolver::global(int body, const Vec2& s) const {
  return origin_[body + 1] + turn(body, s);
}

Vec3 InstantCentreSolver::toPublic(const Vec3& h) const {
  const Vec2 xy(h.x(), h.y());
  const double xyNorm = xy.norm();
  if (std::abs(h.z()) <= CentreTolerances::infinity * xyNorm) {
    Vec2 d = xy / xyNorm;
    // An unoriented direction, written one way: dx > 0, or up when (within rounding) vertical.
    if (d.x() < -1e-12 || (std::abs(d.x()) <= 1e-12 && d.y() < 0)) d = -d;
    return Vec3(d.x(), d.y(), 0.0);
  }
  const Vec2 p = centre_ + (L_ / h.z()) * xy;
  return Vec3(p.x(), p.y(), 1.0);
}

inline Vec3 InstantCentreSolver::primaryLine(const Primary& pr) const {
  if (pr.rule == CentreRule::PoseLine)
    return scaled(pr.at).cross(Vec3(pr.along.x(), pr.along.y(), 0.0));
  const Vec3 p = scaled(global(pr.pBody[0], pr.p[0]));
  if (pr.rule == CentreRule::LineThrough) return p.cross(scaled(global(pr.pBody[1], pr.p[1])));
  const Vec2 n = turn(pr.nBody, pr.n);
  return p.cross(Vec3(n.x(), n.y(), 0.0));
}

inline void InstantCentreSolver::primaryPoint(const Primary& pr, Vec3& h, Vec3& mm,
                                              double& err) const {
  err = 1;
  if (pr.rule == CentreRule::AtPoint) {
    const Vec2 x = global(pr.pBody[0], pr.p[0]);
    h = scaled(x);
    mm = Vec3(x.x(), x.y(), 1.0);
  } else if (pr.rule == CentreRule::AtInfinity) {
    // Relative translation normal to n: the centre at infinity along n.
    const Vec2 n = turn(pr.nBody, pr.n);
    h = Vec3(n.x(), n.y(), 0.0);
    mm = toPublic(h);
  } else {
    // Weighted: (A - r B) / (1 - r), about the middle of the drawing in units of L; its error
    // grows as 1 - r shrinks (the centre runs off to infinity at r = 1).
    const Vec2 a = global(pr.pBody[0], pr.p[0]), b = global(pr.pBody[1], pr.p[1]);
    const double r = pr.ratio, z = 1 - r;
    const Vec2 xy = (a - centre_ - r * (b - centre_)) / L_;
    const Vec3 raw(xy.x(), xy.y(), z);
    const double norm = raw.norm();
    h = raw / norm;
    mm = toPublic(h);
    err = (1 + std::abs(r)) / norm;
  }
}

// The lines the joints' kinds compute at this pose (a cam's common normal). A machine in space
// has none: its kinds' lines are of its planes' frames, which no cam joins yet.
void InstantCentreSolver::poseLines(const Kinematics& k) {
  struct At : Pose {
    const Kinematics& k;
    explicit At(const Kinematics& kin) : k(kin) {}
    Vec2 point(PointId p) const override { return k.position(p); }
    Transform body(BodyId b) const override { return k.bodyTransform(b); }
  } pose(k);
  const Mechanism& m = k.mechanism();
  for (Primary& pr : primaries_) {
    if (pr.rule != CentreRule::PoseLine) continue;
    const Joint& j = m.joints[pr.joint];
    const auto line = kindOf(j).centreLine;
    pr.valid = flat_.empty() && line && line(m, j, pose, pr.at, pr.along);
  }
}

void InstantCentreSolver::primaryCentres() {
  for (int p = 0; p < static_cast<int>(work_.size()); ++p) {
    Work& w = work_[p];
    InstantCentre& c = out_.centres[p];
    w.found = -1;
    w.hasLine = w.rigid = w.exact = false;
    w.err = 0;
    c.status = CentreStatus::Velocity;
    c.joint = JointId{};
    c.lines = {};
    c.round = 0;
    c.kennedyFailure = KennedyFailure::None;
    c.errorBound = 0;
    int points = 0;
    bool fromLines = false;
    for (int e = w.firstPrimary; e < w.firstPrimary + w.primaryCount; ++e) {
      const Primary& pr = primaries_[e];
      if (!pr.valid) continue;
      if (pr.rule == CentreRule::LineAlong || pr.rule == CentreRule::LineThrough ||
          pr.rule == CentreRule::PoseLine) {
        // Only a line: the centre is on the normal to the slot through the pin.
        const Vec3 l = primaryLine(pr);
        const double s = l.norm();
        if (!w.hasLine) {
          w.hasLine = true;
          w.line = l / s;
          w.lineErr = 2 / s;
          w.lineJoint = pr.joint;
          continue;
        }
        if (points > 0) continue;
        // A second pin-in-slot between the same bodies: the two normals meet at the centre.
        const Vec3 x = w.line.cross(l / s);
        const double e2 = (w.lineErr + 2 / s) / x.norm();
        if (!(e2 <= CentreTolerances::coincident)) continue;  // the same line again
        w.h = x.normalized();
        w.exact = false;
        w.err = e2;
        c.joint = jointIds_[w.lineJoint];
        c.lines = {CentreLine{0, jointIds_[w.lineJoint]}, CentreLine{0, jointIds_[pr.joint]}};
        points = 1;
        fromLines = true;
        continue;
      }
      Vec3 h, mm;
      double err = 1;
      primaryPoint(pr, h, mm, err);
      if (points == 0 || fromLines) {
        // The first point (a joint's own point replaces an intersection of two slot normals).
        w.h = h;
        w.mm = mm;
        w.exact = true;
        w.err = err;
        c.joint = jointIds_[pr.joint];
        c.lines = {};
        points = 1;
        fromLines = false;
        continue;
      }
      // Another joint between the same bodies: the same centre, or they hold them rigidly.
      if (chordal(w.h, h) > CentreTolerances::check) w.rigid = true;
      ++points;
    }
    if (points > 0) {
      c.status = CentreStatus::Primary;
      w.found = w.rigid ? -1 : 0;
      w.hasLine = false;
    }
  }
}

void InstantCentreSolver::kennedy() {
  out_.kennedyRounds = 0;
  open_.clear();
  for (int a = 0; a < n_; ++a)
    for (int b = a + 1; b < n_; ++b) {
      const int p = pairIndex_[n_ * a + b];
      if (work_[p].found < 0 && !work_[p].rigid && !work_[p].across) open_.push_back({p, a, b});
    }
  // Circle-diagram passes: a pass finds every pair with two lines through centres known before
  // it, so what a pass finds depends on earlier passes only, never on the order of the pairs.
  // Well-conditioned meetings first; a pass takes poorly conditioned ones only when nothing else
  // is left to find.
  for (int round = 1; !open_.empty(); ++round) {
    if (!kennedyPass(round, CentreTolerances::preferred) &&
        !kennedyPass(round, CentreTolerances::coincident))
      break;
    out_.kennedyRounds = round;
    open_.erase(std::remove_if(open_.begin(), open_.end(),
                               [&](const Open& o) { return work_[o.pair].found >= 0; }),
                open_.end());
  }
}

bool InstantCentreSolver::kennedyPass(int round, double limit) {
  auto known = [round](const Work& w) { return w.found >= 0 && w.found < round; };
  const bool last = limit >= CentreTolerances::coincident;
  bool progress = false;
  for (const Open& o : open_) {
    Work& w = work_[o.pair];
    if (w.found >= 0) continue;  // found earlier in this round
    InstantCentre& c = out_.centres[o.pair];
    cand_.clear();
    int degenerate = 0;
    const int* fromA = &pairIndex_[n_ * o.a];
    const int* fromB = &pairIndex_[n_ * o.b];
    for (int k = 0; k < n_; ++k) {
      if (k == o.a || k == o.b) continue;
      const Work& wa = work_[fromA[k]];
      const Work& wb = work_[fromB[k]];
      if (!known(wa) || !known(wb)) continue;
      Vec3 l;
      const double s = crossNorm(wa.h, wb.h, l), e = wa.err + wb.err;
      if (!(e <= limit * s)) {  // the two centres coincide (or nearly): no (usable) line
        ++degenerate;
        continue;
      }
      cand_.push_back({l, s, e, CentreLine{out_.numbers[k], JointId{}}});
    }
    if (w.hasLine) cand_.push_back({w.line, 1.0, w.lineErr, CentreLine{0, jointIds_[w.lineJoint]}});
    // The two lines that fix the centre best: smallest first-order error bound, which for unit
    // lines l, m is (err_l + err_m) / |l x m|; compared by cross-multiplication (no divisions).
    double bestNum = INFINITY, bestDen = 1;
    int bx = -1, by = -1;
    Vec3 bestX = Vec3::Zero();
    for (size_t x = 0; x < cand_.size(); ++x)
      for (size_t y = x + 1; y < cand_.size(); ++y) {
        Vec3 v;
        const double den = crossNorm(cand_[x].line, cand_[y].line, v);
        const double num = cand_[x].err * cand_[y].norm + cand_[y].err * cand_[x].norm;
        if (num * bestDen < bestNum * den) {
          bestNum = num, bestDen = den;
          bx = static_cast<int>(x), by = static_cast<int>(y);
          bestX = v;
        }
      }
    if (!(bestNum <= limit * bestDen)) {
      if (last)
        c.kennedyFailure = cand_.size() + degenerate >= 2 ? KennedyFailure::LinesCoincide
                                                          : KennedyFailure::TooFewLines;
      continue;
    }
    const double best = bestNum / bestDen;
    w.h = bestX / bestDen;
    w.err = best;
    w.found = round;
    c.status = CentreStatus::Kennedy;
    c.lines = {cand_[bx].from, cand_[by].from};
    c.round = round;
    c.kennedyFailure = KennedyFailure::None;
    progress = true;
  }
  return progress;
}

void InstantCentreSolver::velocityCentres(const Kinematics& k) {
  for (Work& w : work_) w.velDetermined = false;
  if (!k.derivativesValid()) return;
  const Eigen::VectorXd& q = k.q();
  const Eigen::VectorXd& dq = k.dq();
  // Each body's twist per radian of the driver, taken at the middle of the drawing: the velocity
  // there over L, and the angular velocity.
  double fastest2 = 0;
  const double invL = 1 / L_;
  for (int t = 0; t < n_; ++t) {
    const int s = sysIndex_[t];
    if (s < 0) {
      twist_[t].setZero();
      continue;
    }
    const double w = dq[3 * s + 2];
    const Vec2 v =
        Vec2(dq[3 * s], dq[3 * s + 1]) + w * perp(centre_ - Vec2(q[3 * s], q[3 * s + 1]));
    twist_[t] = Vec3(v.x() * invL, v.y() * invL, w);
    fastest2 = std::max(fastest2, twist_[t].squaredNorm());
  }
  const double fastest = std::sqrt(fastest2), invFastest = 1 / fastest;
  for (int a = 0; a < n_; ++a)
    for (int b = a + 1; b < n_; ++b) {
      Work& w = work_[pairIndex_[n_ * a + b]];
      if (w.across) continue;  // twists in two frames: no centre to find
      const Vec3 rel = twist_[b] - twist_[a];
      // v + omega perp(P - centre) = 0 at P = centre + perp(v) / omega: in homogeneous
      // coordinates (perp(v) / L, omega), at infinity (perpendicular to v) when omega = 0.
      const Vec3 h(-rel.y(), rel.x(), rel.z());
      const double norm = h.norm();
      if (!(norm > CentreTolerances::noMotion * fastest)) continue;
      w.vel = h * (1 / norm);
      w.velNorm = norm * invFastest;
      w.velDetermined = true;
    }
}

void InstantCentreSolver::finish() {
  out_.disagreements.clear();
  for (int p = 0; p < static_cast<int>(work_.size()); ++p) {
    const Work& w = work_[p];
    InstantCentre& c = out_.centres[p];
    c.velocityDetermined = w.velDetermined;
    c.fromVelocity = w.velDetermined ? toPublic(w.vel) : Vec3::Zero();
    c.checked = false;
    c.euclidean = false;
    c.difference = c.tolerance = 0;
    if (w.found >= 0) {
      c.determined = true;
      c.h = w.exact ? w.mm : toPublic(w.h);
      c.errorBound = w.err;
    } else {
      // Rigidly joined (Primary), or not found by Kennedy: the velocities' centre, if any.
      c.determined = !w.rigid && w.velDetermined;
      c.h = c.determined ? c.fromVelocity : Vec3::Zero();
      continue;
    }
    if (!w.velDetermined) continue;
    // Both derivations are known to first order within these bounds; the check reports what
    // exceeds 1e-9 (or their bounds, where a slow relative motion makes the velocities' centre
    // less sharp than that).
    const double tol = std::max(CentreTolerances::check,
                                CentreTolerances::inputAccuracy * (w.err + 1 / w.velNorm));
    c.checked = true;
    if (c.h.z() != 0 && c.fromVelocity.z() != 0) {
      const Vec2 a = c.point(), b(c.fromVelocity.x(), c.fromVelocity.y());
      const double r2 = std::max((a - centre_).squaredNorm(), (b - centre_).squaredNorm());
      c.euclidean = true;
      c.difference = (a - b).norm();
      c.tolerance = tol * L_ * std::max(1.0, r2 / (L_ * L_));  // far centres: less sharp
    } else {
      c.difference = chordal(w.h, w.vel);
      c.tolerance = tol;
    }
    if (c.difference > c.tolerance)
      out_.disagreements.push_back({c.i, c.j, c.euclidean, c.difference, c.tolerance});
  }
}

const InstantCentres& InstantCentreSolver::compute(const Kinematics& k) {
  if (n_ == 0 || !out_.status.ok()) return out_;
  if (!k.valid() || k.revision() != revision_) {
    // Loud: the numbering, the joints and the body frames prepared are another mechanism's.
    out_.status = Status::badModel(
        "the kinematics hold another mechanism (or another revision of it) than "
        "the one prepared: call prepare() again");
    out_.centres.clear();
    out_.disagreements.clear();
    n_ = 0;
    return out_;
  }
  const System& sys = internal::system(k);
  out_.crankDeg = k.crankDeg();
  out_.velocitiesValid = k.derivativesValid();
  const Eigen::VectorXd& q = k.q();
  for (int s = 0; s < sys.nBodies; ++s) {
    origin_[s + 1] = Vec2(q[3 * s], q[3 * s + 1]);
    cos_[s + 1] = std::cos(q[3 * s + 2]);
    sin_[s + 1] = std::sin(q[3 * s + 2]);
  }
  poseLines(k);
  primaryCentres();
  kennedy();
  velocityCentres(k);
  finish();
  return out_;
}

InstantCentres computeInstantCentres(const Kinematics& k) {
  InstantCentreSolver solver;
  if (Status s = solver.prepare(k); !s.ok()) return solver.result();
  return solver.compute(k);
}

}  // namespace linkage
