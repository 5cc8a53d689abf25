#!/usr/bin/env bash
# Issue 28, "Design from the motion", in a real X window driven by xdotool: a follower drawn
# without a cam (the cam example's block in its slot, its cam joint taken out of the file) is
# given one from its point's right-click menu (Drive by a Cam > Roller, Cam on cam); the Cam
# dock comes up showing it; a rise typed in its table, a segment's end dragged on its plots and
# Find Base pressed are one undo step each; Ctrl+Z takes the drag back; the file saved holds
# the cam as the dock shows it, and loads.
#   tests/x11/cam_design.sh path/to/linkage
set -euo pipefail
linkage=$1
examples="$(cd "$(dirname "$0")/../../resources/examples" && pwd)"
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
file="$work/follower.linkage.json"
python3 - "$examples/cam-translating-roller.linkage.json" "$file" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
m["joints"] = [j for j in m["joints"] if j["type"] != "cam"]
json.dump(m, open(sys.argv[2], "w"), indent=2)
PY
start_linkage "$linkage" "$file"
wait_probe "title: follower.linkage.json" || fail "no probe"

# The follower's roller centre R = (9, 40): its menu offers a cam on the cam's body.
read -r sx sy < <(screen_of 9 40)
xdotool mousemove "$sx" "$sy"; sleep 0.1; xdotool click 3
wait_probe "at menu item Drive by a Cam" || fail "the follower's menu has no Drive by a Cam: $(probe menu)"
xdotool mousemove $(probe "at menu item Drive by a Cam"); sleep 0.3
wait_probe "at menu item Roller, Cam on cam" || fail "no cam on the cam's body offered: $(probe menu)"
shot menu
xdotool mousemove $(probe "at menu item Roller, Cam on cam"); sleep 0.1; xdotool click 1
wait_probe "history: Drive by a Cam" || fail "Drive by a Cam made no undo step"
wait_probe "cam dock: shown" || fail "the Cam dock did not come up"
wait_probe "cam: cam.O → follower.R" || fail "the dock does not show the new cam"
[ "$(probe solved)" = 1 ] || fail "the machine with its cam is not solved"
# Base + roller 41 (the drawing's pitch circle): roller 10.25, base 30.75; rise 8 (30.75 / 4).
wait_probe "cam base: 30.75 roller: 10.25" || fail "not sized for the drawing: $(probe "cam base")"
wait_probe "cam segments: 120 cycloidal 8 | 180 dwell 0 | 300 cycloidal -8 | 360 dwell 0" ||
  fail "not the first programme"
shot made

# A rise typed in the table: the return falls as far.
xdotool mousemove $(probe "at cam cell 0 3"); sleep 0.1; xdotool click --repeat 2 1; sleep 0.2
xdotool key ctrl+a; xdotool type --delay 10 "9"; xdotool key Return
wait_probe "history: Cam Segment Rise" || fail "the rise typed is not an undo step: $(probe "cam message")"
wait_probe "cam segments: 120 cycloidal 9 | 180 dwell 0 | 300 cycloidal -9" || fail "the rise typed was not taken"

# The rise's end dragged 30 px to the right on the plots: one undo step when let go.
read -r ex ey < <(probe "at cam end 0")
xdotool mousemove "$ex" "$ey" mousedown 1
for t in 1 2 3 4 5 6; do xdotool mousemove $(( ex + 5 * t )) "$ey"; sleep 0.05; done
xdotool mouseup 1
wait_probe "history: Drag Cam Segment End" || fail "the drag made no undo step"
end=$(probe "cam segments" | cut -d" " -f1)
python3 -c "import sys; e=float('$end'); sys.exit(0 if 125 <= e <= 145 else 1)" ||
  fail "the rise's end dragged is at $end degrees"
[ "$(grep -c "history: Drag Cam Segment End" "$work/probe.txt")" = 1 ] || fail "the drag is not one step"
shot dragged

# Find Base for the custom 30 degrees: the checks say the largest is within it.
xdotool mousemove $(probe "at cam button camFindBase"); sleep 0.1; xdotool click 1
wait_probe "history: Find Cam Base" || fail "Find Base made no undo step: $(probe "cam message")"
checks=$(probe "cam checks")
python3 -c "
import re, sys
m = re.search(r'Largest pressure angle ([0-9.]+)', '''$checks''')
sys.exit(0 if m and float(m.group(1)) <= 30 else 1)" || fail "the base found breaks the limit: $checks"
shot found

# Ctrl+Z three times: the base, then the drag, then back to the typed rise's programme.
xdotool key ctrl+z; sleep 0.2; xdotool key ctrl+z
wait_probe "cam segments: 120 cycloidal 9 | 180 dwell 0" || fail "Ctrl+Z did not take the drag back"
wait_probe "cam base: 30.75 roller: 10.25" || fail "Ctrl+Z did not take the base back"
xdotool key ctrl+s
wait_probe "modified: 0" || fail "Ctrl+S did not save"
python3 - "$file" <<'PY' || fail "the saved cam is not the dock's"
import json, sys
m = json.load(open(sys.argv[1]))
c = [j for j in m["joints"] if j["type"] == "cam"]
assert len(c) == 1 and c[0]["a"] == "cam.O" and c[0]["b"] == "follower.R", c
assert abs(c[0]["base_mm"] - 30.75) < 1e-9 and abs(c[0]["roller_mm"] - 10.25) < 1e-9, c
assert [s.get("rise_mm", 0) for s in c[0]["motion"]] == [9, 0, -9, 0], c[0]["motion"]
PY
echo "ok: a cam made from a follower's menu, its rise typed, an end dragged, its base found: one undo step each; saved as shown"
