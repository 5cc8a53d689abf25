#include "document/commands.h"

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

}  // namespace linkage::ui
