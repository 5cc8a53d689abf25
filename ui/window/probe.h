// For the tests that drive the editor in a real X server (tests/x11/): with LINKAGE_PROBE=FILE
// in the environment, the open windows write the words a user reads (title, size, status and
// message lines, the output points' table, the velocity chain, the Properties fields, the
// history) to FILE a few times a second, atomically, so that a script can check what is shown
// as well as what is drawn; and the text caret stops blinking, so that two screenshots of a
// still window agree. Without the variable nothing runs.
#pragma once

#include <QString>

namespace linkage::ui {

// Starts the probe when LINKAGE_PROBE is set (once, for the whole application).
void startProbeFromEnvironment();
// What the probe writes, for every open window.
QString probeText();

}  // namespace linkage::ui
