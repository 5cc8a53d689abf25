// A slot's form: its name (unique on its link), its shape (straight, or an arc through three
// points), a straight slot's ends, an arc's three points or its centre, radius and the angles
// of its ends. Every set of numbers typed is refused when it makes no curve.
#include <cmath>
#include <optional>

#include "document/document.h"
#include "linkage/edits.h"
#include "linkage/guide.h"
#include "properties/forms.h"

namespace linkage::ui {

namespace {

constexpr double kDeg = M_PI / 180;

bool takes(const Mechanism& m, const FormTarget& t) {
  return t.slot && m.contains(t.slot);
}

// An arc has other rows than a straight slot, a slot written in the world a z for each point.
QString shape(const Mechanism& m, const FormTarget& t) {
  const Slot* sl = m.slot(t.slot);
  return QStringLiteral("%1%2 %3").arg(sl->id.value).arg(sl->arc() ? " arc" : "").arg(sl->z.size());
}

void addName(Form& form, SlotId id) {
  Document* doc = form.document();
  form.addText(
      Form::tr("Name"), [doc, id] { return QString::fromStdString(doc->design().slot(id)->name); },
      [&form, doc, id](const QString& t, QString* why) {
        const Mechanism& m = doc->design();
        if (!slotNameFree(m, m.slot(id)->body, t.toStdString(), id)) {
          *why = Form::tr("the link has another slot \"%1\" (or the name has a dot)").arg(t);
          return false;
        }
        return form.change(
            Form::tr("Rename slot"),
            [&](Mechanism& n, QString*) {
              n.slot(id)->name = t.toStdString();
              return true;
            },
            why);
      });
}

// Straight or arc (bendSlot, straightenSlot): an arc is bent through a point off the middle of
// the chord (a quarter of its length out, in the slot's plane), a straight slot keeps the arc's
// ends.
void addShape(Form& form, SlotId id) {
  Document* doc = form.document();
  form.addChoice(
      Form::tr("Shape"), {Form::tr("straight"), Form::tr("arc (through three points)")},
      [doc, id] { return doc->design().slot(id)->arc() ? 1 : 0; },
      [&form, id](int i) {
        QString why;
        if (!form.change(
                Form::tr("Slot shape"),
                [&](Mechanism& m, QString* why) {
                  if (i == 0) {
                    straightenSlot(m, id);
                    return true;
                  }
                  std::string problem;
                  if (bendSlot(m, id, &problem)) return true;
                  if (why) *why = QString::fromStdString(problem);
                  return false;
                },
                &why))
          form.warn(Form::tr("The slot is not bent: %1").arg(why));
      });
}

// The slot as `probe` has it, as one edit, refused when it makes no curve.
bool applySlot(Form& form, SlotId id, const Slot& probe, QString* why) {
  std::string problem;
  if (!soundSlot(probe, &problem)) {
    *why = QString::fromStdString(problem);
    return false;
  }
  return form.change(
      Form::tr("Slot"),
      [&](Mechanism& m, QString*) {
        *m.slot(id) = probe;
        return true;
      },
      why);
}

// Sets the slot's points (mid only for an arc), its z kept.
bool setSlot(Form& form, SlotId id, const Vec2& p0, const std::optional<Vec2>& mid, const Vec2& p1,
             QString* why) {
  Slot probe = *form.document()->design().slot(id);
  probe.p0 = p0;
  probe.p1 = p1;
  probe.mid = mid;
  return applySlot(form, id, probe, why);
}

// The ground's slot written in the world: each point's z (in the order p0, (mid,) p1).
void addDepths(Form& form, SlotId id) {
  Document* doc = form.document();
  const size_t n = doc->design().slot(id)->z.size();
  for (size_t k = 0; k < n; ++k)
    form.addNumber(
        QString::fromLatin1(k == 0       ? "z0"
                            : k + 1 == n ? "z1"
                                         : "zm"),
        [doc, id, k] {
          const std::vector<double>& z = doc->design().slot(id)->z;
          return k < z.size() ? z[k] : NAN;
        },
        [&form, doc, id, k](double v, QString* why) {
          Slot probe = *doc->design().slot(id);
          if (k >= probe.z.size()) return false;
          probe.z[k] = v;
          return applySlot(form, id, probe, why);
        },
        Form::tr("mm"));
}

void addEnds(Form& form, SlotId id) {
  Document* doc = form.document();
  const char* names[4] = {"x0", "y0", "x1", "y1"};
  for (int k = 0; k < 4; ++k)
    form.addNumber(
        QString::fromLatin1(names[k]),
        [doc, id, k] {
          const Slot* s = doc->design().slot(id);
          return (k < 2 ? s->p0 : s->p1)[k % 2];
        },
        [&form, doc, id, k](double v, QString* why) {
          Vec2 p0 = doc->design().slot(id)->p0, p1 = doc->design().slot(id)->p1;
          (k < 2 ? p0 : p1)[k % 2] = v;
          return setSlot(form, id, p0, std::nullopt, p1, why);
        },
        Form::tr("mm"));
}

// An arc's three points.
void addArcPoints(Form& form, SlotId id) {
  Document* doc = form.document();
  const char* names[6] = {"x0", "y0", "xm", "ym", "x1", "y1"};
  auto point = [](Slot& s, int k) -> Vec2& { return k < 2 ? s.p0 : k < 4 ? *s.mid : s.p1; };
  for (int k = 0; k < 6; ++k)
    form.addNumber(
        QString::fromLatin1(names[k]),
        [doc, id, k, point] {
          Slot s = *doc->design().slot(id);
          return point(s, k)[k % 2];
        },
        [&form, doc, id, k, point](double v, QString* why) {
          Slot s = *doc->design().slot(id);
          point(s, k)[k % 2] = v;
          return setSlot(form, id, s.p0, s.mid, s.p1, why);
        },
        Form::tr("mm"));
}

// An arc's centre, radius and the angles of its ends (degrees about the centre): typing one
// moves its three points.
void addArcCircle(Form& form, SlotId id) {
  Document* doc = form.document();
  auto guide = [doc, id] { return *guideOf(*doc->design().slot(id)); };
  const char* circle[5] = {QT_TRANSLATE_NOOP("Form", "Centre x"),
                           QT_TRANSLATE_NOOP("Form", "Centre y"),
                           QT_TRANSLATE_NOOP("Form", "Radius"), QT_TRANSLATE_NOOP("Form", "From"),
                           QT_TRANSLATE_NOOP("Form", "To")};
  for (int k = 0; k < 5; ++k)
    form.addNumber(
        Form::tr(circle[k]),
        [guide, k] {
          const Guide g = guide();
          const double values[5] = {g.centre.x(), g.centre.y(), g.radius, g.a0 / kDeg,
                                    (g.a0 + g.sweep) / kDeg};
          return values[k];
        },
        [&form, id, guide, k](double v, QString* why) {
          const Guide g = guide();
          double c[5] = {g.centre.x(), g.centre.y(), g.radius, g.a0, g.a0 + g.sweep};
          c[k] = k < 3 ? v : v * kDeg;
          // The arc keeps its turning direction, less than a full turn from its start.
          double sweep = std::remainder(c[4] - c[3], 2 * M_PI);
          if ((sweep < 0) != (g.sweep < 0)) sweep += g.sweep < 0 ? -2 * M_PI : 2 * M_PI;
          auto at = [&](double a) {
            return Vec2(c[0] + c[2] * std::cos(a), c[1] + c[2] * std::sin(a));
          };
          if (!(c[2] > 0)) {
            *why = Form::tr("the radius must be positive");
            return false;
          }
          return setSlot(form, id, at(c[3]), at(c[3] + sweep / 2), at(c[3] + sweep), why);
        },
        k < 3 ? Form::tr("mm") : Form::tr("deg"));
}

void fill(Form& form, const FormTarget& t) {
  const Mechanism& m = form.document()->design();
  form.setTitle(
      Form::tr("<b>Slot</b> %1").arg(QString::fromStdString(m.slotLabel(t.slot)).toHtmlEscaped()));
  addName(form, t.slot);
  addShape(form, t.slot);
  if (m.slot(t.slot)->arc()) {
    addArcPoints(form, t.slot);
    // Its circle in x, y: none for the ground's arc written in the world (in a plane of its
    // own, whose circle its x, y do not show).
    if (m.slot(t.slot)->z.empty()) addArcCircle(form, t.slot);
  } else {
    addEnds(form, t.slot);
  }
  addDepths(form, t.slot);
}

}  // namespace

const FormDescriptor& slotForm() {
  static const FormDescriptor form{"slot", takes, shape, fill};
  return form;
}

}  // namespace linkage::ui
