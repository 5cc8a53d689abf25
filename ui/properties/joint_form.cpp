// A joint's form: its title, then the rows its element kind puts there (ui/elements/).
#include "document/document.h"
#include "elements/element_ui.h"
#include "properties/forms.h"

namespace linkage::ui {

namespace {

bool takes(const Mechanism& m, const FormTarget& t) {
  return t.joint && m.contains(t.joint);
}

// Its kind's rows are made for its type and point; a pin's show the driver's when it drives.
QString shape(const Mechanism& m, const FormTarget& t) {
  const Joint* j = m.joint(t.joint);
  return QStringLiteral("%1 type %2 at %3%4")
      .arg(j->id.value)
      .arg(int(j->type.index))
      .arg(j->a.value)
      .arg(m.driver ? QStringLiteral(" driven %1").arg(m.driver->joint.value) : QString());
}

void fill(Form& form, const FormTarget& t) {
  const Mechanism& m = form.document()->design();
  form.setTitle(Form::tr("<b>Joint</b> %1")
                    .arg(QString::fromStdString(jointName(m, t.joint)).toHtmlEscaped()));
  elementUi(m.joint(t.joint)->type).form(form, t.joint);
}

}  // namespace

const FormDescriptor& jointForm() {
  static const FormDescriptor form{"joint", takes, shape, fill};
  return form;
}

}  // namespace linkage::ui
