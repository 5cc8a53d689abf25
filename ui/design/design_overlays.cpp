#include "design/design_overlays.h"

#include "canvas/canvas_scene.h"
#include "design/design_choices.h"
#include "design/extremes_item.h"
#include "design/extremes_notes.h"
#include "design/transmission_item.h"
#include "document/document.h"

namespace linkage::ui {

namespace {
// Above the traced paths (-10), under the frame (-5) and the bodies: ghosts behind the
// mechanism; their marks and values, and the arcs, over everything but the instant centres.
constexpr double kExtremesZ = -8, kNotesZ = 94, kTransmissionZ = 95;
}  // namespace

DesignOverlays::DesignOverlays(CanvasScene* scene, DesignChoices* choices, QObject* parent)
    : QObject(parent), choices_(choices) {
  extremes_ = new ExtremesItem(scene->context());
  extremes_->setZValue(kExtremesZ);
  extremes_->setVisible(false);
  scene->addOverlay(extremes_);
  notes_ = new ExtremesNotes(scene->context(), extremes_);
  notes_->setZValue(kNotesZ);
  notes_->setVisible(false);
  extremes_->setNotes(notes_);
  scene->addOverlay(notes_);
  transmission_ = new TransmissionItem(scene->context());
  transmission_->setZValue(kTransmissionZ);
  transmission_->setVisible(false);
  transmission_->setBand(choices_->band());
  scene->addOverlay(transmission_);
  connect(choices_, &DesignChoices::subjectChanged, this, &DesignOverlays::updateExtremes);
  connect(choices_, &DesignChoices::bandChanged, this,
          [this] { transmission_->setBand(choices_->band()); });
}

void DesignOverlays::setDocument(Document* doc) {
  delete docContext_;
  docContext_ = nullptr;
  doc_ = doc;
  if (doc_) {
    docContext_ = new QObject(this);
    connect(doc_, &Document::designChanged, docContext_, [this] {
      updateExtremes();
      updateJoints();
    });
    connect(doc_, &Document::poseChanged, docContext_, [this] { updateArcs(); });
  }
  updateExtremes();
  updateJoints();
}

void DesignOverlays::setExtremesVisible(bool on) {
  if (on == extremesOn_) return;
  extremesOn_ = on;
  extremes_->setVisible(on);
  notes_->setVisible(on);
  updateExtremes();
}

void DesignOverlays::setTransmissionVisible(bool on) {
  if (on == transmissionOn_) return;
  transmissionOn_ = on;
  transmission_->setVisible(on);
  updateJoints();
}

void DesignOverlays::updateExtremes() {
  const bool solved = doc_ && doc_->solved();
  const std::optional<LimitMeasure> what =
      solved ? choices_->measure(doc_->design()) : std::nullopt;
  if (!extremesOn_ || !what) {
    extremes_->clear();
    return;
  }
  ++searches_;
  extremes_->setPoses(findExtremePoses(doc_->kinematics(), *what));
}

void DesignOverlays::updateJoints() {
  const bool solved = doc_ && doc_->solved();
  transmission_->setJoints(transmissionOn_ && solved
                               ? transmissionJoints(doc_->kinematics().mechanism())
                               : std::vector<TransmissionJoint>{});
  updateArcs();
}

void DesignOverlays::updateArcs() {
  if (!transmissionOn_ || transmission_->joints().empty()) return;
  ++arcUpdates_;
  transmission_->setPose(doc_->kinematics());
}

}  // namespace linkage::ui
