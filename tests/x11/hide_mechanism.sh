#!/usr/bin/env bash
# A mechanism hidden from the Mechanisms panel in a real X window driven by xdotool (issue 18):
# the lockstitch machine opened, the panel shown by its key (Shift+M), the hook's row clicked
# (its body selected) and its check box clicked: the hook is no longer drawn (the
# picture changes), Ctrl+Z brings it back, Ctrl+Shift+Z hides it again, and the file saved with
# Ctrl+S holds it hidden.
#   tests/x11/hide_mechanism.sh path/to/linkage
set -euo pipefail
linkage=$1
examples="$(cd "$(dirname "$0")/../../resources/examples" && pwd)"
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
machine="$work/machine.linkage.json"
cp "$examples/lockstitch-machine.linkage.json" "$machine"
start_linkage "$linkage" "$machine"
wait_probe "title: machine.linkage.json" || fail "no probe"

xdotool mousemove 640 300 click 1   # the canvas has the keyboard
xdotool key shift+m
wait_probe "mechanism hook: shown" || fail "Shift+M did not list the hook"
wait_still 1 || fail "the picture does not settle"

read -r x y < <(probe "mechanism hook" | cut -d" " -f2,3)
xdotool mousemove "$x" "$y" click 1
wait_probe "properties: Link hook" || fail "a click on the hook's row did not select the hook"
read -r cx cy < <(probe "mechanism hook" | cut -d" " -f5,6)
xdotool mousemove "$cx" "$cy" click 1
wait_probe "mechanism hook: hidden" || fail "a click on the hook's check box did not hide it"
wait_probe "history: Hide mechanism hook" || fail "hiding is not an undo step"
wait_changed 1 2 || fail "the canvas did not change when the hook was hidden"

xdotool mousemove 640 300 click 1
xdotool key ctrl+z
wait_probe "mechanism hook: shown" || fail "Ctrl+Z did not show the hook again"
xdotool key ctrl+shift+z
wait_probe "mechanism hook: hidden" || fail "Ctrl+Shift+Z did not hide it again"

xdotool key ctrl+s
wait_probe "modified: 0" || fail "Ctrl+S did not save"
python3 - "$machine" <<'PY' || fail "the saved file does not hold the hook hidden"
import json, sys
m = json.load(open(sys.argv[1]))
entries = [e for e in m.get("mechanisms", []) if e["bodies"] == ["hook"]]
assert entries and entries[0].get("hidden") is True, m.get("mechanisms")
PY
echo "ok: the hook hidden from the Mechanisms panel, undone, redone and saved hidden"
