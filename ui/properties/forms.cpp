#include "properties/forms.h"

#include <cmath>

#include "linkage/io/numbers.h"

namespace linkage::ui {

const FormDescriptor& bodyForm();
const FormDescriptor& pointForm();
const FormDescriptor& jointForm();
const FormDescriptor& slotForm();
const FormDescriptor& mechanismForm();

std::span<const FormDescriptor* const> formDescriptors() {
  static const FormDescriptor* const table[] = {&bodyForm(), &pointForm(), &jointForm(),
                                                &slotForm(), &mechanismForm()};
  return table;
}

double measured(double v) {
  return std::isfinite(v) ? parseNumber(formatNumber(v, 12)).value_or(v) : v;
}

}  // namespace linkage::ui
