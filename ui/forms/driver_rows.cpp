#include "forms/driver_rows.h"

#include <cmath>

#include "document/document.h"
#include "document/shown_numbers.h"
#include "forms/form.h"

namespace linkage::ui {

namespace {
// Ten turns either way: enough for any start (a belt's slower shaft included); beyond it the
// crank would be tracked for ages to reach angle 0.
constexpr double kMaxStartDeg = 3600;

bool setSpeed(Form& form, double v, QString* why) {
  if (!(v > 0)) {
    *why = Form::tr("the speed must be positive");
    return false;
  }
  return form.change(
      Form::tr("Driver speed"),
      [&](Mechanism& m, QString*) {
        m.driver->rpm = v;
        return true;
      },
      why);
}

// The file's start_deg, as the editor shows it: crank angle 0 is the drawing turned on by it
// in the driving direction. A new start angle turns the crank to 0 at once, so that the crank
// is seen to start there (the drawing itself stays as it is).
bool setStart(Form& form, double v, QString* why) {
  if (!(std::abs(v) <= kMaxStartDeg)) {
    *why = Form::tr("the start angle must be between -%1 and %1 degrees").arg(kMaxStartDeg);
    return false;
  }
  if (!form.change(
          Form::tr("Driver start angle"),
          [&](Mechanism& m, QString*) {
            m.driver->startDeg = v;
            return true;
          },
          why))
    return false;
  if (form.document()->solved()) form.document()->setCrankDeg(0);
  return true;
}
}  // namespace

void addDriverRows(Form& form) {
  Document* doc = form.document();
  form.addNumber(
      Form::tr("Driver speed"), [doc] { return doc->design().driver->rpm; },
      [&form](double v, QString* why) { return setSpeed(form, v, why); }, Form::tr("rpm"));
  form.addChoice(
      Form::tr("Direction"), {Form::tr("counter-clockwise"), Form::tr("clockwise")},
      [doc] { return doc->design().driver->direction == Direction::Cw ? 1 : 0; },
      [&form](int i) {
        QString why;
        form.change(
            Form::tr("Driver direction"),
            [&](Mechanism& m, QString*) {
              m.driver->direction = i == 1 ? Direction::Cw : Direction::Ccw;
              return true;
            },
            &why);
      });
  form.addNumber(
      Form::tr("Start angle"), [doc] { return doc->design().driver->startDeg; },
      [&form](double v, QString* why) { return setStart(form, v, why); }, QStringLiteral("\u00b0"));
  form.setTip(Form::tr("Start angle [\u00b0]"),
              Form::tr("Crank angle 0 (Home, where the plots and tables start) is the drawing "
                       "turned on by this angle in the driving direction"));
  form.addInfo(Form::tr("Crank 0 is"), [doc] {
    const Driver& d = *doc->design().driver;
    if (d.startDeg == 0) return Form::tr("the drawing as it is");
    return Form::tr("the drawing turned %1\u00b0 %2")
        .arg(shownText(d.startDeg))
        .arg(d.direction == Direction::Cw ? Form::tr("clockwise") : Form::tr("counter-clockwise"));
  });
}

}  // namespace linkage::ui
