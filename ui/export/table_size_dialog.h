// The rows a table export writes: steps per revolution and revolutions, asked in one small
// dialog that the motion table and the force table share.
#pragma once

#include <QString>

class QWidget;

namespace linkage::ui {

struct TableSize {
  int stepsPerRev = 360;
  int revs = 1;
};

// False when cancelled.
bool askTableSize(QWidget* parent, const QString& title, TableSize* size);

}  // namespace linkage::ui
