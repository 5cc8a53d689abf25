// One window per open document: the canvas in the middle, the status bar under it, and around
// them the window's features, each a class of its own (ui/window/*_feature.h) that makes its
// actions (shortcut, status tip), puts them in the menus and toolbars, adds its docks, and
// keeps typed handles to them: `w.centres().show`, `w.animation().play`, `w.forces().dock`.
// Several windows can be open at once (File > New Window), to compare two inversions.
//
// A new feature (a dock, its actions) plugs in like the others:
//  1. ui/window/<name>_feature.h/.cpp: a WindowFeature subclass whose constructor takes
//     (MainWindow&, WindowLayout&), makes its widgets and actions (makeAction, addDock,
//     raisingToggle in window_feature.h) and places them with layout.add(Slot::..., action);
//     it overrides applyIcons/readSettings/writeSettings if it has icons or settings.
//  2. window_layout.h: a Slot for each menu or toolbar entry, where in the order it goes.
//  3. Here: a forward declaration, an accessor, a member; in main_window.cpp one line in
//     createFeatures() (after the features it tabifies its dock with).
// Code written as MainWindow members before (a main_window_cycle.cpp) moves over as:
// makeAction(name, ...) -> makeAction(&w, name, ...); dock("plots") -> w.plots().dock;
// action("play") -> w.animation().play; menus and toolbars -> layout.add(Slot::..., action).
#pragma once

#include <QMainWindow>
#include <vector>

class QFileSystemWatcher;
class QLabel;

namespace linkage::ui {

class AnimationFeature;
class Animator;
class Autosaver;
class CanvasScene;
class CanvasView;
class CentresFeature;
class CycleFeature;
class CamFeature;
class SensitivityFeature;
class DesignFeature;
class Document;
class EditFeature;
class ExportFeature;
class FileFeature;
class ForcesFeature;
class MechanismsFeature;
class MessageStrip;
class PlotsFeature;
class PropertiesFeature;
struct Recovery;
class ToolsFeature;
class View3dFeature;
class ViewFeature;
class WindowFeature;
class WindowLayout;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  Document* document() const { return doc_; }
  CanvasView* canvas() const { return view_; }
  CanvasScene* scene() const { return scene_; }
  Animator* animator() const { return animator_; }
  Autosaver* autosaver() const { return autosave_; }
  // Under the canvas: the tool's hint, what is wrong with the design, the last message.
  MessageStrip* messageStrip() const { return strip_; }

  // The features, in the order they are made.
  FileFeature& file() const { return *file_; }
  ToolsFeature& tools() const { return *tools_; }
  ViewFeature& view() const { return *viewFeature_; }
  AnimationFeature& animation() const { return *animation_; }
  PropertiesFeature& properties() const { return *properties_; }
  CentresFeature& centres() const { return *centres_; }
  PlotsFeature& plots() const { return *plots_; }
  EditFeature& edit() const { return *edit_; }
  DesignFeature& designChecks() const { return *design_; }
  ExportFeature& exports() const { return *exports_; }
  ForcesFeature& forces() const { return *forces_; }
  MechanismsFeature& mechanisms() const { return *mechanisms_; }
  CycleFeature& cycle() const { return *cycle_; }
  CamFeature& cams() const { return *cams_; }
  SensitivityFeature& sensitivity() const { return *sensitivity_; }
  View3dFeature& view3d() const { return *view3d_; }

  // Every open main window.
  static QList<MainWindow*> windows();

  // Opens a recovered copy of unsaved work (document/autosave.h): as an unsaved edit of its
  // file, one undo step back to what the file holds.
  void openRecovered(const Recovery& r);
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
  bool save();
  bool saveAs();

 protected:
  void closeEvent(QCloseEvent* e) override;
  void dragEnterEvent(QDragEnterEvent* e) override;
  void dropEvent(QDropEvent* e) override;
  void changeEvent(QEvent* e) override;
  void showEvent(QShowEvent* e) override;

 private:
  void createFeatures();
  // The default layout of the docks (a saved one replaces it).
  void arrangeDocks();
  // Its sizes, once the window has its own (before, the dock layout ignores them).
  void sizeDocks();
  void createStatusBar();
  void connectDocument();
  // Watches the document's file; what it holds now is taken as ours (opened or saved here).
  void watchFile();
  void updateTitle();
  void updateStatus();
  // What the solver says of the design: why it cannot take it, or the joints that are
  // redundant and the bodies that are free.
  void showDesignStatus();
  void showMessage(const QString& text, bool warning);
  void readSettings();
  void writeSettings() const;
  // Toolbar and menu icons in the palette's colours.
  void applyIcons();
  // Every window's plots compare with the other windows' documents.
  static void updateComparisons();
  template <class Feature>
  Feature* add(Feature*& member);

  Document* doc_;
  CanvasScene* scene_;
  CanvasView* view_;
  Animator* animator_;
  MessageStrip* strip_ = nullptr;
  Autosaver* autosave_ = nullptr;
  WindowLayout* layout_ = nullptr;
  std::vector<WindowFeature*> features_;
  FileFeature* file_ = nullptr;
  ToolsFeature* tools_ = nullptr;
  ViewFeature* viewFeature_ = nullptr;
  AnimationFeature* animation_ = nullptr;
  PropertiesFeature* properties_ = nullptr;
  CentresFeature* centres_ = nullptr;
  PlotsFeature* plots_ = nullptr;
  EditFeature* edit_ = nullptr;
  DesignFeature* design_ = nullptr;
  ExportFeature* exports_ = nullptr;
  ForcesFeature* forces_ = nullptr;
  MechanismsFeature* mechanisms_ = nullptr;
  CycleFeature* cycle_ = nullptr;
  CamFeature* cams_ = nullptr;
  SensitivityFeature* sensitivity_ = nullptr;
  View3dFeature* view3d_ = nullptr;
  QFileSystemWatcher* watcher_ = nullptr;
  QString watched_;
  QByteArray onDisk_;    // the file's contents as this window last read or wrote them
  bool asking_ = false;  // the reload question is open
  QLabel* cursor_ = nullptr;
  QLabel* crank_ = nullptr;
  QLabel* dof_ = nullptr;
  bool defaultLayout_ = false;  // no saved layout: sizeDocks() at the first show
};

}  // namespace linkage::ui
