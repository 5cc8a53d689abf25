// The Properties rows of forces: a link's mass properties (typed, or estimated from its outline)
// and its counterweights; the loads on a link (torques) or at a point (forces), each with the
// window of crank angles it acts in. Each change is one undo step.
#include <QRegularExpression>

#include "document/document.h"
#include "document/shown_numbers.h"
#include "linkage/io/numbers.h"
#include "properties/mass_dialog.h"
#include "properties/properties_panel.h"

namespace linkage::ui {

namespace {

// "x, y" (a comma, a semicolon or spaces between): two finite numbers.
std::optional<Vec2> parsePair(const QString& text) {
  const QStringList parts =
      text.split(QRegularExpression(QStringLiteral("[,;\\s]+")), Qt::SkipEmptyParts);
  if (parts.size() != 2) return std::nullopt;
  const auto x = parseNumber(parts[0].toStdString()), y = parseNumber(parts[1].toStdString());
  if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y)) return std::nullopt;
  return Vec2(*x, *y);
}

// "x, y" rounded for people; a component that is rounding next to the other (the x of a
// counterweight placed straight below its pivot, -2.8e-15) reads 0.
QString pairText(const Vec2& v) {
  const double scale = std::hypot(v.x(), v.y());
  return shownText(cleaned(v.x(), scale)) + QStringLiteral(", ") + shownText(cleaned(v.y(), scale));
}

// Where a massless body's mass would start: the middle of its points.
Vec2 middle(const Mechanism& m, BodyId id) {
  Vec2 c = Vec2::Zero();
  int n = 0;
  for (const Point& p : m.points)
    if (p.body == id) c += p.pos, ++n;
  return n ? Vec2(c / n) : c;
}

Mass& massOf(Mechanism& m, BodyId id) {
  Body* b = m.body(id);
  if (!b->mass) b->mass = Mass{0, middle(m, id), 0, "", {}};
  return *b->mass;
}

std::vector<LoadId> loadsAt(const Mechanism& m, BodyId body, PointId point) {
  std::vector<LoadId> out;
  for (const Load& l : m.loads)
    if ((point && l.point == point) || (body && !l.point && l.body == body)) out.push_back(l.id);
  return out;
}

}  // namespace

QString loadsShape(const Mechanism& m, BodyId body, PointId point) {
  QString shape = QStringLiteral(" loads");
  for (LoadId l : loadsAt(m, body, point)) shape += QStringLiteral(" %1").arg(l.value);
  return shape;
}

void PropertiesPanel::fillMass(BodyId id) {
  auto mass = [this, id]() -> std::optional<Mass> { return doc_->design().body(id)->mass; };
  // The file reader's bounds (linkage/model.h), said with the link's name.
  auto refused = [this, id](const std::string& why, QString* out) {
    *out = tr("on %1, %2")
               .arg(QString::fromStdString(doc_->design().body(id)->name),
                    QString::fromStdString(why));
    return !why.empty();
  };
  addNumber(
      tr("Mass"), [mass] { return mass() ? mass()->kg : 0.0; },
      [this, id, refused](double v, QString* why) {
        if (refused(massRefusal(v), why)) return false;
        return change(
            tr("Mass"), [&](Mechanism& m, QString*) { return massOf(m, id).kg = v, true; }, why);
      },
      tr("kg"));
  addText(
      tr("Centre of mass"),
      [this, id, mass] { return pairText(mass() ? mass()->com : middle(doc_->design(), id)); },
      [this, id](const QString& t, QString* why) {
        const std::optional<Vec2> at = parsePair(t);
        if (!at) return *why = tr("give x, y in mm"), false;
        return change(
            tr("Centre of mass"),
            [&](Mechanism& m, QString*) { return massOf(m, id).com = *at, true; }, why);
      });
  field(tr("Centre of mass"))->setToolTip(tr("x, y in mm, in the drawing's coordinates"));
  addNumber(
      tr("Moment of inertia"), [mass] { return mass() ? mass()->jKgMm2 : 0.0; },
      [this, id, refused](double v, QString* why) {
        if (refused(inertiaRefusal(v), why)) return false;
        return change(
            tr("Moment of inertia"),
            [&](Mechanism& m, QString*) { return massOf(m, id).jKgMm2 = v, true; }, why);
      },
      tr("kg\u00b7mm\u00b2"));
  addButton(QString(), tr("Estimate from Outline\u2026"), [this, id] { estimateMass(id); });
  addInfo(tr("Counterweights"), [mass] {
    // A copy held while it is read: a loop over mass()->counterweights read the temporary's
    // vector after the temporary was gone (the "4.941e-321 g" of issue 26).
    const std::optional<Mass> held = mass();
    if (!held || held->counterweights.empty()) return tr("none");
    QStringList parts;
    for (const PointMass& c : held->counterweights)
      parts << tr("%1 kg at (%2)").arg(shownText(c.kg), pairText(c.at));
    return parts.join(QStringLiteral("; "));
  });
}

void PropertiesPanel::estimateMass(BodyId id) {
  MassDialog dialog(doc_->design(), id, this);
  if (dialog.exec() != QDialog::Accepted || !dialog.estimate()) return;
  const Mass e = *dialog.estimate();
  QString why;
  const QString name = QString::fromStdString(doc_->design().body(id)->name);
  change(
      tr("Estimate the mass of %1").arg(name),
      [&](Mechanism& m, QString* refusal) {
        Mass& to = massOf(m, id);
        // The counterweights a balance added stay: they are on the body, not in its outline.
        Mass next = e;
        next.extras = to.extras;
        for (const PointMass& c : to.counterweights) {
          const double kg = next.kg + c.kg;
          const Vec2 com = (next.kg * next.com + c.kg * c.at) / kg;
          next.jKgMm2 +=
              next.kg * (next.com - com).squaredNorm() + c.kg * (c.at - com).squaredNorm();
          next.kg = kg;
          next.com = com;
        }
        next.counterweights = to.counterweights;
        // An outline of a ship's size is no link's: refused as the field and the file refuse it.
        for (const std::string& no : {massRefusal(next.kg), inertiaRefusal(next.jKgMm2)})
          if (!no.empty())
            return *refusal =
                       tr("Estimate from Outline: on %1, %2").arg(name, QString::fromStdString(no)),
                   false;
        to = next;
        return true;
      },
      &why);
  if (!why.isEmpty()) emit message(why, true);
}

void PropertiesPanel::fillLoads(BodyId body, PointId point) {
  const std::vector<LoadId> ids = loadsAt(doc_->design(), body, point);
  for (size_t i = 0; i < ids.size(); ++i) fillLoad(ids[i], static_cast<int>(i) + 1);
}

void PropertiesPanel::fillLoad(LoadId id, int number) {
  auto load = [this, id] { return *doc_->design().load(id); };
  const bool torque = !load().point;
  const QString name = torque ? tr("Torque %1").arg(number) : tr("Load %1").arg(number);
  auto edit = [this, id](const QString& text, auto&& f, QString* why) {
    return change(
        text, [&](Mechanism& m, QString*) { return f(*m.load(id)), true; }, why);
  };
  if (torque)
    addNumber(
        name, [load] { return load().torqueNm; },
        [edit](double v, QString* why) {
          if (!std::isfinite(v)) return *why = tr("give a number"), false;
          return edit(
              tr("Torque"), [v](Load& l) { l.torqueNm = v; }, why);
        },
        tr("N\u00b7m, + ccw"));
  else
    addText(
        name, [load] { return pairText(load().forceN) + QStringLiteral(" N"); },
        [edit](const QString& t, QString* why) {
          const std::optional<Vec2> f = parsePair(QString(t).remove(QStringLiteral("N")));
          if (!f) return *why = tr("give fx, fy in N"), false;
          return edit(
              tr("Load"), [f](Load& l) { l.forceN = *f; }, why);
        });
  addText(
      tr("%1 acts").arg(name),
      [load] {
        const Load l = load();
        if (!l.fromDeg) return tr("always");
        return tr("%1 to %2\u00b0").arg(shownText(*l.fromDeg), shownText(*l.toDeg));
      },
      [edit](const QString& t, QString* why) {
        const QString text = QString(t).remove(QChar(0x00b0)).trimmed();
        if (text.isEmpty() || text == tr("always"))
          return edit(
              tr("Load window"), [](Load& l) { l.fromDeg = l.toDeg = std::nullopt; }, why);
        const std::optional<Vec2> w =
            parsePair(QString(text).replace(tr("to"), QStringLiteral(" ")));
        if (!w) return *why = tr("give \"always\" or \"FROM to TO\" in crank degrees"), false;
        return edit(
            tr("Load window"), [w](Load& l) { l.fromDeg = w->x(), l.toDeg = w->y(); }, why);
      });
  field(tr("%1 acts").arg(name))
      ->setToolTip(tr("The crank angles (modulo 360) it acts at, e.g. 160 to 200; it may wrap "
                      "past 360 (300 to 20)"));
  addButton(QString(), tr("Remove %1").arg(name), [this, id, name] {
    QString why;
    change(
        tr("Remove %1").arg(name.toLower()),
        [&](Mechanism& m, QString*) {
          std::erase_if(m.loads, [id](const Load& l) { return l.id == id; });
          return true;
        },
        &why);
  });
}

}  // namespace linkage::ui
