// Edit: undo and redo (the document's undo stack) and the History dock of every edit.
#pragma once

#include "window/window_feature.h"

class QUndoView;

namespace linkage::ui {

class MainWindow;
class WindowLayout;

class EditFeature : public WindowFeature {
 public:
  EditFeature(MainWindow& w, WindowLayout& layout);
  void applyIcons(const QPalette& p) override;

  QAction* undo;
  QAction* redo;
  QDockWidget* historyDock;
  QAction* showHistory;  // the dock's toggle
  QUndoView* history;
};

}  // namespace linkage::ui
