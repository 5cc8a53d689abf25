// The driver's rows: its speed, direction and start angle, and what crank angle 0 is. On the
// mechanism's form and on its pin's (the pin that drives it, ui/elements/pin_ui.cpp).
#pragma once

namespace linkage::ui {

class Form;

// The document has a driver.
void addDriverRows(Form& form);

}  // namespace linkage::ui
