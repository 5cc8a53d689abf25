#include "document/commands.h"

#include <cmath>

namespace linkage::ui {

EditCommand::EditCommand(Document* doc, const QString& text, Mechanism next)
    : QUndoCommand(text), doc_(doc), before_(doc->state()), next_(std::move(next)) {}

EditCommand::EditCommand(Document* doc, const QString& text, DocumentState before,
                         DocumentState after)
    : QUndoCommand(text),
      doc_(doc),
      before_(std::move(before)),
      after_(std::move(after)),
      applied_(true) {}

void EditCommand::undo() {
  doc_->restore(before_);
}

void EditCommand::redo() {
  if (applied_) {
    applied_ = false;  // pushed after it was made live: nothing to do the first time
    return;
  }
  if (after_) {
    doc_->restore(*after_);
    return;
  }
  doc_->setDesign(*next_);
  after_ = doc_->state();
  next_.reset();
}

void editDesign(Document* doc, const QString& text, Mechanism next) {
  doc->undoStack()->push(new EditCommand(doc, text, std::move(next)));
}

namespace {

void transformBody(Mechanism& m, BodyId b, const Transform& T) {
  for (Point& p : m.points)
    if (p.body == b) p.pos = T * p.pos;
  for (Slot& s : m.slots)
    if (s.body == b) {
      s.p0 = T * s.p0;
      s.p1 = T * s.p1;
    }
}

bool isIdentity(const Transform& T, double size) {
  return std::abs(T.R.s) <= 1e-15 && T.R.c > 0 && T.t.norm() <= 1e-15 * size;
}

// `solved` holds `m` solved at the current pose; redraws m at `k`'s pose.
void redraw(Mechanism& m, const Kinematics& k) {
  for (const Body& b : m.bodies)
    if (!b.ground && k.contains(b.id)) {
      const Transform T = k.bodyTransform(b.id);
      if (!isIdentity(T, k.size())) transformBody(m, b.id, T);
    }
}

}  // namespace

void commitEdit(Document* doc, const QString& text, Mechanism next) {
  commitEdit(doc, text, std::move(next), doc->state());
}

void commitEdit(Document* doc, const QString& text, Mechanism next, const DocumentState& before) {
  // Solved from the pose before the edit (the current one): where the user drew it.
  Kinematics trial = before.kinematics;
  const bool solved = before.kinematics.valid() && trial.edit(next).ok();
  if (solved && next.driver) {
    const double sketchDeg = -next.driver->startDeg;
    if (std::abs(trial.crankDeg() - sketchDeg) > 1e-12) {
      Kinematics atSketch = trial;
      if (atSketch.moveTo(sketchDeg).ok()) {
        redraw(next, atSketch);
      } else {
        // The sketch's pose is out of reach now: the drawing becomes this pose.
        redraw(next, trial);
        next.driver->startDeg = -trial.crankDeg();
      }
      // The same shapes moved rigidly: the solution here does not change.
      if (!trial.edit(next).ok()) {
        doc->restore(before);
        editDesign(doc, text, std::move(next));
        return;
      }
    }
  }
  if (!solved) {
    // Refused (or nothing solved yet): the design is kept with the solver's reason.
    doc->restore(before);
    editDesign(doc, text, std::move(next));
    return;
  }
  DocumentState after{std::move(next), std::move(trial), Status::success()};
  doc->restore(after);
  doc->undoStack()->push(new EditCommand(doc, text, before, doc->state()));
}

bool flipAssembly(Document* doc, BodyId body, QString* why) {
  if (!doc->solved()) {
    if (why) *why = QStringLiteral("the mechanism is not solved");
    return false;
  }
  Kinematics trial = doc->kinematics();
  Mechanism redrawn;
  Status s = trial.flipBranch(body, &redrawn);
  // The solver takes the redrawn design on the branch it is on now (same shapes, same pose).
  if (s.ok()) s = trial.edit(redrawn);
  if (!s.ok()) {
    if (why) *why = QString::fromStdString(s.message);
    return false;
  }
  const DocumentState before = doc->state();
  const Body* b = redrawn.body(body);
  const QString name = b ? QString::fromStdString(b->name) : QString();
  DocumentState after{std::move(redrawn), std::move(trial), Status::success()};
  doc->restore(after);
  doc->undoStack()->push(
      new EditCommand(doc, QObject::tr("Flip the assembly of %1").arg(name), before, doc->state()));
  return true;
}

}  // namespace linkage::ui
