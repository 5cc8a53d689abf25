#include "window/main_window.h"
#include "window/mechanisms_feature.h"

#include <algorithm>

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QGuiApplication>
#include <QLabel>
#include <QLayout>
#include <QMimeData>
#include <QScreen>
#include <QSettings>
#include <QShowEvent>
#include <QStatusBar>

#include "animation/animator.h"
#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "document/autosave.h"
#include "document/document.h"
#include "document/shown_numbers.h"
#include "plots/plots_panel.h"
#include "tools/selection.h"
#include "tools/toolbox.h"
#include "window/animation_feature.h"
#include "window/cam_feature.h"
#include "window/centres_feature.h"
#include "window/choice_keys.h"
#include "window/cycle_feature.h"
#include "window/design_feature.h"
#include "window/edit_feature.h"
#include "window/export_feature.h"
#include "window/file_feature.h"
#include "window/forces_feature.h"
#include "window/message_strip.h"
#include "window/plots_feature.h"
#include "window/properties_feature.h"
#include "window/sensitivity_feature.h"
#include "window/tools_feature.h"
#include "window/view3d_feature.h"
#include "window/view_feature.h"
#include "window/window_layout.h"

namespace linkage::ui {

namespace {
QList<MainWindow*>& openWindows() {
  static QList<MainWindow*> w;
  return w;
}
}  // namespace

QList<MainWindow*> MainWindow::windows() {
  return openWindows();
}

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  setAttribute(Qt::WA_DeleteOnClose);
  setAcceptDrops(true);
  ChoiceKeys::install();
  openWindows().append(this);
  doc_ = new Document(this);
  autosave_ = new Autosaver(doc_, this);
  scene_ = new CanvasScene(this);
  view_ = new CanvasView(scene_, this);
  animator_ = new Animator(this);
  setCentralWidget(view_);
  strip_ = new MessageStrip(view_);
  view_->setBottomCover(strip_);
  scene_->setDocument(doc_);
  animator_->setDocument(doc_);
  createFeatures();
  createStatusBar();
  connectDocument();
  applyIcons();
  readSettings();
  updateTitle();
  updateStatus();
  updateComparisons();
  // The keyboard to the canvas: tool keys and Space work from the start.
  view_->setFocus();
}

template <class Feature>
Feature* MainWindow::add(Feature*& member) {
  member = new Feature(*this, *layout_);
  features_.push_back(member);
  return member;
}

void MainWindow::createFeatures() {
  layout_ = new WindowLayout(this);
  add(file_);
  add(tools_);
  add(viewFeature_);
  add(animation_);
  add(properties_);
  add(centres_);
  add(plots_);
  add(edit_);
  arrangeDocks();
  add(design_);                // its dock a tab beside the instant centres
  add(exports_);               // reads the plots
  add(forces_);                // its dock a tab beside the plots
  add(mechanisms_);            // its dock a tab beside the history
  add(cycle_);                 // its dock a tab beside the plots
  add(cams_);                  // its dock a tab beside the plots
  add(sensitivity_);           // its dock a tab beside the plots
  add(view3d_);                // its dock a tab beside the properties
  properties_->dock->raise();  // the default front tab on the right (a saved layout may differ)
}

MainWindow::~MainWindow() {
  openWindows().removeAll(this);
  updateComparisons();
  exports_->endFrames();
  // The children (document, docks, scene) are destroyed after this destructor, by QObject's;
  // signals they send on the way (a dock hidden, the undo stack cleared) must not reach this
  // window's slots any more, nor its features'.
  for (QObject* child : findChildren<QObject*>()) {
    disconnect(child, nullptr, this, nullptr);
    for (WindowFeature* f : features_) disconnect(child, nullptr, f, nullptr);
  }
}

void MainWindow::updateComparisons() {
  for (MainWindow* w : openWindows()) {
    QList<Document*> others;
    for (MainWindow* o : openWindows())
      if (o != w) others.append(o->doc_);
    w->plots_->panel()->setComparisonDocuments(others);
  }
}

void MainWindow::connectDocument() {
  connect(animator_, &Animator::message, this, &MainWindow::showMessage);
  connect(doc_, &Document::fileStateChanged, this, &MainWindow::updateTitle);
  // Another file (New, an example), or this one written: the watch follows.
  connect(doc_, &Document::fileStateChanged, this, [this] {
    if (doc_->filePath() != watched_) watchFile();
  });
  connect(doc_, &Document::saved, this, &MainWindow::watchFile);
  connect(doc_, &Document::designChanged, this, &MainWindow::updateStatus);
  connect(doc_, &Document::designChanged, this, &MainWindow::showDesignStatus);
  connect(doc_, &Document::poseChanged, this, &MainWindow::updateStatus);
  connect(view_, &CanvasView::cursorMoved, this, [this](QPointF mm) {
    cursor_->setText(tr("x %1  y %2 mm").arg(mm.x(), 0, 'f', 2).arg(mm.y(), 0, 'f', 2));
  });
}

void MainWindow::arrangeDocks() {
  QDockWidget* p = properties_->dock;
  QDockWidget* c = centres_->dock;
  QDockWidget* pl = plots_->dock;
  // The properties and the instant centres as tabs on the right, full height; the plots under
  // the canvas.
  setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
  setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
  tabifyDockWidget(p, c);
  p->raise();
  // A title bar dragged a little moves a panel within the window, not out of it (View >
  // Detachable Panels lets them float).
  for (QDockWidget* d : {p, c, pl, edit_->historyDock})
    d->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable);
}

void MainWindow::sizeDocks() {
  // The Properties wide enough for the outputs' three columns; the plots low enough to leave
  // the canvas most of the height (at 1400 x 950 it had 440 px: the sizes asked before the
  // first show were not applied).
  resizeDocks({properties_->dock}, {std::clamp(width() * 27 / 100, 300, 420)}, Qt::Horizontal);
  resizeDocks({plots_->dock}, {std::clamp(height() * 28 / 100, 220, 360)}, Qt::Vertical);
}

void MainWindow::showEvent(QShowEvent* e) {
  QMainWindow::showEvent(e);
  if (!defaultLayout_) return;
  defaultLayout_ = false;
  // The dock layout takes sizes once it has laid out the window at its size: now, before the
  // first paint (not later: a first click would land in another layout).
  layout()->setGeometry(rect());
  sizeDocks();
}

void MainWindow::createStatusBar() {
  // The hint, the design's problem and the messages wrap under the canvas (MessageStrip); the
  // status bar keeps the short readouts and the actions' status tips.
  strip_->setHint(tools_->toolbox()->hint());
  connect(tools_->toolbox(), &Toolbox::hintChanged, strip_, &MessageStrip::setHint);
  cursor_ = new QLabel;
  crank_ = new QLabel;
  dof_ = new QLabel;
  for (QLabel* l : {cursor_, crank_, dof_}) l->setMinimumWidth(90);
  cursor_->setMinimumWidth(170);
  statusBar()->addPermanentWidget(cursor_);
  statusBar()->addPermanentWidget(crank_);
  statusBar()->addPermanentWidget(dof_);
  // A message goes when it stops being true: at the next edit, selection, or turn of the crank
  // by the user (not at every frame of the animation, whose own messages stay while it plays).
  connect(doc_, &Document::designChanged, strip_, &MessageStrip::clearMessage);
  connect(tools_->selection(), &Selection::changed, strip_, &MessageStrip::clearMessage);
  connect(doc_, &Document::poseChanged, this, [this] {
    if (!animator_->playing()) strip_->clearMessage();
  });
}

void MainWindow::showMessage(const QString& text, bool warning) {
  strip_->setMessage(text, warning);
}

void MainWindow::updateStatus() {
  const Kinematics& k = doc_->kinematics();
  crank_->setText(k.valid() ? tr("crank %1\u00b0").arg(angleText(doc_->crankDeg(), 2))
                            : tr("crank \u2013"));
  // Of the design only when the solver holds it (not of the last design it could solve).
  if (doc_->solved()) {
    const StructureReport r = k.structure();
    dof_->setText(r.gruebler == r.mobility
                      ? tr("DOF %1").arg(r.mobility)
                      : tr("DOF %1 (Gruebler %2)").arg(r.mobility).arg(r.gruebler));
    dof_->setToolTip(tr("Degrees of freedom: %1 (Gruebler's count %2; rank %3)")
                         .arg(r.mobility)
                         .arg(r.gruebler)
                         .arg(r.rank));
  } else {
    dof_->setText(tr("DOF \u2013"));
    dof_->setToolTip(tr("Not solved: %1").arg(QString::fromStdString(doc_->solveStatus().message)));
  }
}

void MainWindow::showDesignStatus() {
  // Kept in a label of its own while it holds (transient messages come and go beside it).
  QString text;
  const Kinematics& k = doc_->kinematics();
  if (!doc_->solveStatus().ok()) {
    text = QString::fromStdString(doc_->solveStatus().message);
  } else if (k.valid()) {
    // Over- or under-constrained: the joints or bodies the structure analysis names (they are
    // drawn in the warning colour).
    for (const Note& n : k.notes())
      if (n.kind == Note::Kind::RedundantJoints || n.kind == Note::Kind::FreedomsHeld) {
        text = QString::fromStdString(n.text);
        break;
      }
  }
  if (text.isEmpty()) text = scene_->slotWarningText();
  strip_->setProblem(text);
}

void MainWindow::updateTitle() {
  setWindowTitle(QStringLiteral("%1[*] \u2014 Linkage").arg(doc_->displayName()));
  setWindowModified(doc_->isModified());
}

void MainWindow::applyIcons() {
  for (WindowFeature* f : features_) f->applyIcons(palette());
}

void MainWindow::changeEvent(QEvent* e) {
  if (e->type() == QEvent::PaletteChange) applyIcons();
  // The user turns to something else: a copy of the unsaved work now.
  if (e->type() == QEvent::ActivationChange && !isActiveWindow()) autosave_->saveNow();
  QMainWindow::changeEvent(e);
}

void MainWindow::closeEvent(QCloseEvent* e) {
  animator_->setPlaying(false);
  if (!maybeSave()) {
    e->ignore();
    return;
  }
  writeSettings();
  e->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* e) {
  if (e->mimeData()->hasUrls() && e->mimeData()->urls().value(0).isLocalFile())
    e->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* e) {
  const QString path = e->mimeData()->urls().value(0).toLocalFile();
  if (path.isEmpty()) return;
  e->acceptProposedAction();
  if (maybeSave()) openFile(path);
}

void MainWindow::readSettings() {
  QSettings s;
  s.beginGroup(QStringLiteral("window"));
  // First start: most of the screen (the canvas, the plots and the panels all want room).
  if (!restoreGeometry(s.value(QStringLiteral("geometry")).toByteArray())) {
    const QRect screen = QGuiApplication::primaryScreen()
                             ? QGuiApplication::primaryScreen()->availableGeometry()
                             : QRect(0, 0, 1280, 800);
    resize(std::max(1024, screen.width() * 9 / 10), std::max(720, screen.height() * 9 / 10));
  }
  defaultLayout_ = !restoreState(s.value(QStringLiteral("state")).toByteArray());
  s.endGroup();
  s.beginGroup(QStringLiteral("view"));
  for (WindowFeature* f : features_) f->readSettings(s);
  s.endGroup();
}

void MainWindow::writeSettings() const {
  QSettings s;
  s.beginGroup(QStringLiteral("window"));
  s.setValue(QStringLiteral("geometry"), saveGeometry());
  s.setValue(QStringLiteral("state"), saveState());
  s.endGroup();
  s.beginGroup(QStringLiteral("view"));
  for (const WindowFeature* f : features_) f->writeSettings(s);
  s.endGroup();
}

}  // namespace linkage::ui
