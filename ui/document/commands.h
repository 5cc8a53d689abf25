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

// An edit drawn on the mechanism as it is shown, at the current crank angle, redrawn at the
// sketch's pose (linkage/edits.h: editAtPose). One undo step, made from `before` (the state
// when the user began, for a drag).
void commitEdit(Document* doc, const QString& text, Mechanism next);
void commitEdit(Document* doc, const QString& text, Mechanism next, const DocumentState& before);

// Puts the group that solves `body` (a dyad) on its other assembly: the mirror closure, at the
// current crank angle, with the design redrawn on the new branch so that the file keeps it.
// One undo step; false with the solver's reason when there is no other assembly to take.
bool flipAssembly(Document* doc, BodyId body, QString* why);

}  // namespace linkage::ui
