// File: new, open (recent files, examples), save, new and close window, quit; Help > About.
// Opening and saving themselves are the window's (main_window_files.cpp).
#pragma once

#include "window/window_feature.h"

class QMenu;

namespace linkage::ui {

class MainWindow;
class WindowLayout;

class FileFeature : public WindowFeature {
 public:
  FileFeature(MainWindow& w, WindowLayout& layout);
  void applyIcons(const QPalette& p) override;
  // Remembers a file opened or saved: first of File > Open Recent, its folder for the dialogs.
  static void addRecent(const QString& path);
  // Where a file was last opened or saved, or empty.

  QAction* newDocument;
  QAction* newWindow;
  QAction* open;
  QAction* save;
  QAction* saveAs;
  QAction* closeWindow;
  QAction* quit;
  QAction* about;
  QMenu* recentMenu;
  QMenu* examplesMenu;

 private:
  void makeActions();
  void fillRecentMenu();
  void fillExamplesMenu();

  MainWindow& w_;
};

}  // namespace linkage::ui
