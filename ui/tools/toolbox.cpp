#include "tools/toolbox.h"

#include <QAction>
#include <QMenu>
#include <QMouseEvent>

#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "document/commands.h"
#include "document/document.h"
#include "elements/element_ui.h"
#include "linkage/edits.h"
#include "tools/pick_point_tool.h"
#include "tools/selection.h"
#include "tools/tool_overlay.h"
#include "tools/tool_registry.h"

namespace linkage::ui {

Toolbox::Toolbox(ToolContext ctx, QWidget* actionParent) : QObject(actionParent), ctx_(ctx) {
  group_ = new QActionGroup(this);
  group_->setExclusive(true);
  auto* parent = actionParent;
  auto make = [&](const QString& name, const QString& text, const QKeySequence& key,
                  const QString& tip) {
    auto* a = new QAction(text, parent);
    a->setObjectName(name);
    a->setShortcut(key);
    a->setStatusTip(tip);
    a->setToolTip(QStringLiteral("%1 (%2)").arg(QString(text).remove('&'), key.toString()));
    parent->addAction(a);
    return a;
  };
  auto tool = [&](const QString& name, const QString& text, const QKeySequence& key,
                  const QString& tip, Tool* t) {
    if (!t) {
      qWarning("Toolbox: no tool is registered for \"%s\"", qPrintable(name));
      return;
    }
    QAction* a = make(QStringLiteral("tool:") + name, text, key, tip);
    a->setCheckable(true);
    a->setData(name);
    group_->addAction(a);
    actions_.push_back(a);
    tools_.emplace_back(t);
    // A tool chosen is work on the canvas: the keyboard goes there (from a Properties field).
    connect(a, &QAction::triggered, this, [this, name] {
      setTool(name);
      ctx_.view->setFocus();
    });
    connect(t, &Tool::hintChanged, this, [this, t] {
      if (t == current_) emit hintChanged(t->hint());
    });
    connect(t, &Tool::finished, this, [this] { setTool(QStringLiteral("select")); });
  };
  tool("select", tr("&Select"), QKeySequence(tr("S")),
       tr("Select and drag: a drag moves the mechanism, Ctrl+drag changes the design"),
       makeTool(QStringLiteral("select"), &ctx_));
  tool("link", tr("&Link"), QKeySequence(tr("L")),
       tr("Draw a link point by point; on a point of another link it pins there"),
       makeTool(QStringLiteral("link"), &ctx_));
  tool("ground", tr("&Ground Pivot"), QKeySequence(tr("G")),
       tr("Pin a point to the ground, or put a ground point on the canvas"),
       makeTool(QStringLiteral("ground"), &ctx_));
  tool("slot", tr("Sl&ot"), QKeySequence(tr("T")),
       tr("Draw a slot on the link under the first click, or in the ground"),
       makeTool(QStringLiteral("slot"), &ctx_));
  // The element kinds' own tools, in the kinds' order (ui/elements/element_ui.h).
  for (const ElementUi* k : elementUis()) {
    const ToolSpec& t = k->tool;
    if (!t.maker) continue;
    tool(QString::fromLatin1(t.name), tr(t.text), QKeySequence(tr(t.key)), tr(t.tip),
         makeTool(QString::fromLatin1(t.maker), &ctx_, k->type));
  }
  tool("driver", tr("&Driver"), QKeySequence(tr("M")), tr("Make a pin the driver (the crank)"),
       makeTool(QStringLiteral("driver"), &ctx_));
  tool("output", tr("O&utput Point"), QKeySequence(tr("O")), tr("Trace, plot and export a point"),
       makeTool(QStringLiteral("output"), &ctx_));

  picker_ = std::make_unique<PickPointTool>(&ctx_);
  connect(picker_.get(), &Tool::hintChanged, this, [this] {
    if (current_ == picker_.get()) emit hintChanged(picker_->hint());
  });
  connect(picker_.get(), &Tool::finished, this, [this] { setTool(QStringLiteral("select")); });

  makeCommands(make);
  connect(ctx_.selection, &Selection::changed, this, &Toolbox::updateCommands);
  connect(ctx_.doc, &Document::designChanged, this, [this] {
    ctx_.selection->prune(ctx_.doc->design());
    updateCommands();
  });
  ctx_.view->viewport()->installEventFilter(this);
  ctx_.view->installEventFilter(this);
  setTool(QStringLiteral("select"));
}

Toolbox::~Toolbox() = default;

// Delete, Flip Assembly and Snap to Grid.
template <class Make>
void Toolbox::makeCommands(Make make) {
  delete_ = make(QStringLiteral("delete"), tr("&Delete"), QKeySequence::Delete,
                 tr("Delete the selection and what depends on it"));
  connect(delete_, &QAction::triggered, this, &Toolbox::deleteSelection);
  flip_ = make(QStringLiteral("flip"), tr("&Flip Assembly"), QKeySequence(tr("X")),
               tr("Put the selected dyad on its other assembly branch (the mirror closure)"));
  connect(flip_, &QAction::triggered, this, [this] {
    const Selection& s = *ctx_.selection;
    BodyId b = s.bodies.empty() ? BodyId{} : s.bodies.front();
    if (!b && !s.joints.empty())
      if (const Joint* j = ctx_.doc->design().joint(s.joints.front()))
        if (const Point* p = ctx_.doc->design().point(j->b ? j->b : j->a)) b = p->body;
    QString why;
    if (!b)
      ctx_.message(tr("Select a link of the dyad to flip"), true);
    else if (!flipAssembly(ctx_.doc, b, &why))
      ctx_.message(tr("Cannot flip: %1").arg(why), true);
    else
      ctx_.message(tr("Flipped to the other assembly"), false);
  });
  snap_ = make(QStringLiteral("snapGrid"), tr("Snap to &Grid"), QKeySequence(),
               tr("New points snap to the grid (hold Alt to place them freely)"));
  snap_->setCheckable(true);
  snap_->setChecked(true);
}

void Toolbox::editWith(const QString& text,
                       const std::function<bool(Mechanism&, std::string&)>& change) {
  Mechanism next = ctx_.doc->design();
  std::string why;
  if (!change(next, why)) {
    ctx_.message(QString::fromStdString(why), true);
    return;
  }
  commitEdit(ctx_.doc, text, std::move(next));
}

void Toolbox::startTool(const QString& name, const ToolStart& from) {
  setTool(name);
  if (const QAction* a = toolAction(name); a && a->isChecked()) current_->start(from);
}

void Toolbox::pickPoint(const QString& purpose, std::function<void(PointId)> picked,
                        std::function<void()> cancelled) {
  // Whoever was picking before gives up first; so does the tool that was current.
  if (current_) current_->deactivate();
  current_ = picker_.get();
  if (QAction* a = group_->checkedAction()) a->setChecked(false);
  ctx_.overlay->clearPreview();
  picker_->start(purpose, std::move(picked), std::move(cancelled));
  emit hintChanged(picker_->hint());
  ctx_.view->setFocus();  // Esc on the canvas gives up
}

bool Toolbox::picking() const {
  return current_ == picker_.get() && picker_->picking();
}

QAction* Toolbox::toolAction(const QString& name) const {
  for (QAction* a : actions_)
    if (a->data().toString() == name) return a;
  return nullptr;
}

void Toolbox::setTool(const QString& name) {
  for (size_t i = 0; i < actions_.size(); ++i)
    if (actions_[i]->data().toString() == name) {
      if (current_ && current_ != tools_[i].get()) current_->deactivate();
      current_ = tools_[i].get();
      actions_[i]->setChecked(true);
      current_->activate();
      ctx_.overlay->clearPreview();
      emit hintChanged(current_->hint());
      return;
    }
}

QString Toolbox::hint() const {
  return current_ ? current_->hint() : QString();
}

void Toolbox::updateCommands() {
  delete_->setEnabled(!ctx_.selection->empty());
  bool flippable = false;
  if (ctx_.doc->solved()) {
    const std::vector<BodyId> ok = ctx_.doc->kinematics().flippableBodies();
    for (BodyId b : ctx_.selection->bodies)
      flippable = flippable || std::find(ok.begin(), ok.end(), b) != ok.end();
    flippable = flippable || !ctx_.selection->joints.empty();
  }
  flip_->setEnabled(flippable);
}

void Toolbox::deleteSelection() {
  const Selection& s = *ctx_.selection;
  if (s.empty()) return;
  Mechanism m = ctx_.doc->design();
  std::vector<BodyId> bodies;
  for (BodyId b : s.bodies)
    if (const Body* body = m.body(b); body && !body->ground) bodies.push_back(b);
  const Removal r = m.remove(bodies, s.points, s.slots_, s.joints);
  if (r.empty() && !r.driver) return;
  const int n = int(r.bodies.size() + r.points.size() + r.slots.size() + r.joints.size());
  ctx_.selection->clear();
  editDesign(ctx_.doc, tr("Delete %n item(s)", "", n), std::move(m));
  ctx_.message(tr("Deleted %n item(s) (with what depended on them)", "", n), false);
}

CanvasMouse Toolbox::mouseAt(const QPoint& viewPos, Qt::MouseButton button,
                             Qt::MouseButtons buttons, Qt::KeyboardModifiers mods) const {
  CanvasMouse e;
  const QPointF at = ctx_.view->mapToScene(viewPos);
  e.world = Vec2(at.x(), at.y());
  e.viewPos = viewPos;
  e.button = button;
  e.buttons = buttons;
  e.modifiers = mods;
  const double px = ctx_.scene->pixelSize();
  e.pick = pickAt(*ctx_.scene, e.world, px);
  const bool grid = snap_->isChecked() && !(mods & Qt::AltModifier);
  e.snap = snapAt(*ctx_.scene, e.pick, e.world, px, grid ? ctx_.view->gridStep() : 0);
  return e;
}

bool Toolbox::eventFilter(QObject* watched, QEvent* event) {
  if (!current_) return false;
  CanvasView* view = ctx_.view;
  if (watched == view && event->type() == QEvent::KeyPress) {
    auto* k = static_cast<QKeyEvent*>(event);
    if (current_->key(k)) return true;
    if (k->key() == Qt::Key_Escape) {
      setTool(QStringLiteral("select"));
      return true;
    }
    return false;
  }
  if (watched != view->viewport()) return false;
  switch (event->type()) {
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonRelease:
    case QEvent::MouseButtonDblClick:
    case QEvent::MouseMove: {
      auto* m = static_cast<QMouseEvent*>(event);
      // The view's own: zoom, and panning with the middle button or Space held.
      if (view->panning() || view->spaceHeld() || m->button() == Qt::MiddleButton ||
          (m->buttons() & Qt::MiddleButton))
        return false;
      const CanvasMouse e =
          mouseAt(m->position().toPoint(), m->button(), m->buttons(), m->modifiers());
      if (event->type() == QEvent::MouseMove) {
        ctx_.overlay->setHover(e.pick);
        ctx_.overlay->setSnap(current_->snaps() ? std::optional<Snap>(e.snap) : std::nullopt);
        current_->move(e);
        return false;  // the view still reports the cursor position
      }
      if (m->button() == Qt::RightButton) {
        if (event->type() == QEvent::MouseButtonRelease && !current_->rightClick(e)) {
          QMenu* menu = contextMenu(e, view);
          if (menu) {
            menu->setAttribute(Qt::WA_DeleteOnClose);
            menu->popup(view->viewport()->mapToGlobal(m->position().toPoint()));
          }
        }
        return true;
      }
      if (event->type() == QEvent::MouseButtonPress) {
        view->setFocus();
        current_->press(e);
      } else if (event->type() == QEvent::MouseButtonRelease) {
        current_->release(e);
      } else {
        // Qt sends a double click in place of the second click's press: the press first,
        // then the double click (a quick second click may also be a new start).
        view->setFocus();
        current_->press(e);
        current_->doubleClick(e);
      }
      return true;
    }
    case QEvent::ContextMenu:
      return true;  // handled on the right button's release
    default:
      return false;
  }
}

}  // namespace linkage::ui
