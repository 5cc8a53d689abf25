// The loads' rows: on a moving link's form its torques, on a point's form the forces at it;
// each its value, the window of crank angles it acts in, and a button that removes it.
#include "document/document.h"
#include "document/shown_numbers.h"
#include "forces/force_rows.h"

namespace linkage::ui {

namespace {

// An edit of a load as one undo step, named `text`.
using LoadEdit =
    std::function<bool(const QString& text, const std::function<void(Load&)>& f, QString* why)>;

std::vector<LoadId> loadsAt(const Mechanism& m, BodyId body, PointId point) {
  std::vector<LoadId> out;
  for (const Load& l : m.loads)
    if ((point && l.point == point) || (body && !l.point && l.body == body)) out.push_back(l.id);
  return out;
}

// A link's loads are the torques on a moving one.
bool hasLoads(const Mechanism& m, const FormTarget& t) {
  return t.point || (t.body && !m.body(t.body)->ground);
}

// Which loads there are: each has rows of its own.
QString shape(const Mechanism& m, const FormTarget& t) {
  QString shape = QStringLiteral(" loads");
  if (hasLoads(m, t))
    for (LoadId l : loadsAt(m, t.body, t.point)) shape += QStringLiteral(" %1").arg(l.value);
  return shape;
}

// "always", or "FROM to TO" in crank degrees.
bool setWindow(const QString& t, QString* why, const LoadEdit& edit) {
  const QString text = QString(t).remove(QChar(0x00b0)).trimmed();
  if (text.isEmpty() || text == Form::tr("always"))
    return edit(
        Form::tr("Load window"), [](Load& l) { l.fromDeg = l.toDeg = std::nullopt; }, why);
  const std::optional<Vec2> w =
      parsePair(QString(text).replace(Form::tr("to"), QStringLiteral(" ")));
  if (!w) return *why = Form::tr("give \"always\" or \"FROM to TO\" in crank degrees"), false;
  return edit(
      Form::tr("Load window"), [w](Load& l) { l.fromDeg = w->x(), l.toDeg = w->y(); }, why);
}

void addLoad(Form& form, LoadId id, int number) {
  Document* doc = form.document();
  auto load = [doc, id] { return *doc->design().load(id); };
  const bool torque = !load().point;
  const QString name = torque ? Form::tr("Torque %1").arg(number) : Form::tr("Load %1").arg(number);
  const LoadEdit edit = [&form, id](const QString& text, const std::function<void(Load&)>& f,
                                    QString* why) {
    return form.change(
        text, [&](Mechanism& m, QString*) { return f(*m.load(id)), true; }, why);
  };
  if (torque)
    form.addNumber(
        name, [load] { return load().torqueNm; },
        [edit](double v, QString* why) {
          if (!std::isfinite(v)) return *why = Form::tr("give a number"), false;
          return edit(
              Form::tr("Torque"), [v](Load& l) { l.torqueNm = v; }, why);
        },
        Form::tr("N\u00b7m, + ccw"));
  else
    form.addText(
        name, [load] { return pairText(load().forceN) + QStringLiteral(" N"); },
        [edit](const QString& t, QString* why) {
          const std::optional<Vec2> f = parsePair(QString(t).remove(QStringLiteral("N")));
          if (!f) return *why = Form::tr("give fx, fy in N"), false;
          return edit(
              Form::tr("Load"), [f](Load& l) { l.forceN = *f; }, why);
        });
  form.addText(
      Form::tr("%1 acts").arg(name),
      [load] {
        const Load l = load();
        if (!l.fromDeg) return Form::tr("always");
        return Form::tr("%1 to %2\u00b0").arg(shownText(*l.fromDeg), shownText(*l.toDeg));
      },
      [edit](const QString& t, QString* why) { return setWindow(t, why, edit); });
  form.setTip(Form::tr("%1 acts").arg(name),
              Form::tr("The crank angles (modulo 360) it acts at, e.g. 160 to 200; it may wrap "
                       "past 360 (300 to 20)"));
  form.addButton(QString(), Form::tr("Remove %1").arg(name), [&form, id, name] {
    QString why;
    form.change(
        Form::tr("Remove %1").arg(name.toLower()),
        [&](Mechanism& m, QString*) {
          std::erase_if(m.loads, [id](const Load& l) { return l.id == id; });
          return true;
        },
        &why);
  });
}

void fill(Form& form, const FormTarget& t) {
  const Mechanism& m = form.document()->design();
  if (!hasLoads(m, t)) return;
  const std::vector<LoadId> ids = loadsAt(m, t.body, t.point);
  for (size_t i = 0; i < ids.size(); ++i) addLoad(form, ids[i], static_cast<int>(i) + 1);
}

}  // namespace

FormSection loadRows(const char* form) {
  return FormSection{form, shape, fill};
}

}  // namespace linkage::ui
