// The forms of the Properties panel, one per kind of thing selected, each described once in its
// own file (mechanism_form.cpp, body_form.cpp, point_form.cpp, joint_form.cpp, slot_form.cpp)
// and registered in one table (forms.cpp), as the element kinds are: the panel fills the first
// form that takes what is selected, then the sections other folders add to it (the forces'
// mass and loads: forms/form.h, FormSection). Nothing else branches on what is selected.
#pragma once

#include <QString>
#include <span>

#include "forms/form.h"

namespace linkage::ui {

struct FormDescriptor {
  const char* name;  // what sections name to join it: "body"
  // It is the form of `t` (the one thing selected; none: the mechanism's).
  bool (*takes)(const Mechanism& m, const FormTarget& t);
  // What its rows are made from (a bar's two points, a joint's type): they are made anew when
  // it changes and only refreshed while it stays, so that an edit or an undo that changes it
  // (a bar turned plate, a point gone) makes them again, never reads what is gone.
  QString (*shape)(const Mechanism& m, const FormTarget& t);
  // Its title and rows.
  void (*fill)(Form& form, const FormTarget& t);
};

// In the order they are asked; the mechanism's, which takes anything, last.
std::span<const FormDescriptor* const> formDescriptors();

// A length or angle measured between points, to 12 digits: the 40 typed comes back 40, not the
// 39.99999999999999 that the coordinates' last bits make of it.
double measured(double v);

}  // namespace linkage::ui
