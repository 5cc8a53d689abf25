#!/usr/bin/env bash
# Issue 26, item 6, in a real X window driven by xdotool: a gear pair selected the ways a user
# tries (a click on a pitch circle, on the pitch point, inside a circle, a band over it), its
# ratio typed in the Properties; a right click on it opens a menu naming it, whose Edit Ratio
# puts the keyboard in the ratio's field; each edit one undo step; the file saved holds the
# ratio typed. Then the lockstitch machine's 2:1 belt, clicked on a run of the belt.
# The gear-four-bar example: the pinion on (-45, 0), pitch radius 15, in mesh with the gear on
# (0, 0), radius 30; the pitch point at (-30, 0).
#   tests/x11/select_gear.sh path/to/linkage
set -euo pipefail
linkage=$1
examples="$(cd "$(dirname "$0")/../../resources/examples" && pwd)"
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
gears="$work/gears.linkage.json"
cp "$examples/gear-four-bar.linkage.json" "$gears"
start_linkage "$linkage" "$gears"
wait_probe "title: gears.linkage.json" || fail "no probe"
gear="gear pinion.I - gear.O2"
empty() { click_mm -70 50; wait_probe "properties: Mechanism" || fail "a click on nothing kept a selection"; }

# A click on the pinion's pitch circle (its top).
click_mm -45 15
wait_probe "properties: Joint $gear" || fail "a click on the pinion's pitch circle did not select the gear"
wait_probe "selection: $gear" || fail "the selection is not the gear alone"
grep -q "field Ratio: -0.5" "$work/probe.txt" || fail "no Ratio field holding -0.5"
shot selected
# The pitch point, and inside the gear's circle away from its arm.
for at in "-30 0" "-8 -12"; do
  empty
  click_mm $at
  wait_probe "properties: Joint $gear" || fail "a click at ($at) did not select the gear"
done
# A band over both circles: the gear among what it holds.
empty
read -r x0 y0 < <(screen_of -60 20)
read -r x1 y1 < <(screen_of 15 -15)
xdotool mousemove "$x0" "$y0" mousedown 1
for t in 1 2 3 4 5; do
  xdotool mousemove $(( x0 + (x1 - x0) * t / 5 )) $(( y0 + (y1 - y0) * t / 5 )); sleep 0.05
done
xdotool mouseup 1
for _ in $(seq 50); do probe selection | grep -qF "$gear" && break; sleep 0.1; done
probe selection | grep -qF "$gear" || fail "a band over the gears did not select the gear: $(probe selection)"

# Selected by a click (the top of the gear's circle), its ratio typed: one undo step, solved.
empty
click_mm 0 30
wait_probe "properties: Joint $gear" || fail "a click on the gear's pitch circle did not select it"
click_field "Ratio"
xdotool key ctrl+a; xdotool type --delay 10 -- "-0.25"; xdotool key Return
wait_probe "field Ratio: -0.25" || fail "the ratio typed was not taken"
wait_probe "history: Gear ratio" || fail "the ratio typed is not an undo step"
[ "$(probe solved)" = 1 ] || fail "not solved after the ratio was typed"

# A right click on the pitch circle: a menu naming the gear, with Edit Ratio.
read -r sx sy < <(screen_of 30.5 0)
xdotool mousemove "$sx" "$sy"; sleep 0.1; xdotool click 3
wait_probe "menu: " || fail "a right click on the gear opened no menu"
probe menu | grep -qF "$gear" || fail "the menu does not name the gear: $(probe menu)"
probe menu | grep -qF "Gears in Mesh" || fail "the menu has no Gears in Mesh: $(probe menu)"
wait_probe "at menu item Edit Ratio..." || fail "the menu has no Edit Ratio: $(probe menu)"
shot menu
xdotool mousemove $(probe "at menu item Edit Ratio...") click 1
wait_probe "focus: QLineEdit" || fail "Edit Ratio did not put the keyboard in a field"
xdotool type --delay 10 -- "-0.4"; xdotool key Return
wait_probe "field Ratio: -0.4" || fail "the ratio typed after Edit Ratio was not taken"
[ "$(grep -c "history: Gear ratio" "$work/probe.txt")" = 2 ] || fail "not two ratio edits in the history"
xdotool key ctrl+s
wait_probe "modified: 0" || fail "Ctrl+S did not save"
python3 - "$gears" <<'PY' || fail "the saved gear's ratio is not -0.4"
import json, sys
m = json.load(open(sys.argv[1]))
g = [j for j in m["joints"] if j["type"] == "gear"]
assert len(g) == 1 and g[0]["ratio"] == -0.4, g
PY

# The lockstitch machine's 2:1 belt (armshaft.O (0, 0) to hook.L (0, -200), pulleys of
# radius 200/6 and 200/12): a click on its run on the +x side, halfway down.
xdotool key ctrl+o
wait_window "Open Mechanism" || fail "Ctrl+O did not open the dialog"
sleep 0.5
xdotool key ctrl+a; xdotool type --delay 10 "$examples/lockstitch-machine.linkage.json"; xdotool key Return
wait_probe "title: lockstitch-machine.linkage.json" || fail "the lockstitch machine did not open"
run=$(python3 -c "import math; d=200; ra=d/6; rb=d/12; a=(ra-rb)/d; c=math.sqrt(1-a*a)
# u = (0, -1), perp(u) = (1, 0): the normal n = a u + c perp(u) on the +x side
n=(c, -a); pa=(ra*n[0], ra*n[1]); pb=(rb*n[0], -d+rb*n[1]); print((pa[0]+pb[0])/2, (pa[1]+pb[1])/2)")
click_mm $run
wait_probe "properties: Joint gear " || fail "a click on the belt's run at ($run) did not select it"
probe properties | grep -qF "gear armshaft.O - hook.L" || fail "not the 2:1 belt: $(probe properties)"
grep -q "field Ratio: 2" "$work/probe.txt" || fail "the belt's ratio is not shown as 2"
shot belt
echo "ok: a gear selected by its circles, pitch point, centre area and a band; its ratio typed and edited from its menu; saved; a belt selected by its run"
