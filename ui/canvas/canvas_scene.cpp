#include "canvas/canvas_scene.h"

#include <QGraphicsPathItem>
#include <cmath>

#include "canvas/traces.h"
#include "document/document.h"
#include "elements/element_ui.h"
#include "linkage/elements.h"

namespace linkage::ui {

namespace {

// Z order, bottom to top.
constexpr double kTraceZ = -10, kGroundZ = -5, kBodyZ = 0, kDriverZ = 35, kOutputZ = 40;

// A ground slot that the view sees edge on (an arc in a plane square to the chosen one: its
// points there on one line): the segment it covers, its curve's samples seen along the normal;
// none when it is seen end on.
std::optional<Guide> edgeOn(const Slot& s, const PlaneView& view) {
  std::vector<Vec2> seen;
  for (const Vec3& w : slotCurveInWorld(s)) seen.push_back(view.worldInView(w));
  // On a line: the farthest from any one is an end, the farthest from that the other.
  auto farthest = [&](const Vec2& from) {
    return *std::max_element(seen.begin(), seen.end(), [&](const Vec2& a, const Vec2& b) {
      return (a - from).squaredNorm() < (b - from).squaredNorm();
    });
  };
  Slot line = s;
  line.mid.reset();
  line.p0 = farthest(seen.front());
  line.p1 = farthest(line.p0);
  return guideOf(line);
}

// The body's shapes as the view sees them (`seen`: view.seen() of the mechanism `m`).
BodyGeometry geometryOf(const Mechanism& m, const PlaneView& view, const Drawing::Body& b) {
  const Mechanism& seen = view.seen(m);
  BodyGeometry g;
  g.body = b;
  for (const Slot& s : seen.slots) {
    if (s.body != b.id) continue;
    std::optional<Guide> guide = guideOf(s);
    if (!guide && b.shape == Drawing::Shape::Ground && !view.mapsNothing())
      guide = edgeOn(*m.slot(s.id), view);
    if (!guide) continue;
    g.slots.push_back(*guide);
    g.slotIds.push_back(s.id);
  }
  for (const Point& p : seen.points)
    if (p.body == b.id) g.points.push_back(p.pos);
  return g;
}

// An item restyled, then its children as they are after it: its rebuild may have made them
// anew (the clearance marks' labels), so a list of them taken before would name deleted items.
void restyleTree(QGraphicsItem* item) {
  if (auto* c = dynamic_cast<CanvasItem*>(item)) c->restyle();
  const QList<QGraphicsItem*> children = item->childItems();
  for (QGraphicsItem* child : children) restyleTree(child);
}

}  // namespace

CanvasScene::CanvasScene(QObject* parent) : QGraphicsScene(parent) {
  // Items move every frame: no spatial index to keep up to date.
  setItemIndexMethod(NoIndex);
  // Room to pan anywhere a mechanism could be drawn (mm).
  setSceneRect(-1e6, -1e6, 2e6, 2e6);
  ctx_.style = CanvasStyle::fromPalette(QPalette());
  ctx_.view = &view_;
  addOverlay(new LabelStart([this](const QTransform& t) { startLabels(t); }));
  centres_ = new CentresItem(&ctx_);
  centres_->setVisible(false);
  addItem(centres_);
  chain_ = new ChainItem(&ctx_);
  addItem(chain_);
}

CanvasScene::~CanvasScene() = default;

void CanvasScene::setDocument(Document* doc) {
  for (auto& c : connections_) disconnect(c);
  connections_.clear();
  doc_ = doc;
  if (doc_) {
    connections_.push_back(connect(doc_, &Document::designChanged, this, &CanvasScene::rebuild));
    connections_.push_back(connect(doc_, &Document::poseChanged, this, &CanvasScene::updatePose));
  }
  rebuild();
}

void CanvasScene::addOverlay(QGraphicsItem* item) {
  overlays_.push_back(item);
  addItem(item);
}

void CanvasScene::restyleItems() {
  // The top-level items first collected (an item's rebuild replaces only its own children),
  // each then restyled with what it holds after: never items() of all levels, taken before.
  QList<QGraphicsItem*> top;
  for (QGraphicsItem* i : items())
    if (!i->parentItem()) top.append(i);
  for (QGraphicsItem* i : top) restyleTree(i);
}

void CanvasScene::setPixelSize(double mmPerPx) {
  if (!(mmPerPx > 0) || mmPerPx == ctx_.px) return;
  ctx_.px = mmPerPx;
  restyleItems();
}

void CanvasScene::setPalette(const QPalette& p) {
  ctx_.style = CanvasStyle::fromPalette(p);
  setBackgroundBrush(ctx_.style.paper);
  restyleItems();
  for (QGraphicsPathItem* t : traces_) {
    QPen pen(ctx_.style.trace, 1.2, Qt::DashLine);
    pen.setCosmetic(true);
    t->setPen(pen);
  }
}

void CanvasScene::setCentresVisible(bool on) {
  if (on == centresVisible_) return;
  centresVisible_ = on;
  centres_->setVisible(on);
  updatePose();
}

void CanvasScene::setTracesVisible(bool on) {
  if (on == tracesVisible_) return;
  tracesVisible_ = on;
  updateTraces();
}

const Mechanism& CanvasScene::shownMechanism() const {
  static const Mechanism none;
  if (!doc_) return none;
  return solverShown_ ? doc_->kinematics().mechanism() : doc_->design();
}

Vec2 CanvasScene::worldOf(PointId p) const {
  if (solverShown_ && doc_->kinematics().contains(p)) return view_.point(doc_->kinematics(), p);
  return doc_ ? view_.sketchPoint(doc_->design(), p) : Vec2(NAN, NAN);
}

Transform CanvasScene::poseOf(BodyId b) const {
  if (solverShown_ && doc_->kinematics().contains(b)) return view_.pose(doc_->kinematics(), b);
  return view_.sketchPose(b);
}

BodyItem* CanvasScene::bodyItem(BodyId id) const {
  for (BodyItem* b : bodies_)
    if (b->id() == id) return b;
  return nullptr;
}

std::optional<Guide> CanvasScene::drawnSlot(SlotId id) const {
  const Slot* slot = shownMechanism().slot(id);
  const BodyItem* b = slot ? bodyItem(slot->body) : nullptr;
  if (!b) return std::nullopt;
  const BodyGeometry& g = b->geometry();
  for (size_t i = 0; i < g.slotIds.size() && i < g.slots.size(); ++i)
    if (g.slotIds[i] == id) return g.slots[i];
  return std::nullopt;
}

QRectF CanvasScene::mechanismRect() const {
  if (drawing_.bodies.empty()) return QRectF();
  QRectF r(toQt(drawing_.min), toQt(drawing_.max));
  r = r.normalized().united(extent_);
  for (const QGraphicsPathItem* t : traces_) r = r.united(t->path().boundingRect());
  return r;
}

void CanvasScene::clearItems() {
  // Top-level items only, collected first: deleting one deletes its children (labels), which
  // items() also lists.
  QList<QGraphicsItem*> doomed;
  for (QGraphicsItem* i : items())
    if (i != centres_ && i != chain_ && !i->parentItem() &&
        std::find(overlays_.begin(), overlays_.end(), i) == overlays_.end())
      doomed.append(i);
  for (QGraphicsItem* i : doomed) {
    removeItem(i);
    delete i;
  }
  bodies_.clear();
  joints_.clear();
  outputs_.clear();
  traces_.clear();
  driver_ = nullptr;
}

void CanvasScene::rebuild() {
  clearItems();
  drawing_ = Drawing{};
  view_ = PlaneView();
  if (!doc_) return;
  const Kinematics& k = doc_->kinematics();
  // The solver's pose when it holds this design (or the last good state of an edit of its
  // dimensions it refused); otherwise the design as drawn (one the solver cannot take yet).
  std::vector<BodyId> reshaped;
  solverShown_ =
      k.valid() && (doc_->solved() || sameTopology(doc_->design(), k.mechanism(), reshaped));
  view_ = PlaneView(shownMechanism(), plane_);
  drawing_ =
      solverShown_ ? describeDrawing(k, nullptr, &view_) : describeSketch(doc_->design(), &view_);
  const Mechanism& m = shownMechanism();
  std::map<BodyId, int> number;
  for (const Drawing::Body& b : drawing_.bodies) {
    number[b.id] = b.number;
    auto* item = new BodyItem(&ctx_, geometryOf(m, view_, b));
    item->setZValue(b.shape == Drawing::Shape::Ground ? kGroundZ : kBodyZ + bodies_.size() * 0.01);
    addItem(item);
    bodies_.push_back(item);
  }
  // Each joint as its kind draws it (ui/elements/element_ui.h).
  for (const JointSymbol& sym : drawing_.joints) {
    JointItem* item = elementUi(sym.type).item(&ctx_, sym, drawing_);
    item->setToolTip(QString::fromStdString(jointName(m, sym.joint)));
    item->place(sym);
    addItem(item);
    joints_.push_back(item);
  }
  for (const Drawing::Driver& d : drawing_.drivers) {
    // The design's speed (the solver's may be that of the last design it could solve).
    const QString tip =
        QStringLiteral("driver: %1 rpm %2")
            .arg(doc_->design().driver ? doc_->design().driver->rpm : k.rpm())
            .arg(d.ccw ? QStringLiteral("counter-clockwise") : QStringLiteral("clockwise"));
    driver_ = new DriverItem(&ctx_, d.ccw, tip);
    driver_->setZValue(kDriverZ);
    addItem(driver_);
  }
  for (const Drawing::Output& o : drawing_.outputs) {
    auto* item = new OutputItem(&ctx_, o.point, QString::fromStdString(o.label));
    item->setZValue(kOutputZ);
    addItem(item);
    outputs_.push_back(item);
  }
  applyMechanisms();
  extent_ = QRectF();
  if (solverShown_) {
    const auto [lo, hi] = motionExtent(k, view_);
    extent_ = QRectF(toQt(lo), toQt(hi)).normalized();
  }
  updateTraces();
  updatePose();
}

bool CanvasScene::bodyHidden(BodyId b) const {
  return std::find(hidden_.begin(), hidden_.end(), b) != hidden_.end() ||
         std::find(offPlane_.begin(), offPlane_.end(), b) != offPlane_.end();
}

void CanvasScene::setShownPlane(const std::string& name) {
  const std::string plane = name == "drawing" ? std::string() : name;
  if (plane == plane_) return;
  plane_ = plane;
  // Every position is another plane's: the items made again (the overlays mapped anew).
  rebuild();
  restyleItems();
}

void CanvasScene::setOtherPlanesHidden(bool hide) {
  if (hide == hideOtherPlanes_) return;
  hideOtherPlanes_ = hide;
  applyMechanisms();
}

bool CanvasScene::onShownPlane(BodyId id) const {
  const Body* b = shownMechanism().body(id);
  return !b || b->ground || b->plane == plane_ || (b->plane == "drawing" && plane_.empty());
}

void CanvasScene::applyPlanes() {
  const Mechanism& m = shownMechanism();
  offPlane_.clear();
  for (const Body& b : m.bodies)
    if (!onShownPlane(b.id)) offPlane_.push_back(b.id);
  // A joint is of the plane when a body it joins is (a ball rod from it to another plane is).
  auto jointOff = [&](JointId id) {
    const Joint* j = m.joint(id);
    if (!j || offPlane_.empty()) return false;
    bool anyMoving = false;
    for (PointId p : {j->a, j->b})
      if (const Point* q = m.point(p)) {
        if (onShownPlane(q->body) && !m.body(q->body)->ground) return false;
        anyMoving = anyMoving || !m.body(q->body)->ground;
      }
    if (const Slot* sl = m.slot(j->slot); sl && onShownPlane(sl->body) && !m.body(sl->body)->ground)
      return false;
    return anyMoving;
  };
  auto fade = [this](QGraphicsItem* item, bool off) {
    if (off && hideOtherPlanes_) item->setVisible(false);
    item->setOpacity(off ? 0.18 : 1.0);
    item->setEnabled(!off);
  };
  for (BodyItem* b : bodies_) fade(b, !onShownPlane(b->id()));
  for (JointItem* j : joints_) fade(j, jointOff(j->joint()));
  // The ground's slots that only other planes' bodies run in, faint as those bodies are.
  std::vector<SlotId> faint;
  for (const Slot& sl : m.slots) {
    if (!m.body(sl.body) || !m.body(sl.body)->ground) continue;
    bool used = false, off = true;
    for (const Joint& j : m.joints)
      if (j.slot == sl.id) used = true, off = off && jointOff(j.id);
    if (used && off) faint.push_back(sl.id);
  }
  for (BodyItem* b : bodies_)
    if (m.body(b->id()) && m.body(b->id())->ground) b->setFaintSlots(faint);
  for (OutputItem* o : outputs_) {
    const Point* p = m.point(o->point());
    fade(o, p && !onShownPlane(p->body));
  }
  if (driver_ && m.driver) fade(driver_, jointOff(m.driver->joint));
}

void CanvasScene::applyMechanisms() {
  const Mechanism& m = shownMechanism();
  mechanisms_ = subMechanisms(m);
  hidden_.clear();
  offPlane_.clear();  // the mechanisms' visibility first; applyPlanes() then fades the planes
  std::vector<JointId> hiddenJoints;
  for (const SubMechanism& s : mechanisms_)
    if (s.hidden) {
      hidden_.insert(hidden_.end(), s.bodies.begin(), s.bodies.end());
      hiddenJoints.insert(hiddenJoints.end(), s.joints.begin(), s.joints.end());
    }
  auto jointHidden = [&](JointId j) {
    return std::find(hiddenJoints.begin(), hiddenJoints.end(), j) != hiddenJoints.end();
  };
  // A coloured mechanism's colour; invalid: each body its own.
  auto colourOf = [&](BodyId b) {
    const int k = subMechanismOf(mechanisms_, b);
    return k >= 0 && !mechanisms_[k].colour.empty()
               ? QColor(QString::fromStdString(mechanisms_[k].colour))
               : QColor();
  };
  for (BodyItem* b : bodies_) {
    b->setVisible(!bodyHidden(b->id()));
    b->setColour(colourOf(b->id()));
  }
  for (JointItem* j : joints_) {
    j->setVisible(!jointHidden(j->joint()));
    j->setBodyColours(colourOf);
  }
  for (OutputItem* o : outputs_) {
    const Point* p = m.point(o->point());
    o->setVisible(!p || !bodyHidden(p->body));
  }
  if (driver_ && m.driver) driver_->setVisible(!jointHidden(m.driver->joint));
  applyPlanes();
}

void CanvasScene::updatePose() {
  if (!doc_) return;
  if (!solverShown_) {
    // The sketch of a design the solver cannot take: no overlay of the solver's last state.
    centres_->setCentres({});
    updateFlags();
    emit redrawn();
    return;
  }
  const Kinematics& k = doc_->kinematics();
  // The solver's pose is drawn also while it keeps the last good state of a refused edit of
  // the same shape; its centres are of that other design, not of this one: none.
  const InstantCentres* ics = centresVisible_ && doc_->solved() ? &doc_->instantCentres() : nullptr;
  if (!updateDrawing(drawing_, k, ics, &view_)) {
    rebuild();  // the solver holds another revision: the items are out of date
    return;
  }
  for (size_t i = 0; i < bodies_.size(); ++i) bodies_[i]->setPose(drawing_.bodies[i].pose);
  for (size_t i = 0; i < joints_.size(); ++i) joints_[i]->place(drawing_.joints[i]);
  if (driver_ && !drawing_.drivers.empty()) driver_->setAt(drawing_.drivers[0].at);
  for (size_t i = 0; i < outputs_.size(); ++i) outputs_[i]->setAt(drawing_.outputs[i].at);
  centres_->setCentres(ics ? determinedCentres(k) : std::vector<Drawing::Centre>{});
  updateFlags();
  emit redrawn();
}

std::vector<Drawing::Centre> CanvasScene::determinedCentres(const Kinematics& k) const {
  // A body free with the crank held has no centre the driver determines: none is drawn.
  std::vector<BodyId> free = k.structure().freeBodies;
  // Nor of a hidden mechanism's bodies.
  free.insert(free.end(), hidden_.begin(), hidden_.end());
  if (free.empty()) return drawing_.centres;
  std::vector<int> numbers;
  for (const Drawing::Body& b : drawing_.bodies)
    if (std::find(free.begin(), free.end(), b.id) != free.end()) numbers.push_back(b.number);
  auto held = [&](int n) { return std::find(numbers.begin(), numbers.end(), n) != numbers.end(); };
  std::vector<Drawing::Centre> out;
  for (const Drawing::Centre& c : drawing_.centres)
    if (!held(c.i) && !held(c.j)) out.push_back(c);
  return out;
}

void CanvasScene::updateFlags() {
  // The joints and bodies a failure names: an edit the solver refused, or a position the
  // motion cannot pass (a change point). A limit position is not a failure.
  const Status& s = doc_->solveStatus();
  const Status& pose = doc_->poseStatus();
  const bool poseFailed =
      pose.code == StatusCode::Singular || pose.code == StatusCode::NotConverged;
  // And what the structure analysis names: redundant joints, bodies free with the crank held.
  StructureReport structure;
  if (solverShown_) structure = doc_->kinematics().structure();
  auto listed = [&](JointId j) {
    for (JointId x : structure.redundantJoints)
      if (x == j) return true;
    for (const Status* st : {&s, &pose}) {
      if (st == &pose && !poseFailed) continue;
      for (JointId x : st->joints)
        if (x == j) return true;
      for (const JointGap& g : st->gaps)
        if (g.joint == j) return true;
    }
    return false;
  };
  const std::vector<SlotWarning>& out = slotWarnings();
  auto outOfSlot = [&](JointId j) {
    return std::any_of(out.begin(), out.end(), [&](const SlotWarning& w) { return w.joint == j; });
  };
  for (JointItem* j : joints_) j->setFlagged(listed(j->joint()) || outOfSlot(j->joint()));
  for (BodyItem* b : bodies_) {
    std::vector<SlotId> slots;
    for (const SlotWarning& w : out) slots.push_back(w.slot);
    b->setFlaggedSlots(std::move(slots));
  }
  for (BodyItem* b : bodies_) {
    bool named = false;
    for (BodyId x : s.bodies) named = named || x == b->id();
    for (BodyId x : structure.freeBodies) named = named || x == b->id();
    b->setFlagged(named);
  }
}

void CanvasScene::updateTraces() {
  for (QGraphicsPathItem* t : traces_) {
    removeItem(t);
    delete t;
  }
  traces_.clear();
  // Of the design only when the solver holds it (not the last good state of a refused edit).
  if (!tracesVisible_ || !doc_ || !doc_->solved()) return;
  const Kinematics& k = doc_->kinematics();
  const std::vector<PointId>& outputs = k.mechanism().outputs;
  std::vector<std::vector<Vec2>> paths = tracePaths(k, view_);
  for (size_t i = 0; i < paths.size(); ++i) {
    // A point the driver does not move has no path: it would be the solver's hold, made up.
    std::vector<Vec2>& path = paths[i];
    if (!k.checkDetermined({outputs[i]}).ok()) path.clear();
    if (const Point* p = k.mechanism().point(outputs[i]); p && bodyHidden(p->body)) path.clear();
    QPainterPath pp;
    for (size_t i = 0; i < path.size(); ++i)
      i == 0 ? pp.moveTo(toQt(path[i])) : pp.lineTo(toQt(path[i]));
    QPen pen(ctx_.style.trace, 1.2, Qt::DashLine);
    pen.setCosmetic(true);
    auto* item = addPath(pp, pen);
    item->setZValue(kTraceZ);
    traces_.push_back(item);
  }
}

void CanvasScene::startLabels(const QTransform& toDevice) const {
  ctx_.labels.clear();
  for (const OutputItem* o : outputs_)
    for (const QGraphicsItem* label : o->childItems())
      if (label->isVisible())
        ctx_.labels.take(label->boundingRect().translated(toDevice.map(o->pos())));
}

}  // namespace linkage::ui
