#!/usr/bin/env bash
# The Cycle dock in a real X window driven by xdotool (issue 18): the lockstitch machine
# opened, the dock shown by its key (Shift+C), a window typed in its line (the kind chosen in
# its box), its crank angles shown as the solver finds them; the hook point and the needle
# point picked on the canvas (a click, a Shift+click) and watched with Shift+W: the closest
# approach in the dock and marked on the canvas; a click on the diagram turns the crank there;
# Ctrl+Z takes the clearance back; Ctrl+S saves the timing in the file.
#   tests/x11/cycle_dock.sh path/to/linkage
set -euo pipefail
linkage=$1
examples="$(cd "$(dirname "$0")/../../resources/examples" && pwd)"
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
machine="$work/machine.linkage.json"
# The example without the windows it ships: the dock starts empty and a window is typed.
python3 - "$examples/lockstitch-machine.linkage.json" "$machine" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
del m["timing"]
json.dump(m, open(sys.argv[2], "w"), indent=2)
PY
start_linkage "$linkage" "$machine"
wait_probe "title: machine.linkage.json" || fail "no probe"

xdotool mousemove 640 300 click 1   # the canvas has the keyboard
xdotool key shift+c
wait_probe "cycle: The machine's cycle diagram: add a row" || fail "Shift+C did not show the dock"
wait_still 1 || fail "the picture does not settle"

# The kind box: Window (typed to it), then the window in the line.
xdotool mousemove $(probe "at cycle kind") click 1
sleep 0.3
xdotool key W Return
sleep 0.2
xdotool mousemove $(probe "at cycle line") click 1
xdotool type --delay 20 'needle=needlebar.N:y<-185'
xdotool key Return
wait_probe "cycle entry Window 0: needle=needlebar.N:y<-185 => 131.59°–228.41°" ||
  fail "the window typed is not in the dock with its crank angles"
wait_probe "history: Add window" || fail "adding a window is not an undo step"

# The hook point K (12, -191) and the needle point N (0, -160) at crank 0, picked on the canvas.
click_mm 12 -191
xdotool keydown shift
click_mm 0 -160
xdotool keyup shift
xdotool key shift+w
wait_probe "cycle entry Clearance 0: hook.K needlebar.N => point needlebar.N: closest 4.411 mm at 210.25°" ||
  fail "Shift+W did not watch the clearance of the two points picked"
wait_probe "clearance marks: 1" || fail "the closest approach is not marked on the canvas"
wait_still 2 || fail "the picture does not settle"

# A click on the diagram at crank 250 turns the crank there (to a pixel's worth).
xdotool mousemove $(probe "at cycle 250") click 1
for _ in $(seq 50); do
  c=$(probe crank)
  awk -v c="$c" 'BEGIN { exit !(c > 248 && c < 252) }' && break
  sleep 0.1
done
awk -v c="$(probe crank)" 'BEGIN { exit !(c > 248 && c < 252) }' ||
  fail "a click on the diagram at 250 degrees left the crank at $(probe crank)"
wait_probe "cycle values: At 2" || fail "no values at the pose under the diagram"

xdotool mousemove 640 300 click 1
xdotool key ctrl+z
wait_probe_gone "cycle entry Clearance" || fail "Ctrl+Z did not take the clearance back"
wait_probe "clearance marks: 0" || fail "the mark stayed after the undo"
xdotool key ctrl+s
wait_probe "modified: 0" || fail "Ctrl+S did not save"
python3 - "$machine" <<'PY' || fail "the saved file does not hold the window"
import json, sys
m = json.load(open(sys.argv[1]))
t = m.get("timing", {})
assert t.get("windows") == ["needle=needlebar.N:y<-185"], t
assert "clearances" not in t, t
PY
echo "ok: a window typed, a clearance picked and marked, the crank turned from the diagram, undone and saved"
