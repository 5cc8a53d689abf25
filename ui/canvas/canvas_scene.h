// The mechanism on the canvas: one item per body and per joint symbol, built from the solver's
// paint list (linkage/drawing.h) when the design changes and only moved when the pose changes.
// Overlays (instant centres, traced paths) are computed only while they are shown; others
// (the forces', the design's) are added by their folders and follow redrawn().
#pragma once

#include <QGraphicsScene>
#include <QPointer>
#include <map>
#include <vector>

#include "canvas/body_item.h"
#include "canvas/centres_item.h"
#include "canvas/chain_item.h"
#include "canvas/driver_item.h"
#include "canvas/output_item.h"
#include "canvas/slot_warnings.h"
#include "document/document.h"
#include "draw/canvas_item.h"
#include "elements/block_item.h"
#include "elements/pin_item.h"
#include "linkage/drawing.h"
#include "linkage/mechanisms.h"
#include "linkage/plane_view.h"

namespace linkage::ui {

class CanvasScene : public QGraphicsScene {
  Q_OBJECT

 public:
  explicit CanvasScene(QObject* parent = nullptr);
  ~CanvasScene() override;

  void setDocument(Document* doc);
  Document* document() const { return doc_; }

  // An item drawn over the mechanism that the scene keeps across rebuilds (the tools').
  void addOverlay(QGraphicsItem* item);
  const CanvasContext* context() const { return &ctx_; }
  // A paint begins (`toDevice`: the scene to the device's pixels): the label board is cleared
  // and the output points' names put on it before any overlay's label.
  void startLabels(const QTransform& toDevice) const;

  // Millimetres per screen pixel: symbols are rebuilt to keep their size on screen.
  void setPixelSize(double mmPerPx);
  double pixelSize() const { return ctx_.px; }
  void setPalette(const QPalette& p);
  const CanvasStyle& style() const { return ctx_.style; }

  void setCentresVisible(bool on);
  bool centresVisible() const { return centresVisible_; }
  void setTracesVisible(bool on);
  bool tracesVisible() const { return tracesVisible_; }

  // What is drawn now, for tests.
  const Drawing& drawing() const { return drawing_; }
  // What fitting the view shows: the mechanism now and everywhere it goes in a revolution.
  QRectF mechanismRect() const;
  // Where the solver's mechanism goes in a revolution (empty: the solver does not hold it).
  QRectF motionRect() const { return extent_; }
  CentresItem* centresItem() const { return centres_; }
  ChainItem* chainItem() const { return chain_; }
  BodyItem* bodyItem(BodyId id) const;
  // A slot as it is drawn, in its body's frame: its guide in the plane shown (a ground arc seen
  // edge on: the segment it covers); none where it is not drawn.
  std::optional<Guide> drawnSlot(SlotId id) const;

  // The machine's mechanisms as drawn (names, colours, visibility): a hidden one's bodies,
  // joints, outputs, traces and centres are not drawn; a coloured one's bodies are in its colour.
  const std::vector<SubMechanism>& mechanisms() const { return mechanisms_; }
  // Not drawn at full strength and not picked: a hidden mechanism's body, or one of a plane
  // other than the one shown.
  bool bodyHidden(BodyId b) const;

  // A machine in space (linkage/space.h) is edited one plane at a time: the canvas draws the
  // bodies of plane `name` ("" or "drawing": the drawing plane) and the ground in that plane's
  // coordinates (linkage/plane_view.h: the ground projected along its normal, bodies of planes
  // parallel to it seen along it); the bodies of planes that are not parallel, in their own
  // planes' coordinates over these, faint (or not at all, `hideOthers`), and nothing of them
  // is picked. New bodies go into this plane.
  void setShownPlane(const std::string& name);
  const std::string& shownPlane() const { return plane_; }
  // How the solver's positions are mapped into the shown plane (maps nothing when planar).
  const PlaneView& planeView() const { return view_; }
  void setOtherPlanesHidden(bool hide);
  bool otherPlanesHidden() const { return hideOtherPlanes_; }
  // Of the shown plane, or the ground (on every plane), or of a planar machine.
  bool onShownPlane(BodyId b) const;
  // The blocks and pins that leave their slots over a turn (drawn in the warning colour).
  const std::vector<SlotWarning>& slotWarnings() { return doc_ ? warnings_.of(*doc_) : none_; }
  QString slotWarningText() { return doc_ ? warnings_.text(*doc_) : QString(); }

  // What is drawn: the solver's mechanism at its pose, or the design as drawn when the solver
  // cannot take it. Tools place what they make with these.
  bool solverShown() const { return solverShown_; }
  const Mechanism& shownMechanism() const;
  // Canvas coordinates are the shown plane's (x, y).
  Vec2 worldOf(PointId p) const;
  Transform poseOf(BodyId b) const;  // sketch -> world as drawn
  // One item per symbol of the drawing's joints, in their order.
  const std::vector<JointItem*>& jointItems() const { return joints_; }
  std::vector<BlockItem*> blockItems() const { return itemsOf<BlockItem>(); }
  std::vector<PinItem*> pinItems() const { return itemsOf<PinItem>(); }
  const std::vector<OutputItem*>& outputItems() const { return outputs_; }
  // Traced path of each output point (scene coordinates), in the order of the outputs.
  const std::vector<QGraphicsPathItem*>& traceItems() const { return traces_; }

 Q_SIGNALS:
  // Emitted after the items moved (a new pose or design): the overlays that other folders add
  // follow (forces/forces_overlay.h).
  void redrawn();

 private:
  void rebuild();
  // The scale or the palette changed: every item made again for it.
  void restyleItems();
  void updatePose();
  void updateTraces();
  void updateFlags();
  std::vector<Drawing::Centre> determinedCentres(const Kinematics& k) const;
  void clearItems();
  void applyMechanisms();
  // The bodies, joints and outputs of the other planes faint or hidden (after applyMechanisms).
  void applyPlanes();

  QPointer<Document> doc_;
  CanvasContext ctx_;
  Drawing drawing_;
  QRectF extent_;
  bool solverShown_ = false;
  template <class T>
  std::vector<T*> itemsOf() const {
    std::vector<T*> out;
    for (JointItem* j : joints_)
      if (auto* t = dynamic_cast<T*>(j)) out.push_back(t);
    return out;
  }

  std::vector<SubMechanism> mechanisms_;
  std::vector<BodyId> hidden_;
  std::vector<BodyId> offPlane_;
  std::string plane_;
  PlaneView view_;
  bool hideOtherPlanes_ = false;
  SlotWarnings warnings_;
  const std::vector<SlotWarning> none_;
  std::vector<BodyItem*> bodies_;
  std::vector<JointItem*> joints_;
  std::vector<OutputItem*> outputs_;
  std::vector<QGraphicsPathItem*> traces_;
  DriverItem* driver_ = nullptr;
  CentresItem* centres_ = nullptr;
  ChainItem* chain_ = nullptr;
  std::vector<QGraphicsItem*> overlays_;
  bool centresVisible_ = false, tracesVisible_ = false;
  std::vector<QMetaObject::Connection> connections_;
};

}  // namespace linkage::ui
