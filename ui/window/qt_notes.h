// Qt's notes that tell a user of a picture program nothing: drawing a figure or a screenshot
// offscreen, Qt says on standard error that XDG_RUNTIME_DIR is not set (it is not, for root on
// a server, in CI, under cron; Qt then uses /tmp/runtime-USER and the picture is the same) and
// that the offscreen platform cannot pass size hints on. A user reading `timing --out`'s
// standard error takes them for trouble. Only these two are dropped: every other message goes
// to Qt's own handler.
#pragma once

namespace linkage::ui {

// Before the QApplication of a program that draws pictures without a window: the offscreen
// platform unless QT_QPA_PLATFORM names one, and those two notes dropped.
void prepareOffscreen();

}  // namespace linkage::ui
