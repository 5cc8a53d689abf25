// One window per open document: the canvas in the middle; docks for the properties
// (inspector), the instant centres and the plots; the file, view and animation actions in menus
// and toolbars (each with its shortcut and status tip); the crank scrubber; the status bar with
// the cursor position, the crank angle and the degrees of freedom. Several windows can be open
// at once (File > New Window), so that two inversions can be compared side by side.
#pragma once

#include <QMainWindow>
#include <QPointer>
#include <memory>

class QDockWidget;
class QFileSystemWatcher;
class QLabel;
class QMenu;
class QUndoView;

namespace linkage::ui {

class Animator;
class Autosaver;
struct Recovery;
class CanvasScene;
class CanvasView;
class CentresPanel;
class ChecksPanel;
class CrankBar;
class DesignChoices;
class DesignOverlays;
class Document;
class InspectorPanel;
class MechanismsPanel;
class MessageStrip;
class PropertiesPanel;
class PlotsPanel;
class Selection;
class StudyDialog;
class ForcesPanel;
class BalanceDialog;
class ToolOverlay;
class Toolbox;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  Document* document() const { return doc_; }
  CanvasView* canvas() const { return view_; }
  CanvasScene* scene() const { return scene_; }
  Animator* animator() const { return animator_; }
  CentresPanel* centresPanel() const { return centres_; }
  InspectorPanel* inspector() const { return inspector_; }
  PropertiesPanel* properties() const { return properties_; }
  PlotsPanel* plots() const { return plots_; }
  ForcesPanel* forcesPanel() const { return forces_; }
  MechanismsPanel* mechanismsPanel() const { return mechanisms_; }
  CrankBar* crankBar() const { return crankBar_; }
  Toolbox* toolbox() const { return toolbox_; }
  Selection* selection() const { return selection_; }
  DesignChoices* designChoices() const { return choices_; }
  DesignOverlays* designOverlays() const { return designOverlays_; }
  ChecksPanel* checksPanel() const { return checks_; }
  Autosaver* autosaver() const { return autosave_; }
  // Opens a recovered copy of unsaved work (document/autosave.h): as an unsaved edit of its
  // file, one undo step back to what the file holds.
  void openRecovered(const Recovery& r);
  // Under the canvas: the tool's hint, what is wrong with the design, the last message.
  MessageStrip* messageStrip() const { return strip_; }
  // The parameter-study dialog, made on first use (Analysis > Parameter Study).
  StudyDialog* studyDialog();
  QDockWidget* dock(const QString& objectName) const;
  // An action by its object name ("play", "open", "showCentres", ...), for tests and scripts.
  QAction* action(const QString& objectName) const;
  // Every open main window.
  static QList<MainWindow*> windows();

  // Opens a file in this window; on failure shows the reader's message in a dialog (unless
  // `error` is given, then it is returned there) and leaves the document as it was. No prompt
  // for unsaved changes here: callers ask first (maybeSave).
  bool openFile(const QString& path, QString* error = nullptr);
  // An example by name (resources/examples), opened untitled under its name.
  bool openExample(const QString& name, QString* error = nullptr);
  // A path or an example's name, as `linkage [FILE | EXAMPLE-NAME]` takes it.
  bool openNameOrPath(const QString& arg, QString* error = nullptr);
  // Where the file dialogs open: beside the current file, else where a file was last opened
  // or saved (QSettings "lastFolder"), else the home folder.
  QString fileFolder() const;
  // A file changed on disk by another program: says so and offers to reload it (from the
  // file system watcher; tests call it directly).
  void fileChangedOnDisk();
  // Asks what to do with unsaved changes; true when it is all right to go on.
  bool maybeSave();
  // One frame of the animation as File > Export > Animation writes it: the mechanism at a crank
  // angle, fitted to its motion, at `size`; endFrames() when done.
  QImage renderFrame(double deg, QSize size);
  void endFrames();
  bool save();
  bool saveAs();

 protected:
  void closeEvent(QCloseEvent* e) override;
  void dragEnterEvent(QDragEnterEvent* e) override;
  void dropEvent(QDropEvent* e) override;
  void changeEvent(QEvent* e) override;

 private:
  void createActions();  // main_window_actions.cpp, by menu
  void createFileActions();
  void createEditActions();
  void createViewActions();
  void createOverlayActions();
  void createAnimationActions();
  void createTools();
  void createMenus();
  void createToolBars();
  void createDocks();
  void createStatusBar();
  void createDesignChecks();  // main_window_design.cpp
  QMenu* addAnalysisMenu();
  void createForces();  // main_window_forces.cpp
  void addForcesMenuEntries(QMenu* analysis, QMenu* exports);
  void createMechanisms();  // main_window_mechanisms.cpp
  void connectDocument();
  QAction* makeAction(const QString& name, const QString& text, const QKeySequence& key,
                      const QString& tip);
  // Watches the document's file; what it holds now is taken as ours (opened or saved here).
  void watchFile();
  void fillRecentMenu();
  void fillExamplesMenu();
  void addRecent(const QString& path);
  void updateTitle();
  void updateStatus();
  // What the solver says of the design: why it cannot take it, or the joints that are
  // redundant and the bodies that are free.
  void showDesignStatus();
  void updateWork();
  void showMessage(const QString& text, bool warning);
  void readSettings();
  void writeSettings() const;
  void setDarkPalette(bool on);
  // Toolbar and menu icons in the palette's colours.
  void applyIcons();
  // File > Export: the motion table, the plots' figure, the animation.
  void exportMotionTable();
  void exportFigure();
  void exportAnimation();
  // Every window's plots compare with the other windows' documents.
  static void updateComparisons();

  Document* doc_;
  CanvasScene* scene_;
  CanvasView* view_;
  Animator* animator_;
  CrankBar* crankBar_ = nullptr;
  CentresPanel* centres_ = nullptr;
  InspectorPanel* inspector_ = nullptr;
  PropertiesPanel* properties_ = nullptr;
  PlotsPanel* plots_ = nullptr;
  QUndoView* history_ = nullptr;
  Selection* selection_ = nullptr;
  ToolOverlay* overlay_ = nullptr;
  Toolbox* toolbox_ = nullptr;
  bool propertiesSeen_ = false;
  std::unique_ptr<CanvasScene> frameScene_;
  std::unique_ptr<CanvasView> frameView_;
  QMenu* recentMenu_ = nullptr;
  QMenu* examplesMenu_ = nullptr;
  MessageStrip* strip_ = nullptr;
  Autosaver* autosave_ = nullptr;
  QFileSystemWatcher* watcher_ = nullptr;
  QString watched_;
  QByteArray onDisk_;    // the file's contents as this window last read or wrote them
  bool asking_ = false;  // the reload question is open
  QLabel* cursor_ = nullptr;
  QLabel* crank_ = nullptr;
  QLabel* dof_ = nullptr;
  DesignChoices* choices_ = nullptr;
  DesignOverlays* designOverlays_ = nullptr;
  ChecksPanel* checks_ = nullptr;
  StudyDialog* study_ = nullptr;
  ForcesPanel* forces_ = nullptr;
  BalanceDialog* balance_ = nullptr;
  MechanismsPanel* mechanisms_ = nullptr;
};

}  // namespace linkage::ui
