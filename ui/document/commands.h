// Every edit of a document is one undo step that puts back exactly what was there: the design,
// the solver's pose and assembly branch, and what the solver said (DocumentState).
#pragma once

#include <QUndoCommand>
#include <optional>

#include "document/document.h"

namespace linkage::ui {

class EditCommand : public QUndoCommand {
 public:
  // An edit to make: its first redo (when pushed) sets the design and re-solves it.
  EditCommand(Document* doc, const QString& text, Mechanism next);
  // An edit already made live (a drag): before and after are known; redo puts `after` back.
  EditCommand(Document* doc, const QString& text, DocumentState before, DocumentState after);
  void undo() override;
  void redo() override;

 private:
  Document* doc_;
  DocumentState before_;
  std::optional<Mechanism> next_;
  std::optional<DocumentState> after_;
  bool applied_ = false;  // the live edit's first redo changes nothing
};

// Pushes an edit of the design onto the document's undo stack (and so makes it).
void editDesign(Document* doc, const QString& text, Mechanism next);

}  // namespace linkage::ui
