// The mechanism's form (nothing or several things selected): its name, and its driver's rows.
#include "document/document.h"
#include "forms/driver_rows.h"
#include "properties/forms.h"

namespace linkage::ui {

namespace {

bool takes(const Mechanism&, const FormTarget&) {
  return true;
}

// A driver that appears or goes changes the rows.
QString shape(const Mechanism& m, const FormTarget&) {
  return m.driver ? QStringLiteral("driven %1").arg(m.driver->joint.value) : QString();
}

void fill(Form& form, const FormTarget&) {
  Document* doc = form.document();
  form.setTitle(Form::tr("<b>Mechanism</b>"));
  form.addText(
      Form::tr("Name"), [doc] { return QString::fromStdString(doc->design().name); },
      [&form](const QString& t, QString* why) {
        return form.change(
            Form::tr("Rename the mechanism"),
            [&](Mechanism& m, QString*) {
              m.name = t.toStdString();
              return true;
            },
            why);
      });
  if (doc->design().driver) addDriverRows(form);
}

}  // namespace

const FormDescriptor& mechanismForm() {
  static const FormDescriptor form{"mechanism", takes, shape, fill};
  return form;
}

}  // namespace linkage::ui
