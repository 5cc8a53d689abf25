#!/usr/bin/env bash
# The hook point's clearance to the needle as a segment (issue 26, item 7), picked in a real X
# window driven by xdotool: the lockstitch machine (without the clearance it ships), the hook
# point K clicked, the needle's point N and the needle bar's top B (its rod's pin) added with
# Shift+click, Shift+W: the Cycle dock watches K to the segment needlebar.N-B and says that they
# meet, where (4.74 mm above the needle's point, at crank 206.57) and the canvas marks it with
# the needle where it is then; Ctrl+S keeps it in the file's timing.
#   tests/x11/cycle_clearance_segment.sh path/to/linkage
set -euo pipefail
linkage=$1
examples="$(cd "$(dirname "$0")/../../resources/examples" && pwd)"
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
machine="$work/machine.linkage.json"
python3 - "$examples/lockstitch-machine.linkage.json" "$machine" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
m["timing"].pop("clearances", None)
json.dump(m, open(sys.argv[2], "w"), indent=2)
PY
start_linkage "$linkage" "$machine"
wait_probe "title: machine.linkage.json" || fail "no probe"
wait_still 1 || fail "the picture does not settle"

# At crank 0: K (12, -191), N (0, -160), B (0, -29), where the rod's pin and the needle bar's
# block in its guide are (a click there selects the joint).
click_mm 12 -191
xdotool keydown shift
click_mm 0 -160
click_mm 0 -29
xdotool keyup shift
xdotool key shift+w
wait_probe "cycle entry Clearance 0: hook.K needlebar.N-B => segment needlebar.N-B: 0 mm, meets it at 206.57°, 4.74 mm from needlebar.N" ||
  fail "Shift+W on a point and two points of the needle bar did not watch the segment"
wait_probe "history: Add clearance" || fail "watching the clearance is not an undo step"
wait_probe "clearance mark: hook.K – segment needlebar.N-B: meets it at 206.57°" ||
  fail "the canvas does not mark where the hook point meets the needle"
wait_probe "(part of 2 points)" || fail "the mark does not draw the needle where it is then"
wait_still 2 || fail "the picture does not settle"

xdotool mousemove 640 300 click 1
xdotool key ctrl+s
wait_probe "modified: 0" || fail "Ctrl+S did not save"
python3 - "$machine" <<'PY' || fail "the saved file does not hold the segment clearance"
import json, sys
t = json.load(open(sys.argv[1]))["timing"]
assert t.get("clearances") == [{"between": ["hook.K", "needlebar.N-B"]}], t
PY
echo "ok: a point and two points of the needle bar watched as the segment, its meeting shown and saved"
