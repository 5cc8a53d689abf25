#include "forces/dynamics_marks.h"
#include "linkage/space.h"

#include <cmath>

#include "canvas/body_item.h"
#include "canvas/canvas_scene.h"
#include "document/document.h"
#include "linkage/force_samples.h"

namespace linkage::ui {

namespace {

QString number(double v) {
  return QString::number(v, 'g', 3);
}

bool hasForces(const Mechanism& m) {
  if (!m.loads.empty() || m.gravityWorld().squaredNorm() > 0) return true;
  for (const Body& b : m.bodies)
    if (!b.ground && b.mass && b.mass->kg > 0) return true;
  return false;
}

void addMasses(const CanvasScene& scene, const Mechanism& m, DynamicsMarks& out) {
  for (const Body& b : m.bodies) {
    if (b.ground || !b.mass || !(b.mass->kg > 0) || scene.bodyHidden(b.id)) continue;
    const Transform t = scene.poseOf(b.id);
    DynamicsMarks::Mass mark;
    mark.com = toQt(t * b.mass->com);
    for (const PointMass& c : b.mass->counterweights) {
      mark.counterweights.push_back(toQt(t * c.at));
      mark.counterweightKg.push_back(c.kg);
    }
    out.masses.push_back(std::move(mark));
  }
}

// Where a torque on a body is drawn: its centre of mass, else its first point.
Vec2 torqueAnchor(const CanvasScene& scene, const Mechanism& m, BodyId body) {
  const Body* b = m.body(body);
  if (b && b->mass) return scene.poseOf(body) * b->mass->com;
  for (const Point& p : m.points)
    if (p.body == body) return scene.worldOf(p.id);
  return scene.poseOf(body).t;
}

void addLoads(const CanvasScene& scene, const Mechanism& m, double crankDeg, DynamicsMarks& out) {
  for (const Load& l : m.loads) {
    const Point* p = m.point(l.point);
    if (scene.bodyHidden(p ? p->body : l.body)) continue;  // not drawn: a hidden mechanism's
    DynamicsMarks::Load mark;
    mark.active = l.activeAt(crankDeg);
    mark.torque = !l.point;
    if (mark.torque) {
      mark.at = toQt(torqueAnchor(scene, m, l.body));
      mark.torqueNm = l.torqueNm;
      mark.label = number(l.torqueNm) + QStringLiteral(" N\u00b7m");
    } else {
      mark.at = toQt(scene.worldOf(l.point));
      mark.forceN = QPointF(l.forceN.x(), l.forceN.y());
      mark.label = number(std::hypot(l.forceN.x(), l.forceN.y())) + QStringLiteral(" N");
    }
    if (!mark.active) mark.label += QStringLiteral(" (off)");
    out.loads.push_back(std::move(mark));
  }
}

void addReactions(Document& doc, double mmPerN, DynamicsMarks& out) {
  const Forces& f = doc.forces();
  if (!f.status.ok()) {
    out.legend =
        QStringLiteral("Forces not shown: %1").arg(QString::fromStdString(f.status.message));
    return;
  }
  if (isSpatial(doc.kinematics().mechanism())) {
    // The reactions there have parts out of the canvas's plane, and their points are in each
    // body's plane class: arrows in one plane would show a part of them in the wrong place.
    out.legend = QStringLiteral(
                     "Reactions not drawn on a machine in space (linkage-cli dynamics writes them "
                     "in 3D, the Forces dock plots them in the world's axes); driver torque %1 "
                     "N\u00b7m at %2 rpm")
                     .arg(number(f.driverTorqueNm), QString::number(doc.kinematics().rpm()));
    return;
  }
  out.mmPerN = mmPerN;
  for (size_t j = 0; j < f.joints.size(); ++j) {
    const JointReaction& r = f.joints[j];
    DynamicsMarks::Reaction mark;
    mark.determined = std::isfinite(r.force.x()) && std::isfinite(r.force.y());
    mark.at = toQt(r.at);
    if (mark.determined) mark.forceN = QPointF(r.force.x(), r.force.y());
    if (std::isfinite(r.at.x()) && std::isfinite(r.at.y())) out.reactions.push_back(mark);
  }
  const QString scale = mmPerN > 0
                            ? QStringLiteral("reactions: 10 mm = %1 N").arg(number(10 / mmPerN))
                            : QStringLiteral("reactions: none");
  out.legend = QStringLiteral("%1; driver torque %2 N\u00b7m at %3 rpm")
                   .arg(scale, number(f.driverTorqueNm), QString::number(doc.kinematics().rpm()));
}

}  // namespace

double reactionScale(const Kinematics& k, double extentMm) {
  if (!k.valid() || isSpatial(k.mechanism())) return 0;  // no arrows there (addReactions)
  const ForceSamples s = sampleForces(k, 72);
  double most = 0;
  for (const std::vector<Vec2>& joint : s.reactionN)
    for (const Vec2& f : joint)
      if (std::isfinite(f.x()) && std::isfinite(f.y()))
        most = std::max(most, std::hypot(f.x(), f.y()));
  if (!(most > 0) || !(extentMm > 0)) return 0;
  const double perTen = most / (0.25 * extentMm) * 10;  // N per 10 mm
  // The smallest 1-2-5 step of newtons not under it: arrows at most a quarter of the extent.
  const double decade = std::pow(10.0, std::floor(std::log10(perTen)));
  double step = 10 * decade;
  for (double f : {1.0, 2.0, 5.0})
    if (f * decade >= perTen) {
      step = f * decade;
      break;
    }
  return 10 / step;
}

DynamicsMarks dynamicsMarks(const CanvasScene& scene, Document& doc, bool forces, double mmPerN) {
  DynamicsMarks out;
  const Mechanism& m = scene.shownMechanism();
  addMasses(scene, m, out);
  addLoads(scene, m, doc.crankDeg(), out);
  if (!forces) return out;
  if (!hasForces(doc.design())) {
    out.legend = QStringLiteral(
        "No masses, gravity or loads: every force is zero. Give bodies masses in Properties.");
    return out;
  }
  addReactions(doc, mmPerN, out);
  return out;
}

}  // namespace linkage::ui
