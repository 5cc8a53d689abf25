#include "window/probe.h"

#include "cam/cam_panel.h"
#include "design/optimize_dialog.h"
#include "design/sensitivity_panel.h"
#include "window/cam_feature.h"
#include "window/sensitivity_feature.h"

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QCryptographicHash>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QSaveFile>
#include <QTabBar>
#include <QTableWidget>
#include <QTextDocument>
#include <QTimer>
#include <QUndoStack>

#include "animation/animator.h"
#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "canvas/clearance_marks.h"
#include "centres/centres_panel.h"
#include "cycle/cycle_panel.h"
#include "document/document.h"
#include "forces/dynamics_item.h"
#include "forces/forces_overlay.h"
#include "linkage/elements.h"
#include "linkage/io/model_file.h"
#include "mechanisms/mechanisms_panel.h"
#include "plots/plots_panel.h"
#include "properties/inspector_panel.h"
#include "properties/properties_panel.h"
#include "tools/selection.h"
#include "view3d/view3d_widget.h"
#include "window/features.h"
#include "window/mechanisms_feature.h"
#include "window/tools_feature.h"

namespace linkage::ui {

namespace {

QString oneLine(QString s) {
  s.replace(QLatin1Char('\n'), QLatin1Char(' '));
  return s;
}

QString plain(const QString& rich) {
  QTextDocument d;
  d.setHtml(rich);
  return oneLine(d.toPlainText());
}

// What is selected, by the names the messages use: "coupler.P; gear pinion.I - gear.O2".
QString selectionText(MainWindow& w) {
  const Mechanism& m = w.document()->design();
  const Selection& s = *w.tools().selection();
  QStringList names;
  for (BodyId b : s.bodies)
    if (const Body* body = m.body(b)) names << QString::fromStdString(body->name);
  for (PointId p : s.points) names << QString::fromStdString(m.pointLabel(p));
  for (JointId j : s.joints) names << QString::fromStdString(jointName(m, j));
  for (SlotId sl : s.slots_) names << QString::fromStdString(m.slotLabel(sl));
  return names.join(QStringLiteral("; "));
}

// The docks' named number boxes (the crank's angle and step, the plots' revolutions and
// steps): what they show and where.
void spinBoxes(MainWindow& w, QStringList& out) {
  for (QAbstractSpinBox* s : w.findChildren<QAbstractSpinBox*>()) {
    // A dock behind another's tab keeps its widgets "visible", moved off the window.
    if (s->objectName().isEmpty() || s->visibleRegion().isEmpty()) continue;
    const QPoint c = s->mapToGlobal(s->rect().center());
    out << QStringLiteral("spin %1: %2").arg(s->objectName(), s->text());
    out << QStringLiteral("at spin %1: %2 %3").arg(s->objectName()).arg(c.x()).arg(c.y());
  }
}

// The machine in space: the plane the canvas shows, the bodies it draws faint, the chooser and
// the 3D view where they are on the screen, and the 3D view's direction.
void spaceText(MainWindow& w, QStringList& out) {
  const std::string& plane = w.scene()->shownPlane();
  out << QStringLiteral("plane: ") + QString::fromStdString(plane.empty() ? "drawing" : plane);
  QStringList faint;
  for (const Body& b : w.document()->design().bodies)
    if (BodyItem* item = w.scene()->bodyItem(b.id); item && item->opacity() < 1)
      faint << QString::fromStdString(b.name);
  out << QStringLiteral("faint bodies: ") + faint.join(QLatin1Char(' '));
  if (QComboBox* c = w.view3d().planeChooser; c->isVisible()) {
    const QPoint at = c->mapToGlobal(c->rect().center());
    out << QStringLiteral("at combo planeChooser: %1 %2").arg(at.x()).arg(at.y());
  }
  View3dWidget* v = w.view3d().view();
  // A dock behind another's tab is moved off the window, "visible".
  const QRect inWindow(v->mapTo(&w, QPoint(0, 0)), v->size());
  if (v->visibleRegion().isEmpty() || !w.rect().contains(inWindow)) {
    out << QStringLiteral("view3d: hidden");
    return;
  }
  const QPoint o = v->mapToGlobal(QPoint(0, 0));
  out << QStringLiteral("view3d: shown %1 %2 %3 %4")
             .arg(o.x())
             .arg(o.y())
             .arg(v->width())
             .arg(v->height());
  const Eigen::Matrix3d& r = v->projection().rotation();
  out << QStringLiteral("view3d eye: %1 %2 %3")
             .arg(r(2, 0), 0, 'f', 3)
             .arg(r(2, 1), 0, 'f', 3)
             .arg(r(2, 2), 0, 'f', 3);
}

void windowText(MainWindow* w, QStringList& out) {
  out << QStringLiteral("title: ") + w->windowTitle();
  out << QStringLiteral("size: %1x%2").arg(w->width()).arg(w->height());
  out << QStringLiteral("zoom: %1").arg(w->canvas()->zoom());
  // Where the drawing's origin is on the screen and pixels per mm (y up): what a script clicks
  // a point of the mechanism by.
  CanvasView* v = w->canvas();
  const QPoint o = v->viewport()->mapToGlobal(v->mapFromScene(QPointF(0, 0)));
  out << QStringLiteral("canvas: %1 %2 %3").arg(o.x()).arg(o.y()).arg(v->zoom(), 0, 'g', 12);
  for (QTabBar* bar : w->findChildren<QTabBar*>())
    for (int i = 0; i < bar->count(); ++i) {
      const QPoint c = bar->mapToGlobal(bar->tabRect(i).center());
      out << QStringLiteral("tab %1: %2 %3").arg(bar->tabText(i)).arg(c.x()).arg(c.y());
    }
  out << QStringLiteral("crank: %1").arg(w->document()->crankDeg());
  out << QStringLiteral("solved: %1").arg(w->document()->solved() ? 1 : 0);
  out << QStringLiteral("modified: %1").arg(w->document()->isModified() ? 1 : 0);
  // The design as Save would write it, by its SHA-1: what a script compares files with.
  const QByteArray design = QByteArray::fromStdString(serializeMechanism(w->document()->design()));
  out << QStringLiteral("design: ") +
             QString::fromLatin1(
                 QCryptographicHash::hash(design, QCryptographicHash::Sha1).toHex());
  out << QStringLiteral("playing: %1").arg(w->animator()->playing() ? 1 : 0);
  QWidget* f = QApplication::focusWidget();
  out << QStringLiteral("focus: ") + (f ? QString::fromLatin1(f->metaObject()->className()) : "");
  for (const char* name : {"hint", "problem", "notice", "message"})
    if (auto* l = w->findChild<QLabel*>(QString::fromLatin1(name)))
      out << QString::fromLatin1(name) + ": " + (l->isVisible() ? oneLine(l->text()) : QString());
  out << QStringLiteral("inspector: ") + plain(w->properties().inspector()->summaryText());
  const QTableWidget* t = w->properties().inspector()->motionTable();
  for (int r = 0; r < t->rowCount(); ++r) {
    QStringList cells;
    for (int c = 0; c < t->columnCount(); ++c)
      cells << (t->item(r, c) ? t->item(r, c)->text() : "");
    out << QStringLiteral("output: ") + cells.join(QStringLiteral(" | "));
  }
  out << QStringLiteral("outputs note: ") + oneLine(w->properties().inspector()->noteText());
  out << QStringLiteral("chain: ") + oneLine(w->centres().panel()->stepsText());
  out << QStringLiteral("plots: ") + oneLine(w->plots().panel()->cursorText());
  // The plots' named choices (the comparison and the point compared with), where shown.
  for (QComboBox* c : w->plots().panel()->findChildren<QComboBox*>()) {
    if (c->objectName().isEmpty() || !c->isVisible()) continue;
    const QPoint at = c->mapToGlobal(c->rect().center());
    out << QStringLiteral("combo %1: %2").arg(c->objectName(), c->currentText());
    out << QStringLiteral("at combo %1: %2 %3").arg(c->objectName()).arg(at.x()).arg(at.y());
  }
  const DynamicsMarks& forces = w->forces().overlay()->item()->marks();
  out << QStringLiteral("forces: ") + forces.legend;
  out << QStringLiteral("dynamics: masses %1 loads %2 reactions %3")
             .arg(forces.masses.size())
             .arg(forces.loads.size())
             .arg(forces.reactions.size());
  out << QStringLiteral("properties: ") + plain(w->properties().panel()->title());
  out << QStringLiteral("selection: ") + selectionText(*w);
  for (QLineEdit* e : w->properties().panel()->findChildren<QLineEdit*>()) {
    const QString label = w->properties().panel()->labelOf(e);
    const QPoint c = e->mapToGlobal(e->rect().center());
    out << QStringLiteral("field %1: %2").arg(label, e->text());
    out << QStringLiteral("at field %1: %2 %3").arg(label).arg(c.x()).arg(c.y());
  }
  spinBoxes(*w, out);
  spaceText(*w, out);
  out << w->mechanisms().panel->probeLines();
  out << w->cycle().panel()->probeLines();
  out << w->cams().panel()->probeLines();
  out << w->sensitivity().panel()->probeLines();
  if (const auto* d = w->findChild<OptimizeDialog*>(); d && d->isVisible()) out << d->probeLines();
  out << QStringLiteral("clearance marks: %1").arg(w->cycle().marks()->marks().size());
  for (const ClearanceMark& m : w->cycle().marks()->marks())
    out << QStringLiteral("clearance mark: %1 (part of %2 points)").arg(m.text).arg(m.part.size());
  const QUndoStack* u = w->document()->undoStack();
  for (int i = 0; i < u->count(); ++i) out << QStringLiteral("history: ") + u->text(i);
}

}  // namespace

QString probeText() {
  QStringList out;
  for (MainWindow* w : MainWindow::windows()) {
    out << QStringLiteral("window");
    windowText(w, out);
  }
  // A menu open (a right click's): its entries, section titles among them, and where they are.
  if (auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget())) {
    QStringList entries;
    for (QAction* a : menu->actions()) {
      const QString text = QString(a->text()).remove(QLatin1Char('&'));
      if (text.isEmpty()) continue;
      entries << text;
      const QPoint c = menu->mapToGlobal(menu->actionGeometry(a).center());
      out << QStringLiteral("at menu item %1: %2 %3").arg(text).arg(c.x()).arg(c.y());
    }
    out << QStringLiteral("menu: ") + entries.join(QStringLiteral(" | "));
  }
  // A question asked (a message box): its title and where its buttons are, to answer it.
  if (QWidget* d = QApplication::activeModalWidget()) {
    out << QStringLiteral("dialog: ") + d->windowTitle();
    for (QAbstractButton* b : d->findChildren<QAbstractButton*>()) {
      if (!b->isVisible() || b->text().isEmpty()) continue;
      const QPoint c = b->mapToGlobal(b->rect().center());
      out << QStringLiteral("at dialog button %1: %2 %3")
                 .arg(QString(b->text()).remove(QLatin1Char('&')))
                 .arg(c.x())
                 .arg(c.y());
    }
  }
  return out.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

void startProbeFromEnvironment() {
  const QString path = qEnvironmentVariable("LINKAGE_PROBE");
  if (path.isEmpty()) return;
  // A steady caret: the tests wait until two screenshots 0.3 s apart agree, and a caret
  // blinking once a second with shots taking 0.2 s under load kept every pair apart
  // (x11.clearance_then_example failed so in a CI run: "the picture does not settle").
  QApplication::setCursorFlashTime(0);
  auto* timer = new QTimer(qApp);
  timer->setInterval(200);
  QObject::connect(timer, &QTimer::timeout, qApp, [path] {
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return;
    f.write(probeText().toUtf8());
    f.commit();
  });
  timer->start();
}

}  // namespace linkage::ui
