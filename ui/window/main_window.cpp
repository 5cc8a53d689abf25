#include "window/main_window.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QGuiApplication>
#include <QLabel>
#include <QLayout>
#include <QMenuBar>
#include <QMimeData>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QStyleFactory>
#include <QToolBar>
#include <QUndoView>

#include "animation/animator.h"
#include "animation/crank_bar.h"
#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "centres/centres_panel.h"
#include "document/autosave.h"
#include "document/document.h"
#include "document/shown_numbers.h"
#include "elements/element_ui.h"
#include "plots/plots_panel.h"
#include "properties/inspector_panel.h"
#include "properties/properties_panel.h"
#include "tools/selection.h"
#include "tools/tool_overlay.h"
#include "tools/toolbox.h"
#include "window/icons.h"
#include "window/message_strip.h"

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
  openWindows().append(this);
  doc_ = new Document(this);
  autosave_ = new Autosaver(doc_, this);
  scene_ = new CanvasScene(this);
  view_ = new CanvasView(scene_, this);
  animator_ = new Animator(this);
  setCentralWidget(view_);
  strip_ = new MessageStrip(view_);
  createActions();
  createTools();
  createDocks();
  createDesignChecks();
  createForces();
  createMechanisms();
  dock("properties")->raise();  // the default front tab on the right (a saved layout may differ)
  createMenus();
  createToolBars();
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

MainWindow::~MainWindow() {
  openWindows().removeAll(this);
  updateComparisons();
  // The children (document, docks, scene) are destroyed after this destructor, by QObject's;
  // signals they send on the way (a dock hidden, the undo stack cleared) must not reach this
  // window's slots any more.
  for (QObject* child : findChildren<QObject*>()) disconnect(child, nullptr, this, nullptr);
}

void MainWindow::updateComparisons() {
  for (MainWindow* w : openWindows()) {
    QList<Document*> others;
    for (MainWindow* o : openWindows())
      if (o != w) others.append(o->doc_);
    w->plots_->setComparisonDocuments(others);
  }
}

QAction* MainWindow::makeAction(const QString& name, const QString& text, const QKeySequence& key,
                                const QString& tip) {
  auto* a = new QAction(text, this);
  a->setObjectName(name);
  if (!key.isEmpty()) a->setShortcut(key);
  a->setStatusTip(tip);
  a->setToolTip(key.isEmpty() ? text
                              : QStringLiteral("%1 (%2)").arg(text).arg(
                                    key.toString(QKeySequence::NativeText)));
  a->setToolTip(a->toolTip().remove('&'));
  addAction(a);
  return a;
}

QAction* MainWindow::action(const QString& objectName) const {
  return findChild<QAction*>(objectName);
}

QDockWidget* MainWindow::dock(const QString& objectName) const {
  return findChild<QDockWidget*>(objectName);
}

void MainWindow::connectDocument() {
  scene_->setDocument(doc_);
  animator_->setDocument(doc_);
  crankBar_->setDocument(doc_);
  centres_->setDocument(doc_);
  inspector_->setDocument(doc_);
  properties_->setDocument(doc_, selection_);
  plots_->setDocument(doc_);
  connect(plots_, &PlotsPanel::crankAngleRequested, this, [this](double deg) {
    animator_->setPlaying(false);
    if (doc_->solved()) doc_->setCrankDeg(deg);
  });
  connect(properties_, &PropertiesPanel::message, this, &MainWindow::showMessage);
  history_->setStack(doc_->undoStack());
  connect(doc_, &Document::fileStateChanged, this, &MainWindow::updateTitle);
  // Another file (New, an example), or this one written: the watch follows.
  connect(doc_, &Document::fileStateChanged, this, [this] {
    if (doc_->filePath() != watched_) watchFile();
  });
  connect(doc_, &Document::saved, this, &MainWindow::watchFile);
  connect(doc_, &Document::designChanged, this, &MainWindow::updateStatus);
  connect(doc_, &Document::designChanged, this, &MainWindow::showDesignStatus);
  // A new solver (a file, an edit) starts with the default: ask again what is shown.
  connect(doc_, &Document::designChanged, this, &MainWindow::updateWork);
  connect(doc_, &Document::poseChanged, this, [this] {
    updateStatus();
    centres_->refresh();
    inspector_->refreshMotion();
  });
  // The chain's distances belong to the instant-centre view: drawn while it is on.
  auto showChain = [this] {
    scene_->chainItem()->setChain(action("showCentres")->isChecked() ? centres_->chain()
                                                                     : std::nullopt);
  };
  connect(centres_, &CentresPanel::chainChanged, this, showChain);
  connect(action("showCentres"), &QAction::toggled, this, showChain);
  connect(centres_, &CentresPanel::centreChosen, view_, &CanvasView::setSelectedCentre);
  connect(animator_, &Animator::message, this, &MainWindow::showMessage);
  connect(animator_, &Animator::playingChanged, this, [this](bool on) {
    QAction* play = action("play");
    play->setChecked(on);
    play->setText(on ? tr("&Pause") : tr("&Play"));
    play->setIcon(themedIcon(on ? QStringLiteral("pause") : QStringLiteral("play"), palette()));
    if (on) showMessage(QString(), false);
  });
  connect(view_, &CanvasView::cursorMoved, this, [this](QPointF mm) {
    cursor_->setText(tr("x %1  y %2 mm").arg(mm.x(), 0, 'f', 2).arg(mm.y(), 0, 'f', 2));
  });
  connect(view_, &CanvasView::spaceTapped, action("play"), &QAction::trigger);
}

void MainWindow::createDocks() {
  auto addDock = [this](const QString& name, const QString& title, QWidget* w,
                        Qt::DockWidgetArea area) {
    auto* d = new QDockWidget(title, this);
    d->setObjectName(name);
    d->setWidget(w);
    addDockWidget(area, d);
    return d;
  };
  // The selection's exact numbers above, what the mechanism is and where it is below.
  properties_ = new PropertiesPanel;
  inspector_ = new InspectorPanel;
  auto* split = new QSplitter(Qt::Vertical);
  auto* scroll = new QScrollArea;
  scroll->setWidget(properties_);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  split->addWidget(scroll);
  split->addWidget(inspector_);
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 2);
  split->setCollapsible(0, false);
  scroll->setMinimumHeight(140);
  // The form whole when its rows change (up to 60 % of the dock; then it scrolls): it started
  // cut off behind the splitter, its last rows out of sight.
  // Queued: the new rows' layout gives its size once the event loop has run it.
  connect(
      properties_, &PropertiesPanel::rebuilt, this,
      [split, scroll, this] {
        properties_->layout()->activate();
        const int want = properties_->sizeHint().height() + 2 * scroll->frameWidth();
        const int total = split->height();
        if (total <= 0 || scroll->height() >= want) return;
        const int form = std::min(want, total * 6 / 10);
        split->setSizes({form, total - form});
      },
      Qt::QueuedConnection);
  QDockWidget* p = addDock("properties", tr("Properties"), split, Qt::RightDockWidgetArea);
  centres_ = new CentresPanel;
  QDockWidget* c = addDock("centres", tr("Instant Centres"), centres_, Qt::RightDockWidgetArea);
  plots_ = new PlotsPanel;
  QDockWidget* pl = addDock("plots", tr("Plots"), plots_, Qt::BottomDockWidgetArea);
  pl->toggleViewAction()->setObjectName("showPlots");
  pl->toggleViewAction()->setStatusTip(
      tr("Position, velocity and acceleration of a point against the crank angle"));
  history_ = new QUndoView;
  history_->setEmptyLabel(tr("<opened>"));
  QDockWidget* h = addDock("history", tr("History"), history_, Qt::LeftDockWidgetArea);
  h->hide();
  // The default layout (a saved one replaces it): the properties and the instant centres as
  // tabs on the right, full height; the plots under the canvas.
  setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
  setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
  tabifyDockWidget(p, c);
  p->raise();
  resizeDocks({p}, {400}, Qt::Horizontal);
  // The plots low enough to leave the canvas most of the height (at 1400 x 950 it had 440 px).
  resizeDocks({pl}, {250}, Qt::Vertical);
  // A title bar dragged a little moves a panel within the window, not out of it (View >
  // Detachable Panels lets them float).
  for (QDockWidget* d : {p, c, pl, h})
    d->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable);
  // Work only while shown: the panels compute when they become visible.
  // Queued: a dock reports its visibility before its contents have changed theirs.
  // A dock's visibility says whether it is seen (a tab behind another is moved off the window
  // but its widget stays "visible").
  connect(p, &QDockWidget::visibilityChanged, this, [this](bool seen) { propertiesSeen_ = seen; });
  for (QDockWidget* d : {p, c})
    connect(d, &QDockWidget::visibilityChanged, this, &MainWindow::updateWork,
            Qt::QueuedConnection);
}

void MainWindow::updateWork() {
  // Accelerations only while something shows them (the inspector's readout).
  doc_->setAccelerationsWanted(propertiesSeen_);
  centres_->refresh();
  inspector_->refreshMotion();
}

void MainWindow::createTools() {
  selection_ = new Selection;
  selection_->setParent(this);
  overlay_ = new ToolOverlay(scene_->context(), scene_, selection_);
  scene_->addOverlay(overlay_);
  connect(selection_, &Selection::changed, this, [this] { overlay_->update(); });
  ToolContext ctx;
  ctx.doc = doc_;
  ctx.scene = scene_;
  ctx.view = view_;
  ctx.selection = selection_;
  ctx.overlay = overlay_;
  ctx.message = [this](const QString& text, bool warning) { showMessage(text, warning); };
  toolbox_ = new Toolbox(ctx, this);
}

void MainWindow::createStatusBar() {
  // The hint, the design's problem and the messages wrap under the canvas (MessageStrip); the
  // status bar keeps the short readouts and the actions' status tips.
  strip_->setHint(toolbox_->hint());
  connect(toolbox_, &Toolbox::hintChanged, strip_, &MessageStrip::setHint);
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
  connect(selection_, &Selection::changed, strip_, &MessageStrip::clearMessage);
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
  if (k.valid()) {
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
  // action object name, icon file
  static const std::pair<const char*, const char*> icons[] = {
      {"new", "new"},
      {"open", "open"},
      {"save", "save"},
      {"undo", "undo"},
      {"redo", "redo"},
      {"fit", "fit"},
      {"showGrid", "grid"},
      {"showCentres", "centres"},
      {"showTraces", "traces"},
      {"stepForward", "step-forward"},
      {"stepBack", "step-back"},
      {"toStart", "to-start"},
      {"tool:select", "tool-select"},
      {"tool:link", "tool-link"},
      {"tool:ground", "tool-ground"},
      {"tool:slot", "tool-slot"},
      {"tool:driver", "tool-driver"},
      {"tool:output", "tool-output"},
      {"delete", "delete"},
      {"flip", "flip"},
  };
  for (const auto& [action, icon] : icons)
    if (QAction* a = this->action(action)) a->setIcon(themedIcon(icon, palette()));
  // The element kinds' tools bring their own icons (ui/elements/element_ui.h).
  for (const ElementUi* k : elementUis())
    if (k->tool.make)
      if (QAction* a = this->action(QStringLiteral("tool:") + k->tool.name))
        a->setIcon(themedIcon(QString::fromLatin1(k->tool.icon), palette()));
  action("play")->setIcon(themedIcon(
      animator_->playing() ? QStringLiteral("pause") : QStringLiteral("play"), palette()));
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
  restoreState(s.value(QStringLiteral("state")).toByteArray());
  s.endGroup();
  s.beginGroup(QStringLiteral("view"));
  action("showGrid")->setChecked(s.value(QStringLiteral("grid"), true).toBool());
  action("showCentres")->setChecked(s.value(QStringLiteral("centres"), false).toBool());
  action("showTraces")->setChecked(s.value(QStringLiteral("traces"), true).toBool());
  action("showForces")->setChecked(s.value(QStringLiteral("forces"), false).toBool());
  action("showExtremes")->setChecked(s.value(QStringLiteral("extremes"), false).toBool());
  action("showTransmission")->setChecked(s.value(QStringLiteral("transmission"), false).toBool());
  action("darkPalette")->setChecked(s.value(QStringLiteral("dark"), false).toBool());
  action("detachablePanels")->setChecked(s.value(QStringLiteral("detachable"), false).toBool());
  crankBar_->setSpeedIndex(s.value(QStringLiteral("speed"), 3).toInt());
  animator_->setIncrementDeg(s.value(QStringLiteral("increment"), 1.0).toDouble());
  s.endGroup();
}

void MainWindow::writeSettings() const {
  QSettings s;
  s.beginGroup(QStringLiteral("window"));
  s.setValue(QStringLiteral("geometry"), saveGeometry());
  s.setValue(QStringLiteral("state"), saveState());
  s.endGroup();
  s.beginGroup(QStringLiteral("view"));
  s.setValue(QStringLiteral("grid"), action("showGrid")->isChecked());
  s.setValue(QStringLiteral("centres"), action("showCentres")->isChecked());
  s.setValue(QStringLiteral("traces"), action("showTraces")->isChecked());
  s.setValue(QStringLiteral("forces"), action("showForces")->isChecked());
  s.setValue(QStringLiteral("extremes"), action("showExtremes")->isChecked());
  s.setValue(QStringLiteral("transmission"), action("showTransmission")->isChecked());
  s.setValue(QStringLiteral("dark"), action("darkPalette")->isChecked());
  s.setValue(QStringLiteral("detachable"), action("detachablePanels")->isChecked());
  s.setValue(QStringLiteral("increment"), animator_->incrementDeg());
  s.endGroup();
}

void MainWindow::setDarkPalette(bool on) {
  // One palette for the whole application: the canvas, docks and plots follow it.
  if (on) {
    QPalette p;
    p.setColor(QPalette::Window, QColor(45, 45, 48));
    p.setColor(QPalette::WindowText, QColor(225, 225, 225));
    p.setColor(QPalette::Base, QColor(30, 30, 32));
    p.setColor(QPalette::AlternateBase, QColor(45, 45, 48));
    p.setColor(QPalette::Text, QColor(230, 230, 230));
    p.setColor(QPalette::Button, QColor(55, 55, 58));
    p.setColor(QPalette::ButtonText, QColor(225, 225, 225));
    p.setColor(QPalette::Highlight, QColor(60, 130, 220));
    p.setColor(QPalette::HighlightedText, Qt::white);
    p.setColor(QPalette::ToolTipBase, QColor(60, 60, 64));
    p.setColor(QPalette::ToolTipText, QColor(230, 230, 230));
    p.setColor(QPalette::PlaceholderText, QColor(150, 150, 150));
    for (auto role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
      p.setColor(QPalette::Disabled, role, QColor(120, 120, 120));
    QApplication::setPalette(p);
  } else {
    QApplication::setPalette(QApplication::style()->standardPalette());
  }
  for (MainWindow* w : windows()) {
    w->action("darkPalette")->setChecked(on);
    w->scene_->setPalette(w->view_->palette());
    w->view_->resetCachedContent();
  }
}

}  // namespace linkage::ui
