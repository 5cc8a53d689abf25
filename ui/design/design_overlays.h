// The design overlays of a window's canvas, and when they are computed: the mechanism at its
// extreme positions once per design (and per change of the point followed) while it is shown,
// on a copy of the document's solver; the transmission arcs at every pose while they are
// shown. Off, they compute nothing and draw nothing. Both show the solver's design only: a
// design it cannot take has no motion to check.
#pragma once

#include <QObject>
#include <QPointer>

namespace linkage::ui {

class CanvasScene;
class DesignChoices;
class Document;
class ExtremesItem;
class ExtremesNotes;
class TransmissionItem;

class DesignOverlays : public QObject {
  Q_OBJECT

 public:
  DesignOverlays(CanvasScene* scene, DesignChoices* choices, QObject* parent = nullptr);
  void setDocument(Document* doc);

  void setExtremesVisible(bool on);
  bool extremesVisible() const { return extremesOn_; }
  void setTransmissionVisible(bool on);
  bool transmissionVisible() const { return transmissionOn_; }

  ExtremesItem* extremesItem() const { return extremes_; }
  ExtremesNotes* extremesNotes() const { return notes_; }
  TransmissionItem* transmissionItem() const { return transmission_; }
  // How often each was computed (extreme searches; arc updates), for tests and measurements.
  int extremeSearches() const { return searches_; }
  int transmissionUpdates() const { return arcUpdates_; }

 private:
  void updateExtremes();
  void updateJoints();
  void updateArcs();

  QPointer<Document> doc_;
  DesignChoices* choices_;
  ExtremesItem* extremes_;
  ExtremesNotes* notes_;
  TransmissionItem* transmission_;
  bool extremesOn_ = false, transmissionOn_ = false;
  int searches_ = 0, arcUpdates_ = 0;
  QObject* docContext_ = nullptr;
};

}  // namespace linkage::ui
