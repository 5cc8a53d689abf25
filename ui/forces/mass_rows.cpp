// A moving link's mass rows: its mass, centre of mass and moment of inertia (typed, or
// estimated from its outline), and the counterweights a balance put on it.
#include "document/document.h"
#include "document/shown_numbers.h"
#include "forces/force_rows.h"
#include "forces/mass_dialog.h"

namespace linkage::ui {

namespace {

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

// The estimate, with the counterweights a balance added kept: they are on the body, not in its
// outline. Refused (with the reason) as the field and the file refuse it.
bool applyEstimate(Mass& to, const Mass& e, const QString& name, QString* refusal) {
  Mass next = e;
  next.extras = to.extras;
  for (const PointMass& c : to.counterweights) {
    const double kg = next.kg + c.kg;
    const Vec2 com = (next.kg * next.com + c.kg * c.at) / kg;
    next.jKgMm2 += next.kg * (next.com - com).squaredNorm() + c.kg * (c.at - com).squaredNorm();
    next.kg = kg;
    next.com = com;
  }
  next.counterweights = to.counterweights;
  // An outline of a ship's size is no link's.
  for (const std::string& no : {massRefusal(next.kg), inertiaRefusal(next.jKgMm2)})
    if (!no.empty()) {
      *refusal = Form::tr("Estimate from Outline: on %1, %2").arg(name, QString::fromStdString(no));
      return false;
    }
  to = next;
  return true;
}

void estimateMass(Form& form, BodyId id) {
  Document* doc = form.document();
  MassDialog dialog(doc->design(), id, form.widget());
  if (dialog.exec() != QDialog::Accepted || !dialog.estimate()) return;
  const Mass e = *dialog.estimate();
  QString why;
  const QString name = QString::fromStdString(doc->design().body(id)->name);
  form.change(
      Form::tr("Estimate the mass of %1").arg(name),
      [&](Mechanism& m, QString* refusal) {
        return applyEstimate(massOf(m, id), e, name, refusal);
      },
      &why);
  if (!why.isEmpty()) form.warn(why);
}

void addCounterweights(Form& form, BodyId id) {
  Document* doc = form.document();
  form.addInfo(Form::tr("Counterweights"), [doc, id] {
    // A copy held while it is read: a loop over the counterweights of a temporary read its
    // vector after the temporary was gone (the "4.941e-321 g" of issue 26).
    const std::optional<Mass> held = doc->design().body(id)->mass;
    if (!held || held->counterweights.empty()) return Form::tr("none");
    QStringList parts;
    for (const PointMass& c : held->counterweights)
      parts << Form::tr("%1 kg at (%2)").arg(shownText(c.kg), pairText(c.at));
    return parts.join(QStringLiteral("; "));
  });
}

void fill(Form& form, const FormTarget& t) {
  Document* doc = form.document();
  const BodyId id = t.body;
  if (doc->design().body(id)->ground) return;
  auto mass = [doc, id]() -> std::optional<Mass> { return doc->design().body(id)->mass; };
  // The file reader's bounds (linkage/model.h), said with the link's name.
  auto refused = [doc, id](const std::string& why, QString* out) {
    *out =
        Form::tr("on %1, %2")
            .arg(QString::fromStdString(doc->design().body(id)->name), QString::fromStdString(why));
    return !why.empty();
  };
  form.addNumber(
      Form::tr("Mass"), [mass] { return mass() ? mass()->kg : 0.0; },
      [&form, id, refused](double v, QString* why) {
        if (refused(massRefusal(v), why)) return false;
        return form.change(
            Form::tr("Mass"), [&](Mechanism& m, QString*) { return massOf(m, id).kg = v, true; },
            why);
      },
      Form::tr("kg"));
  form.addText(
      Form::tr("Centre of mass"),
      [doc, id, mass] { return pairText(mass() ? mass()->com : middle(doc->design(), id)); },
      [&form, id](const QString& t, QString* why) {
        const std::optional<Vec2> at = parsePair(t);
        if (!at) return *why = Form::tr("give x, y in mm"), false;
        return form.change(
            Form::tr("Centre of mass"),
            [&](Mechanism& m, QString*) { return massOf(m, id).com = *at, true; }, why);
      });
  form.setTip(Form::tr("Centre of mass"), Form::tr("x, y in mm, in the drawing's coordinates"));
  form.addNumber(
      Form::tr("Moment of inertia"), [mass] { return mass() ? mass()->jKgMm2 : 0.0; },
      [&form, id, refused](double v, QString* why) {
        if (refused(inertiaRefusal(v), why)) return false;
        return form.change(
            Form::tr("Moment of inertia"),
            [&](Mechanism& m, QString*) { return massOf(m, id).jKgMm2 = v, true; }, why);
      },
      Form::tr("kg\u00b7mm\u00b2"));
  form.addButton(QString(), Form::tr("Estimate from Outline\u2026"),
                 [&form, id] { estimateMass(form, id); });
  addCounterweights(form, id);
}

// Its rows are the same for any mass: none of it is in the shape.
QString shape(const Mechanism&, const FormTarget&) {
  return QString();
}

}  // namespace

FormSection massRows() {
  return FormSection{"body", shape, fill};
}

}  // namespace linkage::ui
