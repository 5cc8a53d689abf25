#!/usr/bin/env bash
# The editor in a real X server (Xvfb), driven as a user would with xdotool: start it on an
# example, press Space: two screenshots a moment apart differ (it animates); pause, press I: the
# instant-centre overlay appears (the picture changes), press I again: it is gone (the picture
# is as before, to the pixel).
#   tests/x11/animate_and_overlay.sh path/to/linkage
set -euo pipefail
linkage=$1
source "$(dirname "$0")/x11_session.sh"
start_x11
start_linkage "$linkage" wanzer-inversion-2

xdotool mousemove 300 300 click 1   # the canvas has the keyboard
wait_still 1 || fail "the picture does not settle after start"
xdotool key space
wait_changed 1 2 || fail "pressing Space did not start the animation"
sleep 0.3
wait_changed 2 3 || fail "the picture did not change while playing"
xdotool key space                   # pause
wait_still 5 || fail "the picture still changes after pausing"
sleep 0.3
shot 4
same 4 5 || fail "the picture changed while paused"
xdotool key i
wait_changed 5 6 || fail "pressing I did not show the instant centres"
xdotool key i
wait_same 5 7 || fail "pressing I again did not hide the instant centres"
echo "ok: animates, pauses, overlay toggles"
