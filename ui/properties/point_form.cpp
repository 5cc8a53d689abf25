// A point's form: its name (unique on its link), its coordinates (moving the points pinned to
// it), its distance and angle from another point of its link, whether it is an output. The
// loads at it follow (the forces' section, ui/forces/).
#include <cmath>

#include "document/document.h"
#include "linkage/edits.h"
#include "properties/forms.h"

namespace linkage::ui {

namespace {

constexpr double kDeg = M_PI / 180;

bool takes(const Mechanism& m, const FormTarget& t) {
  return t.point && m.contains(t.point);
}

// Its distance and angle are from another point of its link (addPolar): those too.
QString shape(const Mechanism& m, const FormTarget& t) {
  const Point* pt = m.point(t.point);
  QString s = QStringLiteral("%1 on %2 with").arg(pt->id.value).arg(pt->body.value);
  for (const Point& p : m.points)
    if (p.body == pt->body) s += QStringLiteral(" %1").arg(p.id.value);
  return s;
}

void addName(Form& form, PointId id) {
  Document* doc = form.document();
  form.addText(
      Form::tr("Name"), [doc, id] { return QString::fromStdString(doc->design().point(id)->name); },
      [&form, doc, id](const QString& t, QString* why) {
        const Mechanism& m = doc->design();
        if (!pointNameFree(m, m.point(id)->body, t.toStdString(), id)) {
          *why = Form::tr("the link has another point \"%1\" (or the name has a dot)").arg(t);
          return false;
        }
        return form.change(
            Form::tr("Rename point"),
            [&](Mechanism& n, QString*) {
              n.point(id)->name = t.toStdString();
              return true;
            },
            why);
      });
}

// The point and the points pinned to it are one place: they move together.
void addPlace(Form& form, PointId id) {
  Document* doc = form.document();
  for (int axis = 0; axis < 2; ++axis)
    form.addNumber(
        axis ? QStringLiteral("y") : QStringLiteral("x"),
        [doc, id, axis] { return doc->design().point(id)->pos[axis]; },
        [&form, id, axis](double v, QString* why) {
          return form.change(
              Form::tr("Move point"),
              [&](Mechanism& m, QString*) {
                for (PointId q : pinnedTogether(m, id)) m.point(q)->pos[axis] = v;
                return true;
              },
              why);
        },
        Form::tr("mm"));
}

// The point's distance and angle (counter-clockwise from +x) from another point of its link,
// chosen in "From"; typing either moves the point (and the points pinned to it).
void addPolar(Form& form, PointId id) {
  Document* doc = form.document();
  const Mechanism& m0 = doc->design();
  std::vector<PointId> others;
  QStringList names;
  for (const Point& p : m0.points)
    if (p.body == m0.point(id)->body && p.id != id) {
      others.push_back(p.id);
      names << QString::fromStdString(p.name);
    }
  if (others.empty()) return;
  const std::function<int()> from = form.addSelector(Form::tr("From"), names);
  auto base = [others, from] { return others[std::max(0, from())]; };
  auto offset = [doc, id, base] {
    return Vec2(doc->design().point(id)->pos - doc->design().point(base())->pos);
  };
  auto place = [&form, id, base](double distance, double angle, QString* why) {
    return form.change(
        Form::tr("Move point"),
        [&](Mechanism& m, QString* w) {
          std::string problem;
          if (setPolar(m, id, base(), distance, angle, &problem)) return true;
          *w = QString::fromStdString(problem);
          return false;
        },
        why);
  };
  form.addNumber(
      Form::tr("Distance"), [offset] { return measured(offset().norm()); },
      [offset, place](double v, QString* why) {
        const Vec2 d = offset();
        return place(v, std::atan2(d.y(), d.x()) / kDeg, why);
      },
      Form::tr("mm"));
  form.addNumber(
      Form::tr("Angle"),
      [offset] {
        const Vec2 d = offset();
        return measured(std::atan2(d.y(), d.x()) / kDeg);
      },
      [offset, place](double v, QString* why) { return place(offset().norm(), v, why); },
      QStringLiteral("\u00b0"));
}

void addOutput(Form& form, PointId id) {
  Document* doc = form.document();
  auto isOut = [doc, id] {
    const auto& o = doc->design().outputs;
    return std::find(o.begin(), o.end(), id) != o.end();
  };
  form.addCheck(
      Form::tr("Output"), Form::tr("traced, plotted, exported"), isOut, [] { return true; },
      [&form, id](bool) {
        QString why;
        form.change(
            Form::tr("Output point"),
            [&](Mechanism& m, QString*) {
              toggleOutput(m, id);
              return true;
            },
            &why);
      });
}

void fill(Form& form, const FormTarget& t) {
  const Mechanism& m = form.document()->design();
  form.setTitle(Form::tr("<b>Point</b> %1")
                    .arg(QString::fromStdString(m.pointLabel(t.point)).toHtmlEscaped()));
  addName(form, t.point);
  addPlace(form, t.point);
  addPolar(form, t.point);
  addOutput(form, t.point);
}

}  // namespace

const FormDescriptor& pointForm() {
  static const FormDescriptor form{"point", takes, shape, fill};
  return form;
}

}  // namespace linkage::ui
