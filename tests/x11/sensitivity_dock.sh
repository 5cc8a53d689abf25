#!/usr/bin/env bash
# Issue 29 in a real X window driven by xdotool: Shift+S brings the Sensitivity dock up with the
# Wanzer needle's dimensions ranked; Ctrl+Shift+F opens Find Dimensions, its Close closes it.
#   tests/x11/sensitivity_dock.sh path/to/linkage
set -euo pipefail
linkage=$1
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
start_linkage "$linkage" wanzer-inversion-2
wait_probe "title: " || fail "no probe"
xdotool mousemove 640 120 click 1   # the canvas has the keyboard
xdotool key shift+s
wait_probe "sensitivity: Matters most: " || fail "Shift+S did not rank the dimensions"
wait_probe "sensitivity bar triangle.E-G: " || fail "the triangle's side EG is not among the bars"
shot dock
xdotool key ctrl+shift+f
wait_window "Find Dimensions" || fail "Ctrl+Shift+F did not open Find Dimensions"
shot dialog
# Its Close button, in the dialog's bottom right corner (no window manager here to focus it).
dialog=$(xdotool search --onlyvisible --name "Find Dimensions" | tail -1)
eval "$(xdotool getwindowgeometry --shell "$dialog")"
xdotool mousemove $((X + WIDTH - 50)) $((Y + HEIGHT - 22)) click 1
for _ in $(seq 50); do xdotool search --onlyvisible --name "Find Dimensions" >/dev/null 2>&1 || break; sleep 0.1; done
xdotool search --onlyvisible --name "Find Dimensions" >/dev/null 2>&1 && fail "Close did not close the dialog"
echo "ok: the Sensitivity dock by Shift+S, Find Dimensions by Ctrl+Shift+F"
