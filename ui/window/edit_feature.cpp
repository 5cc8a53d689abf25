#include "window/edit_feature.h"

#include <QAction>
#include <QDockWidget>
#include <QUndoStack>
#include <QUndoView>

#include "document/document.h"
#include "window/icons.h"
#include "window/main_window.h"
#include "window/window_layout.h"

namespace linkage::ui {

EditFeature::EditFeature(MainWindow& w, WindowLayout& layout) : WindowFeature(&w) {
  QUndoStack* stack = w.document()->undoStack();
  undo = stack->createUndoAction(&w, tr("&Undo"));
  undo->setObjectName("undo");
  undo->setShortcut(QKeySequence::Undo);
  undo->setStatusTip(tr("Undo the last edit"));
  w.addAction(undo);
  redo = stack->createRedoAction(&w, tr("&Redo"));
  redo->setObjectName("redo");
  redo->setShortcuts({QKeySequence(tr("Ctrl+Shift+Z")), QKeySequence(tr("Ctrl+Y"))});
  redo->setStatusTip(tr("Redo the edit undone last"));
  w.addAction(redo);
  history = new QUndoView;
  history->setEmptyLabel(tr("<opened>"));
  history->setStack(stack);
  historyDock = addDock(&w, "history", tr("History"), history, Qt::LeftDockWidgetArea);
  historyDock->hide();
  showHistory = historyDock->toggleViewAction();
  showHistory->setObjectName("showHistory");
  showHistory->setStatusTip(tr("Show every edit; click one to go back to it"));
  layout.add(Slot::EditUndo, undo);
  layout.add(Slot::EditRedo, redo);
  layout.add(Slot::EditHistory, showHistory);
  layout.add(Slot::FileBarUndo, undo);
  layout.add(Slot::FileBarRedo, redo);
}

void EditFeature::applyIcons(const QPalette& p) {
  undo->setIcon(themedIcon(QStringLiteral("undo"), p));
  redo->setIcon(themedIcon(QStringLiteral("redo"), p));
}

}  // namespace linkage::ui
