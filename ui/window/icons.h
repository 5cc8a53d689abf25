// The editor's icons: SVGs in resources/icons drawn in `currentColor`, coloured here with the
// palette's text colour so that they read on light and dark palettes alike.
#pragma once

#include <QIcon>
#include <QPalette>
#include <QString>

namespace linkage::ui {

// The icon named (file name without .svg) for the palette; a null icon when there is none.
QIcon themedIcon(const QString& name, const QPalette& palette);

}  // namespace linkage::ui
