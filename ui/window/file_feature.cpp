#include "window/file_feature.h"

#include <QAction>
#include <QApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>

#include "document/document.h"
#include "document/file_folder.h"
#include "linkage/io/model_lookup.h"
#include "window/icons.h"
#include "window/main_window.h"
#include "window/window_layout.h"

namespace linkage::ui {

namespace {
constexpr int kMaxRecent = 10;
const char* kRecentKey = "recentFiles";
}  // namespace

FileFeature::FileFeature(MainWindow& w, WindowLayout& layout) : WindowFeature(&w), w_(w) {
  makeActions();
  layout.add(Slot::FileNew, newDocument);
  layout.add(Slot::FileNewWindow, newWindow);
  layout.add(Slot::FileOpen, open);
  recentMenu = layout.addMenu(Slot::FileRecent, tr("Open &Recent"));
  connect(recentMenu, &QMenu::aboutToShow, this, &FileFeature::fillRecentMenu);
  examplesMenu = layout.addMenu(Slot::FileExamples, tr("&Examples"));
  fillExamplesMenu();
  layout.add(Slot::FileSave, save);
  layout.add(Slot::FileSaveAs, saveAs);
  layout.add(Slot::FileClose, closeWindow);
  layout.add(Slot::FileQuit, quit);
  layout.add(Slot::HelpAbout, about);
  layout.add(Slot::FileBarNew, newDocument);
  layout.add(Slot::FileBarOpen, open);
  layout.add(Slot::FileBarSave, save);
}

void FileFeature::makeActions() {
  MainWindow* w = &w_;
  newDocument = makeAction(w, "new", tr("&New"), QKeySequence::New, tr("Start a new mechanism"));
  connect(newDocument, &QAction::triggered, w, [w] {
    if (w->maybeSave()) w->document()->clear();
  });
  newWindow = makeAction(w, "newWindow", tr("New &Window"), QKeySequence(tr("Ctrl+Shift+N")),
                         tr("Open another window, to compare two mechanisms side by side"));
  connect(newWindow, &QAction::triggered, w, [] { (new MainWindow)->show(); });
  open = makeAction(w, "open", tr("&Open..."), QKeySequence::Open, tr("Open a mechanism file"));
  connect(open, &QAction::triggered, w, [w] {
    if (!w->maybeSave()) return;
    const QString path = QFileDialog::getOpenFileName(
        w, tr("Open Mechanism"), w->fileFolder(),
        tr("Mechanisms (*.linkage.json);;JSON files (*.json);;All files (*)"));
    if (!path.isEmpty()) w->openFile(path);
  });
  save = makeAction(w, "save", tr("&Save"), QKeySequence::Save, tr("Save the mechanism"));
  connect(save, &QAction::triggered, w, &MainWindow::save);
  saveAs = makeAction(w, "saveAs", tr("Save &As..."), QKeySequence(tr("Ctrl+Shift+S")),
                      tr("Save the mechanism under another name"));
  connect(saveAs, &QAction::triggered, w, &MainWindow::saveAs);
  closeWindow = makeAction(w, "closeWindow", tr("&Close Window"), QKeySequence::Close,
                           tr("Close this window"));
  connect(closeWindow, &QAction::triggered, w, &QWidget::close);
  quit = makeAction(w, "quit", tr("&Quit"), QKeySequence::Quit, tr("Close every window"));
  quit->setMenuRole(QAction::QuitRole);
  connect(quit, &QAction::triggered, qApp, &QApplication::closeAllWindows);
  about = makeAction(w, "about", tr("&About Linkage"), QKeySequence(), tr("About this program"));
  connect(about, &QAction::triggered, w, [w] {
    QMessageBox::about(w, tr("About Linkage"),
                       tr("<b>Linkage</b><br>A planar linkage editor with an exact "
                          "kinematic core: positions, velocities and accelerations from "
                          "the constraint Jacobian, instant centres by "
                          "Kennedy-Aronhold."));
  });
}

void FileFeature::applyIcons(const QPalette& p) {
  newDocument->setIcon(themedIcon(QStringLiteral("new"), p));
  open->setIcon(themedIcon(QStringLiteral("open"), p));
  save->setIcon(themedIcon(QStringLiteral("save"), p));
}

void FileFeature::addRecent(const QString& path) {
  setLastFolder(QFileInfo(path).absolutePath());
  QSettings s;
  QStringList files = s.value(kRecentKey).toStringList();
  files.removeAll(path);
  files.prepend(path);
  while (files.size() > kMaxRecent) files.removeLast();
  s.setValue(kRecentKey, files);
}

void FileFeature::fillRecentMenu() {
  recentMenu->clear();
  const QStringList files = QSettings().value(kRecentKey).toStringList();
  MainWindow* w = &w_;
  for (const QString& f : files) {
    QAction* a = recentMenu->addAction(QFileInfo(f).fileName());
    a->setStatusTip(f);
    a->setEnabled(QFileInfo::exists(f));
    connect(a, &QAction::triggered, w, [w, f] {
      if (w->maybeSave()) w->openFile(f);
    });
  }
  if (files.isEmpty()) recentMenu->addAction(tr("(none)"))->setEnabled(false);
  recentMenu->addSeparator();
  connect(recentMenu->addAction(tr("Clear List")), &QAction::triggered, this,
          [] { QSettings().remove(kRecentKey); });
}

void FileFeature::fillExamplesMenu() {
  examplesMenu->clear();
  MainWindow* w = &w_;
  for (const std::string& name : listExamples(QApplication::applicationFilePath().toStdString())) {
    const QString n = QString::fromStdString(name);
    QAction* a = examplesMenu->addAction(n);
    a->setObjectName(QStringLiteral("example:") + n);
    a->setStatusTip(tr("Open the example %1").arg(n));
    connect(a, &QAction::triggered, w, [w, n] {
      if (w->maybeSave()) w->openExample(n);
    });
  }
  if (examplesMenu->isEmpty()) examplesMenu->addAction(tr("(none found)"))->setEnabled(false);
}

}  // namespace linkage::ui
