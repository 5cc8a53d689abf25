// A link's form: its name (unique), its points, a bar's length and angle (editing them moves
// its second point), a triangle plate's three sides. A moving link's mass and loads follow
// (the forces' sections, ui/forces/). Under its sides, what its dimensions do to the output
// point at the crank angle (properties/dimension_effect.h).
#include <cmath>

#include "document/document.h"
#include "linkage/edits.h"
#include "properties/dimension_effect.h"
#include "properties/forms.h"

namespace linkage::ui {

namespace {

constexpr double kDeg = M_PI / 180;

bool takes(const Mechanism& m, const FormTarget& t) {
  return t.body && m.contains(t.body);
}

// Whether it is the ground, and its points: a bar (two) or a plate (three) has rows of its own.
QString shape(const Mechanism& m, const FormTarget& t) {
  QString s =
      QStringLiteral("%1%2 points").arg(t.body.value).arg(m.body(t.body)->ground ? " ground" : "");
  for (const Point& p : m.points)
    if (p.body == t.body) s += QStringLiteral(" %1").arg(p.id.value);
  return s;
}

void addName(Form& form, BodyId id) {
  Document* doc = form.document();
  form.addText(
      Form::tr("Name"), [doc, id] { return QString::fromStdString(doc->design().body(id)->name); },
      [&form, doc, id](const QString& t, QString* why) {
        if (!bodyNameFree(doc->design(), t.toStdString(), id)) {
          *why = Form::tr("another link is called \"%1\"").arg(t);
          return false;
        }
        return form.change(
            Form::tr("Rename link"),
            [&](Mechanism& m, QString*) {
              m.body(id)->name = t.toStdString();
              return true;
            },
            why);
      });
}

// A bar: its length and angle, measured from its first point; editing them moves the second.
void addBar(Form& form, PointId p0, PointId p1) {
  Document* doc = form.document();
  auto ends = [doc, p0, p1] {
    return std::make_pair(doc->design().point(p0)->pos, doc->design().point(p1)->pos);
  };
  auto moveSecond = [&form, p1](const QString& text, const Vec2& to, QString* why) {
    return form.change(
        text,
        [&](Mechanism& m, QString*) {
          for (PointId q : pinnedTogether(m, p1)) m.point(q)->pos = to;
          return true;
        },
        why);
  };
  form.addNumber(
      Form::tr("Length"), [ends] { return (ends().second - ends().first).norm(); },
      [ends, moveSecond](double v, QString* why) {
        if (!(v > 0)) {
          *why = Form::tr("a length must be positive");
          return false;
        }
        const auto [a, b] = ends();
        const Vec2 d = (b - a).normalized();
        return moveSecond(Form::tr("Bar length"), a + v * d, why);
      },
      Form::tr("mm"));
  form.addNumber(
      Form::tr("Angle"),
      [ends] {
        const Vec2 d = ends().second - ends().first;
        return std::atan2(d.y(), d.x()) / kDeg;
      },
      [ends, moveSecond](double v, QString* why) {
        const auto [a, b] = ends();
        const double r = (b - a).norm();
        return moveSecond(Form::tr("Bar angle"),
                          a + r * Vec2(std::cos(v * kDeg), std::sin(v * kDeg)), why);
      },
      QStringLiteral("\u00b0"));
}

// Sides named by their points, in the order linkage/edits.h's setSideLengths takes them; each
// typed side re-solves the mechanism at once.
void addTriangle(Form& form, BodyId id) {
  Document* doc = form.document();
  std::vector<QString> names;
  for (const Point& p : doc->design().points)
    if (p.body == id) names.push_back(QString::fromStdString(p.name));
  const int ends[3][2] = {{0, 1}, {1, 2}, {0, 2}};
  for (int k = 0; k < 3; ++k)
    form.addNumber(
        Form::tr("Side %1%2").arg(names[ends[k][0]], names[ends[k][1]]),
        [doc, id, k] {
          const std::vector<double> s = sideLengths(doc->design(), id);
          return s.size() == 3 ? measured(s[k]) : NAN;
        },
        [&form, doc, id, k](double v, QString* why) {
          std::vector<double> sides = sideLengths(doc->design(), id);
          if (sides.size() != 3) return false;
          sides[k] = v;
          return form.change(
              Form::tr("Plate sides"),
              [&](Mechanism& m, QString* w) {
                std::string problem;
                if (setSideLengths(m, id, sides, &problem)) return true;
                *w = QString::fromStdString(problem);
                return false;
              },
              why);
        },
        Form::tr("mm"));
}

void fill(Form& form, const FormTarget& t) {
  Document* doc = form.document();
  const BodyId id = t.body;
  const Body* b = doc->design().body(id);
  form.setTitle(Form::tr("<b>Link</b> %1").arg(QString::fromStdString(b->name).toHtmlEscaped()));
  addName(form, id);
  std::vector<PointId> pts;
  for (const Point& p : doc->design().points)
    if (p.body == id) pts.push_back(p.id);
  form.addInfo(Form::tr("Points"), [doc, id] {
    QStringList names;
    for (const Point& p : doc->design().points)
      if (p.body == id) names << QString::fromStdString(p.name);
    return names.join(QStringLiteral(", "));
  });
  if (pts.size() == 3 && !b->ground) addTriangle(form, id);
  if (pts.size() == 2 && !b->ground) addBar(form, pts[0], pts[1]);
  // What its dimensions do to the output, exactly, at this crank angle (issue 29).
  if (!b->ground && !doc->design().outputs.empty())
    form.addInfo(Form::tr("Effect"), [doc, id] { return dimensionEffect(*doc, id); });
}

}  // namespace

const FormDescriptor& bodyForm() {
  static const FormDescriptor form{"body", takes, shape, fill};
  return form;
}

}  // namespace linkage::ui
