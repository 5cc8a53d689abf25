#include "window/window_layout.h"

#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QToolBar>

namespace linkage::ui {

namespace {

bool isSeparator(Slot s) {
  switch (s) {
    case Slot::FileSeparator1:
    case Slot::FileSeparator2:
    case Slot::EditSeparator1:
    case Slot::EditSeparator2:
    case Slot::ToolsSeparator:
    case Slot::ViewSeparator1:
    case Slot::ViewSeparator2:
    case Slot::AnimationSeparator:
    case Slot::AnalysisSeparator1:
    case Slot::AnalysisSeparator2:
    case Slot::AnalysisSeparator3:
    case Slot::AnalysisSeparator4:
    case Slot::ToolsBarSeparator:
      return true;
    default:
      return false;
  }
}

bool within(Slot s, Slot first, Slot last) {
  return s >= first && s <= last;
}

}  // namespace

WindowLayout::WindowLayout(QMainWindow* w) : QObject(w) {
  QMenuBar* bar = w->menuBar();
  file_ = bar->addMenu(tr("&File"));
  edit_ = bar->addMenu(tr("&Edit"));
  tools_ = bar->addMenu(tr("&Tools"));
  view_ = bar->addMenu(tr("&View"));
  animation_ = bar->addMenu(tr("&Animation"));
  analysis_ = bar->addMenu(tr("A&nalysis"));
  help_ = bar->addMenu(tr("&Help"));
  fileBar_ = w->addToolBar(tr("File"));
  fileBar_->setObjectName("fileToolBar");
  toolsBar_ = new QToolBar(tr("Tools"), w);
  toolsBar_->setObjectName("toolsToolBar");
  w->addToolBar(Qt::LeftToolBarArea, toolsBar_);
  viewBar_ = w->addToolBar(tr("View"));
  viewBar_->setObjectName("viewToolBar");
  animationBar_ = new QToolBar(tr("Animation"), w);
  animationBar_->setObjectName("animationToolBar");
  w->addToolBar(Qt::BottomToolBarArea, animationBar_);
  exports_ = addMenu(Slot::FileExport, tr("E&xport"));
  for (int i = 0; i < static_cast<int>(Slot::Count); ++i) {
    const Slot s = static_cast<Slot>(i);
    if (!isSeparator(s)) continue;
    auto* sep = new QAction(target(s));
    sep->setSeparator(true);
    add(s, sep);
  }
}

QWidget* WindowLayout::target(Slot s) const {
  if (within(s, Slot::FileNew, Slot::FileQuit)) return file_;
  if (within(s, Slot::ExportTable, Slot::ExportTimingTable)) return exports_;
  if (within(s, Slot::EditUndo, Slot::EditBallRod)) return edit_;
  if (within(s, Slot::ToolsTools, Slot::ToolsSnap)) return tools_;
  if (within(s, Slot::ViewFit, Slot::View3dDock)) return view_;
  if (within(s, Slot::AnimationPlay, Slot::AnimationFaster)) return animation_;
  if (within(s, Slot::AnalysisDesignChecks, Slot::AnalysisCamDock)) return analysis_;
  if (s == Slot::HelpAbout) return help_;
  if (within(s, Slot::FileBarNew, Slot::FileBarRedo)) return fileBar_;
  if (within(s, Slot::ToolsBarTools, Slot::ToolsBarFlip)) return toolsBar_;
  if (within(s, Slot::ViewBarFit, Slot::ViewBarPlane)) return viewBar_;
  return animationBar_;
}

QAction* WindowLayout::before(Slot s) const {
  QWidget* t = target(s);
  for (int i = static_cast<int>(s) + 1; i < static_cast<int>(Slot::Count); ++i) {
    const Slot next = static_cast<Slot>(i);
    if (target(next) != t) break;
    if (!entries_[i].empty()) return entries_[i].front();
  }
  return nullptr;  // the end
}

void WindowLayout::add(Slot s, QAction* a) {
  target(s)->insertAction(before(s), a);
  entries_[static_cast<size_t>(s)].push_back(a);
}

QAction* WindowLayout::addWidget(Slot s, QWidget* widget) {
  auto* bar = qobject_cast<QToolBar*>(target(s));
  Q_ASSERT(bar);
  QAction* a = bar->insertWidget(before(s), widget);
  entries_[static_cast<size_t>(s)].push_back(a);
  return a;
}

QMenu* WindowLayout::addMenu(Slot s, const QString& title) {
  auto* parent = qobject_cast<QMenu*>(target(s));
  Q_ASSERT(parent);
  auto* menu = new QMenu(title, parent);
  add(s, menu->menuAction());
  return menu;
}

}  // namespace linkage::ui
