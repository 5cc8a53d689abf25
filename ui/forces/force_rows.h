// The Properties rows of forces, as sections of the panel's forms (forms/form.h): a moving
// link's mass properties, typed or estimated from its outline (mass_dialog.h), and its
// counterweights (mass_rows.cpp); the loads on a link (torques) or at a point (forces), each
// with the window of crank angles it acts in (load_rows.cpp). Each change is one undo step.
// The forces' feature adds them to the panel (ui/window/forces_feature.cpp).
#pragma once

#include <QString>
#include <optional>
#include <vector>

#include "forms/form.h"

namespace linkage::ui {

// All of them, in the order they follow a form's own rows: a link's mass, then its loads.
std::vector<FormSection> forceSections();

// A moving link's mass rows (on the "body" form).
FormSection massRows();
// The loads' rows on the form `form`: "body" (the torques on a moving link) or "point" (the
// forces at it).
FormSection loadRows(const char* form);

// "x, y" as typed (a comma, a semicolon or spaces between): two finite numbers.
std::optional<Vec2> parsePair(const QString& text);
// "x, y" rounded for people; a component that is rounding next to the other (the x of a
// counterweight placed straight below its pivot, -2.8e-15) reads 0.
QString pairText(const Vec2& v);

}  // namespace linkage::ui
