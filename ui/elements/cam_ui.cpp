// The cam in the editor: its profile turning with the cam and its follower's roller or face
// (cam_item.h); its follower, base circle, roller and motion programme in the panel. It is made
// from a follower's point (its menu's "Drive by a Cam") and designed in the Cam dock
// (cam/cam_panel.h) from the follower's motion.
#include <QMenu>

#include "document/document.h"
#include "elements/cam_item.h"
#include "elements/element_ui.h"
#include "elements/menu_actions.h"
#include "forms/form.h"
#include "linkage/cam_edits.h"
#include "linkage/cam_joint.h"

namespace linkage::ui {

namespace {

JointItem* item(const CanvasContext* ctx, const JointSymbol& s, const Drawing& d) {
  return new CamItem(ctx, s, ctx->style.body(bodyNumber(d, s.bodies[0])));
}

QString followerText(const CamJoint& c) {
  const QString end = c.kind.flat         ? Form::tr("flat face")
                      : c.kind.roller > 0 ? Form::tr("roller %1 mm").arg(c.kind.roller, 0, 'g', 6)
                                          : Form::tr("knife edge");
  return c.kind.oscillating
             ? Form::tr("oscillating, %1").arg(end)
             : Form::tr("translating, offset %1 mm, %2").arg(c.offset, 0, 'g', 6).arg(end);
}

void form(Form& panel, JointId id) {
  Document* doc = panel.document();
  auto read = [doc, id](std::string* why = nullptr) {
    const Mechanism& m = doc->design();
    return camJoint(m, *m.joint(id), why);
  };
  addTypeChoice(panel, id);
  panel.addInfo(Form::tr("Follower"), [read] {
    std::string why;
    const std::optional<CamJoint> c = read(&why);
    return c ? followerText(*c) : QString::fromStdString(why);
  });
  panel.addInfo(Form::tr("Base circle"), [read] {
    const std::optional<CamJoint> c = read();
    return c ? Form::tr("%1 mm").arg(c->kind.base, 0, 'g', 6) : QString();
  });
  panel.addInfo(Form::tr("Motion"), [read] {
    const std::optional<CamJoint> c = read();
    if (!c) return QString();
    QStringList parts;
    double from = 0;
    for (const cam::Segment& s : c->program.segments()) {
      parts << (s.law ? QStringLiteral("%1-%2: %3 %4")
                            .arg(from)
                            .arg(s.toDeg)
                            .arg(QString::fromLatin1(cam::lawName(*s.law)))
                            .arg(s.rise, 0, 'g', 6)
                      : QStringLiteral("%1-%2: dwell").arg(from).arg(s.toDeg));
      from = s.toDeg;
    }
    return parts.join(QStringLiteral("; "));
  });
}

void jointMenu(MenuActions&, QMenu&, const Joint&) {}

// "Drive by a Cam" on a follower's point: a cam on each body that could carry it (pinned to
// the body that guides the follower), with a roller or a flat face (cam_edits.h: addCam).
void pointMenu(MenuActions& box, QMenu& menu, PointId p) {
  const Mechanism& m = box.document()->design();
  const std::vector<BodyId> cams = camBodiesFor(m, p);
  if (cams.empty()) return;
  QMenu* sub = menu.addMenu(MenuActions::tr("Drive by a Cam"));
  for (bool flat : {false, true})
    for (BodyId cam : cams) {
      const QString on = QString::fromStdString(m.body(cam)->name);
      sub->addAction(flat ? MenuActions::tr("Flat Face, Cam on %1").arg(on)
                          : MenuActions::tr("Roller, Cam on %1").arg(on),
                     sub, [&box, p, cam, flat] {
                       box.editWith(MenuActions::tr("Drive by a Cam"),
                                    [p, cam, flat](Mechanism& m, std::string& why) {
                                      return static_cast<bool>(addCam(m, p, cam, flat, &why));
                                    });
                     });
    }
}

}  // namespace

const ElementUi& camUi() {
  static const ElementUi ui{
      elementKindNamed("cam")->type,
      QT_TRANSLATE_NOOP("Element", "cam (moves its follower by a motion programme)"),
      item,
      {nullptr, nullptr, nullptr, nullptr, nullptr, nullptr},
      form,
      jointMenu,
      nullptr,
      pointMenu};
  return ui;
}

}  // namespace linkage::ui
