// Kinematics: the public face of KinematicsState. Loads and edits are made on a new state and
// take its place only when they succeed, so that a failure leaves the last good state whole.
#include "linkage/kinematics.h"
#include "linkage/space.h"

#include <atomic>
#include <cmath>

#include "kinematics/kinematics_state.h"
#include "linkage/elements.h"

namespace linkage {

namespace {

constexpr double kDeg = M_PI / 180.0;
const Vec2 kNaN2 = Vec2::Constant(NAN);

std::uint64_t newRevision() {
  static std::atomic<std::uint64_t> next{1};
  return next++;
}

}  // namespace

const KinematicsState& internal::state(const Kinematics& k) {
  return *k.d_;
}

Kinematics::Kinematics(KinematicsOptions opt) : d_(std::make_unique<KinematicsState>(opt)) {}
Kinematics::~Kinematics() = default;
Kinematics::Kinematics(const Kinematics& o) : d_(std::make_unique<KinematicsState>(*o.d_)) {}
Kinematics& Kinematics::operator=(const Kinematics& o) {
  if (this != &o) d_ = std::make_unique<KinematicsState>(*o.d_);
  return *this;
}
// A moved-from Kinematics holds nothing (valid() is false) but stays usable.
Kinematics::Kinematics(Kinematics&& o) : d_(std::move(o.d_)) {
  o.d_ = std::make_unique<KinematicsState>(d_->opt);
}
Kinematics& Kinematics::operator=(Kinematics&& o) {
  std::swap(d_, o.d_);
  return *this;
}

Status Kinematics::load(const Mechanism& m) {
  auto next = std::make_unique<KinematicsState>(d_->opt);
  Status s = next->load(m);
  if (!s.ok()) return s;
  next->revision = newRevision();
  d_ = std::move(next);
  return s;
}

Status Kinematics::edit(const Mechanism& m) {
  if (!valid()) return load(m);
  std::vector<BodyId> reshaped;
  const bool dimensionsOnly = sameTopology(d_->mech, m, reshaped);
  if (dimensionsOnly &&
      (d_->editInPlace(m, reshaped) || d_->editBlocks(m) || d_->editKeepingAnalysis(m))) {
    d_->revision = newRevision();
    return Status::success();
  }
  auto next = std::make_unique<KinematicsState>(d_->opt);
  Status s = next->editFrom(*d_, m);
  if (!next->valid) return s;
  next->revision = newRevision();
  d_ = std::move(next);
  return s;
}

int Kinematics::lastEditGroups() const {
  return d_->lastEditGroups;
}

Status Kinematics::moveTo(double crankDeg) {
  if (!valid()) return Status::failure(StatusCode::BadModel, "no mechanism is loaded");
  if (!d_->sys.hasDriver)
    return Status::failure(StatusCode::BadModel, "the mechanism has no driver to turn");
  if (!std::isfinite(crankDeg))
    return Status::failure(StatusCode::BadModel, "the crank angle is not a finite number");
  return d_->moveToPhi(d_->sys.startRad + crankDeg * kDeg);
}

Kinematics::DragResult Kinematics::dragTo(PointId p, const Vec2& target) {
  return d_->drag(p, target);
}

Status Kinematics::flipBranch(BodyId id, Mechanism* redrawn) {
  const Body* b = valid() ? d_->mech.body(id) : nullptr;
  if (!b) return Status::badModel(valid() ? "unknown body" : "no mechanism is loaded");
  if (b->ground) return Status::badModel("the ground does not move: it has no assembly to flip");
  const int group = d_->plan ? d_->plan->groupOfBody(d_->sys.bodyIndex(id)) : -1;
  return d_->flip(group, "body '" + b->name + "'", redrawn);
}

Status Kinematics::flipBranch(JointId id, Mechanism* redrawn) {
  const int j = valid() ? d_->mech.jointIndex(id) : -1;
  if (j < 0) return Status::badModel(valid() ? "unknown joint" : "no mechanism is loaded");
  const int group = d_->plan ? d_->plan->groupOfJoint(j) : -1;
  return d_->flip(group, jointName(d_->mech, id), redrawn);
}

std::vector<BodyId> Kinematics::flippableBodies() const {
  return d_->flippableBodies();
}

bool Kinematics::valid() const {
  return d_->valid;
}
std::uint64_t Kinematics::revision() const {
  return valid() ? d_->revision : 0;
}
double Kinematics::crankDeg() const {
  return valid() ? d_->crankDeg() : NAN;
}
double Kinematics::rpm() const {
  return d_->sys.rpm;
}
void Kinematics::setRpm(double rpm) {
  d_->sys.rpm = rpm;
}
double Kinematics::omega() const {
  return rpm() * 2 * M_PI / 60;
}
bool Kinematics::accelerations() const {
  return d_->opt.accelerations;
}

void Kinematics::setAccelerations(bool on) {
  KinematicsState& k = *d_;
  k.opt.accelerations = on;
  if (!on || !k.valid || k.reg.accelerations || !k.plan) return;
  if (k.plan->solve(k.sys, k.reg, k.reg.phi, k.next, true)) {
    k.next.regular = true;
    k.next.coordinates = false;
    std::swap(k.reg, k.next);
  }
}

const Mechanism& Kinematics::mechanism() const {
  return d_->mech;
}

namespace {
StructureReport report(const Structure& s, const Mechanism& m, const System& sys) {
  StructureReport r;
  r.coordinates = s.coordinates;
  r.jointEquations = s.jointEquations;
  r.gruebler = s.gruebler;
  r.rank = s.rank;
  r.mobility = s.mobility;
  r.driverMoves = s.driverMoves;
  r.freeAfterDriver = s.freeAfterDriver;
  for (int j : s.redundantJoints) r.redundantJoints.push_back(m.joints[j].id);
  for (int k : s.freeBodies) r.freeBodies.push_back(sys.bodyIds[k]);
  return r;
}
}  // namespace

StructureReport Kinematics::structure() const {
  return valid() ? report(d_->structure, d_->mech, d_->sys) : StructureReport{};
}

StructureReport analyzeDrawing(const Mechanism& m, Status& status) {
  std::optional<System> sys = compile(m, status);
  if (!sys) return {};
  return report(analyzeStructure(*sys, sketchCoordinates(*sys)), m, *sys);
}

const AssemblyReport& Kinematics::assembly() const {
  return d_->assembly;
}
const std::vector<Note>& Kinematics::notes() const {
  return d_->notes;
}
double Kinematics::size() const {
  return d_->sys.size;
}

bool Kinematics::contains(BodyId id) const {
  return valid() && d_->mech.contains(id);
}
bool Kinematics::contains(PointId id) const {
  return valid() && d_->mech.contains(id);
}
bool Kinematics::contains(SlotId id) const {
  return valid() && d_->mech.contains(id);
}
bool Kinematics::contains(JointId id) const {
  return valid() && d_->mech.contains(id);
}

bool Kinematics::derivativesValid() const {
  return valid() && d_->cur().regular;
}

Vec2 Kinematics::position(PointId p) const {
  const PointLocation* l = valid() ? d_->sys.point(p) : nullptr;
  return l ? d_->cur().of(l->body).pos(l->s) : kNaN2;
}

Vec2 Kinematics::velocity(PointId p) const {
  const PointLocation* l = valid() ? d_->sys.point(p) : nullptr;
  return l ? Vec2(omega() * d_->cur().of(l->body).vel(l->s)) : kNaN2;
}

Vec2 Kinematics::acceleration(PointId p) const {
  const PointLocation* l = valid() ? d_->sys.point(p) : nullptr;
  if (!l || !d_->cur().accelerations) return kNaN2;
  const double w = omega();
  return w * w * d_->cur().of(l->body).acc(l->s);
}

namespace {
// Position, velocity and acceleration of the local point s of body index `body` (-1 ground).
Kinematics::PointMotion motionAt(const KinematicsState& k, double w, int body, const Vec2& s) {
  const auto& cur = k.cur();
  const BodyState& b = cur.of(body);
  const Vec2 g = b.R * s;
  return {b.r + g, w * (b.v + b.w * perp(g)),
          cur.accelerations ? Vec2(w * w * (b.a + b.al * perp(g) - b.w * b.w * g)) : kNaN2};
}
}  // namespace

Kinematics::PointMotion Kinematics::motion(PointId p) const {
  const PointLocation* l = valid() ? d_->sys.point(p) : nullptr;
  if (!l) return {kNaN2, kNaN2, kNaN2};
  return motionAt(*d_, omega(), l->body, l->s);
}

Kinematics::PointMotion3 Kinematics::motionInSpace(PointId p) const {
  const PointLocation* l = valid() ? d_->sys.point(p) : nullptr;
  const Vec3 nan = Vec3::Constant(kNaN2.x());
  if (!l) return {nan, nan, nan};
  if (l->body < 0) {
    const Point* pt = mechanism().point(p);
    return {worldOf(mechanism(), *pt), Vec3::Zero(), Vec3::Zero()};
  }
  const PointMotion m = motion(p);
  const Plane& f = d_->sys.frames[d_->sys.classOf[l->body]];
  const double depth = p.value < d_->sys.pointDepth.size() ? d_->sys.pointDepth[p.value] : 0.0;
  auto lift = [&](const Vec2& v) { return Vec3(v.x() * f.xAxis + v.y() * f.yAxis); };
  return {Vec3(f.origin + lift(m.position) + depth * f.normal()), lift(m.velocity),
          lift(m.acceleration)};
}

Kinematics::PointMotion Kinematics::motionOf(BodyId b, const Vec2& sketch) const {
  if (!valid() || !(b == d_->sys.groundId || d_->sys.bodyIndex(b) >= 0))
    return {kNaN2, kNaN2, kNaN2};
  const int k = d_->sys.bodyIndex(b);
  return motionAt(*d_, omega(), k, k >= 0 ? Vec2(sketch - d_->sys.frameOrigin[k]) : sketch);
}

namespace {
// The state of a body by id: ground (at rest) for the ground's id, nullptr when unknown.
const BodyState* bodyState(const KinematicsState& k, BodyId b) {
  if (!k.valid) return nullptr;
  if (b == k.sys.groundId) return &k.cur().of(-1);
  const int i = k.sys.bodyIndex(b);
  return i < 0 ? nullptr : &k.cur().of(i);
}
}  // namespace

double Kinematics::bodyAngle(BodyId b) const {
  const BodyState* s = bodyState(*d_, b);
  return s ? s->angle() : NAN;
}

double Kinematics::bodyOmega(BodyId b) const {
  const BodyState* s = bodyState(*d_, b);
  return s ? omega() * s->w : NAN;
}

double Kinematics::bodyAlpha(BodyId b) const {
  const BodyState* s = bodyState(*d_, b);
  return s && d_->cur().accelerations ? omega() * omega() * s->al : NAN;
}

Transform Kinematics::bodyTransform(BodyId b) const {
  const BodyState* s = bodyState(*d_, b);
  if (!s) return Transform{Rot{NAN, NAN}, kNaN2};
  const int i = d_->sys.bodyIndex(b);
  if (i < 0) return Transform{};  // the ground: where it was drawn
  // world = r + R (sketch - frame origin)
  return Transform{s->R, s->r - s->R * d_->sys.frameOrigin[i]};
}

Vec2 Kinematics::toWorld(BodyId b, const Vec2& sketch) const {
  return bodyTransform(b) * sketch;
}

Vec2 Kinematics::toSketch(BodyId b, const Vec2& world) const {
  return bodyTransform(b).inverse(world);
}

Kinematics::Segment Kinematics::slotEnds(SlotId id) const {
  const Slot* s = valid() ? d_->mech.slot(id) : nullptr;
  if (!s) return {kNaN2, kNaN2};
  const Transform T = bodyTransform(s->body);
  return {T * s->p0, T * s->p1};
}

Status Kinematics::checkDetermined(const std::vector<PointId>& points) const {
  const KinematicsState& k = *d_;
  if (!valid()) return Status::failure(StatusCode::BadModel, "no mechanism is loaded");
  for (PointId p : points) {
    const PointLocation* loc = k.sys.point(p);
    if (!loc) return Status::failure(StatusCode::BadModel, "unknown output point");
    if (!k.structure.pointDetermined(k.sys, k.coordinates(k.cur()).q, *loc)) {
      Status s = Status::failure(
          StatusCode::Underconstrained,
          "the motion of " + k.mech.pointLabel(p) +
              " is not determined by the driver: " + std::to_string(k.structure.freeAfterDriver) +
              " degree(s) of freedom remain (bodies " + k.bodyList(k.structure.freeBodies) +
              " can move with the crank held)");
      for (int b : k.structure.freeBodies) s.bodies.push_back(k.sys.bodyIds[b]);
      return s;
    }
  }
  return Status::success();
}

bool Kinematics::closedForm() const {
  return valid() && d_->plan.has_value();
}
bool Kinematics::sparseSolve() const {
  return d_->newton.sparse();
}

const Eigen::VectorXd& Kinematics::q() const {
  return d_->coordinates(d_->cur()).q;
}
const Eigen::VectorXd& Kinematics::dq() const {
  return d_->coordinates(d_->cur()).dq;
}
const Eigen::VectorXd& Kinematics::ddq() const {
  return d_->coordinates(d_->cur()).ddq;
}

}  // namespace linkage
