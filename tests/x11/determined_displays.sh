#!/usr/bin/env bash
# What is shown is what the solver determined (issue 19, items 1-5), in a real X window driven
# by xdotool, read back through the editor's probe (the words on the screen) and screenshots:
# a file that cannot be solved leaves no velocity chain behind; a pin deleted: no numbers, no
# play, Fit stays at millimetres; a start angle of 1e300 refused without widening the window;
# a fixed pivot's velocity 0.000, not -0.000; a Ctrl+drag named in the history.
#   tests/x11/determined_displays.sh path/to/linkage
set -euo pipefail
linkage=$1
examples="$(cd "$(dirname "$0")/../../resources/examples" && pwd)"
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
fourbar="$work/four-bar.linkage.json"
# The four-bar with the rocker's pivot an output too (its velocity, computed through the
# turning rocker, is rounding of 0); and the same with a coupler 1 mm long: it cannot close.
python3 - "$examples/four-bar-crank-rocker.linkage.json" "$fourbar" "$work/short.linkage.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
m["outputs"]["points"].append("rocker.O4")
json.dump(m, open(sys.argv[2], "w"), indent=2)
for b in m["bodies"]:
    if b["name"] == "coupler":
        b["points"]["B"] = [11, 17.320508075688775]
json.dump(m, open(sys.argv[3], "w"))
PY
start_linkage "$linkage" "$fourbar"
wait_probe "title: four-bar.linkage.json" || fail "no probe"
width=$(probe size | cut -dx -f1)

# 3. A file that cannot be solved, opened after one that can: no chain left of the first.
click_tab "Instant Centres"
wait_probe "chain: v of coupler.P" || fail "no velocity chain on the four-bar"
xdotool key ctrl+o
wait_window "Open Mechanism" || fail "Ctrl+O did not open the dialog"
sleep 0.5
xdotool key ctrl+a; xdotool type --delay 10 "$work/short.linkage.json"; xdotool key Return
wait_probe "title: short.linkage.json" || fail "the short file did not open"
wait_probe "chain: Not solved:" || fail "the chain of the previous file stayed"
grep -q "^chain:.*mm/s" "$work/probe.txt" && fail "a velocity is still shown"
xdotool mousemove 200 150 click 1   # the window has the keyboard again (no window manager)
xdotool key ctrl+o
wait_window "Open Mechanism" || fail "Ctrl+O did not open the dialog again"
sleep 0.5
xdotool key ctrl+a; xdotool type --delay 10 "$fourbar"; xdotool key Return
wait_probe "title: four-bar.linkage.json" || fail "the four-bar did not open again"
xdotool mousemove 200 150 click 1
click_tab "Properties"

# 1. The coupler's pin to the rocker deleted: coupler and rocker hang free.
click_mm 72.748 48.348
wait_probe "properties: Joint" || fail "a click on coupler.B did not select its pin"
xdotool key Delete
wait_probe "output: coupler.P | not determined | not determined | not determined" \
  || fail "the output table still shows numbers"
wait_probe "outputs note: the motion of coupler.P is not determined by the driver" || fail "no reason"
xdotool mousemove 200 150 click 1   # the canvas, on nothing: it has the keyboard
xdotool key space
wait_probe "message: Cannot play: the motion is not determined" || fail "Space did not say why"
[ "$(probe playing)" = 0 ] || fail "it plays"
# 4. Fit stays at millimetres (it zoomed out to metres: 0.02 px/mm).
xdotool key f
sleep 0.5
awk -v z="$(probe zoom)" 'BEGIN { exit !(z > 2) }' || fail "Fit zoomed out to $(probe zoom) px/mm"
shot undetermined
xdotool key ctrl+z
wait_probe_gone "not determined" || fail "undo did not bring the numbers back"

# 2. A start angle of 1e300: refused, the window as wide as it was, the crank still plays.
xdotool mousemove 200 150 click 1
wait_probe "field Start angle [°]: 0" || fail "no start angle field"
click_field "Start angle [°]"
xdotool key ctrl+a; xdotool type --delay 10 "1e300"; xdotool key Return
wait_probe "message: Start angle [°]: the start angle must be between -3600 and 3600" \
  || fail "1e300 was not refused"
[ "$(probe size | cut -dx -f1)" = "$width" ] || fail "the window widened to $(probe size)"
xdotool mousemove 200 150 click 1
xdotool key Home space
wait_probe "playing: 1" || fail "Space does not play after the refused angle"
xdotool key space

# 5. The rocker's fixed pivot: its velocity is 0.000, not -0.000; a Ctrl+drag of coupler.P is
# "Move coupler.P" in the history.
xdotool key Home
wait_probe "output: rocker.O4 |" || fail "rocker.O4 is not an output"
grep "output: rocker.O4" "$work/probe.txt" | grep -q -- "-0.000" && fail "-0.000 printed"
wait_probe "output: rocker.O4 | 60.000, 0.000 | 0.000, 0.000 | 0.000, 0.000" \
  || fail "the fixed pivot's motion is not exactly 0"
read -r sx sy < <(screen_of 30.293 55.244)
xdotool mousemove "$sx" "$sy" keydown ctrl mousedown 1
for i in 1 2 3 4 5; do xdotool mousemove "$((sx + 4 * i))" "$((sy - 2 * i))"; sleep 0.05; done
xdotool mouseup 1 keyup ctrl
wait_probe "history: Move coupler.P" || fail "the drag is not named in the history"
grep -q "history: Move ?" "$work/probe.txt" && fail "Move ? in the history"
echo "ok: no chain left behind, undetermined motion shown as such, 1e300 refused, no -0.000, Move coupler.P"
