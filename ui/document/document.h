// One open mechanism: the design the user edits, the solver that moves it, the file it came from
// and the undo stack of its edits. Views (canvas, docks, plots) observe it through its signals
// and hold ids, never pointers into the solver.
//
// The design and the solution are kept apart on purpose: an edit that leaves the mechanism
// impossible to assemble is still the user's design (kept, saved, undoable), while the solver
// keeps the last good state and the reason it could not take the new one (solveStatus()).
#pragma once

#include <QObject>
#include <QString>
#include <QUndoStack>
#include <optional>

#include "linkage/dynamics.h"
#include "linkage/instant_centres.h"
#include "linkage/kinematics.h"
#include "linkage/model.h"

namespace linkage::ui {

// Everything an undo step puts back: the design, the solver with its pose and assembly branch,
// and what the last solve said. Restoring it re-solves nothing, so an undo is exact.
struct DocumentState {
  Mechanism design;
  Kinematics kinematics;
  Status status;
};

class Document : public QObject {
  Q_OBJECT

 public:
  explicit Document(QObject* parent = nullptr);
  ~Document() override;

  // A new document: a ground body and nothing else, untitled, unmodified.
  void clear();
  // Reads a file; on failure returns false with the reader's message (it names the place) and
  // leaves the document exactly as it was.
  bool open(const QString& path, QString* error);
  // Takes a mechanism read elsewhere; `path` may be empty (untitled), then `title` names it
  // (an example opens untitled, under its name, so that Save asks where to write it).
  void setContents(Mechanism m, const QString& path, const QString& title = QString());
  // Writes the design atomically, keeping the unknown fields of the file it came from.
  bool save(const QString& path, QString* error);

  QString filePath() const { return path_; }
  // The file name without directory, or the title, or "untitled".
  QString displayName() const;
  bool isModified() const { return !undo_.isClean(); }
  QUndoStack* undoStack() { return &undo_; }

  // The design as the user made it (what Save writes).
  const Mechanism& design() const { return state_.design; }
  // The last good solve; its mechanism() is the design when solved() is true.
  const Kinematics& kinematics() const { return state_.kinematics; }
  // Why the design is not the solved one (Ok when it is).
  const Status& solveStatus() const { return state_.status; }
  bool solved() const { return state_.status.ok() && state_.kinematics.valid(); }
  // Ok when the design is solved and the driver determines the motion of every body;
  // otherwise why not: the solve's failure, or Underconstrained naming the bodies free with the
  // crank held (the solver holds them where they are drawn: a motion shown of them, a trace or
  // an animation, would be made up).
  Status motionStatus() const;

  // Replaces the design and re-solves it at the current crank angle (the solver's in-place
  // edit). Used by undo commands; an edit the solver refuses is kept as the design.
  void setDesign(const Mechanism& m);
  DocumentState state() const { return state_; }
  // Puts a state back exactly, then turns it to the crank angle the view was at.
  void restore(const DocumentState& s);

  // Pose. setCrankDeg tracks the motion continuously from where it is; on failure it stays at
  // the last angle reached and the status says why.
  double crankDeg() const;
  Status setCrankDeg(double deg);
  // Moves the mechanism along its freedom so that point p follows `target` as a hand would
  // (the solver's drag: never onto the other assembly branch; stops at a limit position).
  Kinematics::DragResult dragTo(PointId p, const Vec2& target);
  // What the last setCrankDeg or dragTo said (Ok, or why it stopped where it is).
  const Status& poseStatus() const { return poseStatus_; }
  // Only what a view shows is computed: accelerations while a view needs them.
  void setAccelerationsWanted(bool on);

  // Instant centres at the current pose, computed on first request after a change.
  const InstantCentres& instantCentres();
  // Forces at the current pose (linkage/dynamics.h), computed on first request after a change;
  // their status says why there are none (the motion not determined, no driver, a singular
  // pose). A view that shows them says so first: they need the accelerations. Each view asks
  // for itself (`who`), and they are computed while any asks: the window's canvas and an
  // animation's frames draw one document, and one's leaving must not turn off the other's.
  void setForcesWanted(const void* who, bool on);
  const Forces& forces();

 Q_SIGNALS:
  // Another design took this one's place (a file opened, New, an example, a recovery), just
  // before designChanged: what a view chose for the last design (a point to plot) is not this
  // one's.
  void contentsReplaced();
  // The design changed (an edit, an undo, a file): items are rebuilt.
  void designChanged();
  // The pose changed (crank angle): items move.
  void poseChanged();
  // The file path or the modified mark changed.
  void fileStateChanged();
  // The design was written to its file (what is on disk now is this document's).
  void saved();

 private:
  void replace(DocumentState s, const QString& path, const QString& title);
  void applyWants();

  DocumentState state_;
  QString path_, title_;
  Status poseStatus_;
  bool wantAccelerations_ = true;
  QUndoStack undo_;
  InstantCentreSolver icSolver_;
  std::uint64_t icRevision_ = 0;
  double icCrankDeg_ = NAN;
  bool icFresh_ = false;
  std::vector<const void*> forcesWanted_;
  ForceSolver forceSolver_;
  Forces forcesRefused_;  // what forces() gives when the solver cannot prepare
  std::uint64_t forcesRevision_ = 0;
  bool forcesPrepared_ = false, forcesFresh_ = false;
};

}  // namespace linkage::ui
