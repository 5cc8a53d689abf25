#include "document/commands.h"

#include <cmath>

#include "linkage/edits.h"

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

void commitEdit(Document* doc, const QString& text, Mechanism next) {
  commitEdit(doc, text, std::move(next), doc->state());
}

void commitEdit(Document* doc, const QString& text, Mechanism next, const DocumentState& before) {
  PoseEdit e = editAtPose(before.kinematics, std::move(next));
  doc->restore(before);
  if (!e.solved) {
    // Refused (or nothing solved yet): the design is kept with the solver's reason.
    editDesign(doc, text, std::move(e.design));
    return;
  }
  DocumentState after{std::move(e.design), std::move(e.kinematics), Status::success()};
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
