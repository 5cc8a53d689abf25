// QCustomPlot for this project: its header spells `signals`, which the project turns off
// (ui/CMakeLists.txt: Mechanism::slots is a member name). Include this, never <qcustomplot.h>.
#pragma once

#define signals Q_SIGNALS
#include <qcustomplot.h>
#undef signals
