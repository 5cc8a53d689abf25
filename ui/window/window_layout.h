// Where each feature's actions go in the window's menus and toolbars. The order of every menu
// and toolbar is written once, here, as the order of `Slot`: features register their entries
// in any order (ui/window/*_feature.cpp) and each lands in its place, so that a feature adds
// an entry to the View menu between two of another's without knowing about it. A new entry:
// a new slot where it goes (a new separator, menu or toolbar: also a line in
// window_layout.cpp, isSeparator or target).
#pragma once

#include <QObject>
#include <array>
#include <vector>

class QAction;
class QMainWindow;
class QMenu;
class QToolBar;
class QWidget;

namespace linkage::ui {

enum class Slot {
  // File
  FileNew,
  FileNewWindow,
  FileOpen,
  FileRecent,
  FileExamples,
  FileSeparator1,
  FileSave,
  FileSaveAs,
  FileExport,
  FileSeparator2,
  FileClose,
  FileQuit,
  // File > Export
  ExportTable,
  ExportFigure,
  ExportAnimation,
  ExportForcesTable,
  ExportForcesFigure,
  ExportCycleFigure,
  ExportTimingTable,
  // Edit
  EditUndo,
  EditRedo,
  EditSeparator1,
  EditHistory,
  EditSeparator2,
  EditDelete,
  EditFlip,
  EditAddPlane,
  EditBallRod,
  // Tools
  ToolsTools,
  ToolsSeparator,
  ToolsSnap,
  // View
  ViewFit,
  ViewZoomIn,
  ViewZoomOut,
  ViewActualSize,
  ViewSeparator1,
  ViewGrid,
  ViewCentres,
  ViewTraces,
  ViewForces,
  ViewExtremes,
  ViewTransmission,
  ViewDark,
  ViewDetachable,
  ViewHideOtherPlanes,
  View3dDirections,
  ViewSeparator2,
  ViewPropertiesDock,
  ViewCentresDock,
  ViewPlotsDock,
  ViewForcesDock,
  ViewDesignChecksDock,
  ViewMechanismsDock,
  ViewCycleDock,
  ViewCamDock,
  ViewSensitivityDock,
  View3dDock,
  // Animation
  AnimationPlay,
  AnimationStepBack,
  AnimationStepForward,
  AnimationToStart,
  AnimationSeparator,
  AnimationSlower,
  AnimationFaster,
  // Analysis
  AnalysisDesignChecks,
  AnalysisStudy,
  AnalysisSensitivityDock,
  AnalysisFindDimensions,
  AnalysisSeparator1,
  AnalysisExtremes,
  AnalysisTransmission,
  AnalysisSeparator2,
  AnalysisForcesDock,
  AnalysisForces,
  AnalysisBalance,
  AnalysisSeparator3,
  AnalysisCycleDock,
  AnalysisWatchClearance,
  AnalysisSeparator4,
  AnalysisCamDock,
  // Help
  HelpAbout,
  // The toolbars: File (top), Tools (left), View (top), Animation (bottom).
  FileBarNew,
  FileBarOpen,
  FileBarSave,
  FileBarUndo,
  FileBarRedo,
  ToolsBarTools,
  ToolsBarSeparator,
  ToolsBarDelete,
  ToolsBarFlip,
  ViewBarFit,
  ViewBarGrid,
  ViewBarCentres,
  ViewBarTraces,
  ViewBarPlane,
  AnimationBarPlay,
  AnimationBarStepBack,
  AnimationBarStepForward,
  AnimationBarToStart,
  AnimationBarCrank,
  Count
};

class WindowLayout : public QObject {
 public:
  // Makes the menus and toolbars of `w`, empty but for their separators.
  explicit WindowLayout(QMainWindow* w);

  // Puts `a` in its slot (after what the slot holds already).
  void add(Slot s, QAction* a);
  // A widget in a toolbar's slot (the crank scrubber): the action that shows or hides it.
  QAction* addWidget(Slot s, QWidget* widget);
  // A submenu in a menu's slot, made here.
  QMenu* addMenu(Slot s, const QString& title);

 private:
  QWidget* target(Slot s) const;
  QAction* before(Slot s) const;  // the first entry after slot s in its menu or toolbar

  std::array<std::vector<QAction*>, static_cast<size_t>(Slot::Count)> entries_;
  QMenu* exports_ = nullptr;
  QMenu *file_, *edit_, *tools_, *view_, *animation_, *analysis_, *help_;
  QToolBar *fileBar_, *toolsBar_, *viewBar_, *animationBar_;
};

}  // namespace linkage::ui
