#!/usr/bin/env bash
# The 3D view and the plane chooser in a real X window driven by xdotool (issue 27): the RSSR
# crank-rocker opened, the 3D view shown by its key (Shift+V), orbited by a left-drag in it (the
# picture and the direction of view change, nothing is selected), the plane chooser switched to
# the rocker's plane (the canvas draws the crank faint: the picture changes), a link drawn there
# (it is of the rocker's plane), the file saved with Ctrl+S and opened again in a new editor:
# a plane added with Edit > Add Plane (Shift+P); the same design, byte for byte as the probe
# hashes it, its planes and ball rod kept.
#   tests/x11/view3d_planes.sh path/to/linkage
set -euo pipefail
linkage=$1
examples="$(cd "$(dirname "$0")/../../resources/examples" && pwd)"
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
machine="$work/rssr.linkage.json"
cp "$examples/rssr-crank-rocker.linkage.json" "$machine"
start_linkage "$linkage" "$machine"
wait_probe "title: rssr.linkage.json" || fail "no probe"
wait_probe "plane: drawing" || fail "the canvas does not start on the drawing plane"
wait_probe "faint bodies: rocker" || fail "the rocker's plane is not drawn faint"

xdotool mousemove 300 420 click 1   # the canvas has the keyboard
xdotool key shift+v
wait_probe "view3d: shown" || fail "Shift+V did not show the 3D view"
wait_still 1 || fail "the picture does not settle"
read -r vx vy vw vh < <(probe "view3d" | cut -d" " -f2-5)
eye=$(probe "view3d eye")

# Orbit: a left-drag across the middle of the 3D view.
cx=$((vx + vw / 2)); cy=$((vy + vh / 2))
xdotool mousemove "$cx" "$cy" mousedown 1
for i in $(seq 1 12); do xdotool mousemove $((cx + 6 * i)) $((cy + 2 * i)); sleep 0.02; done
xdotool mouseup 1
wait_changed 1 2 || fail "the picture did not change when the 3D view was orbited"
wait_probe_gone "view3d eye: $eye" || fail "the direction of view did not change"
wait_probe "selection: " || fail "no selection line"
[ -z "$(probe selection)" ] || fail "a drag selected something: $(probe selection)"

# The plane chooser: the rocker's plane.
wait_still 3 || fail "the picture does not settle after the orbit"
read -r px py < <(probe "at combo planeChooser")
xdotool mousemove "$px" "$py" click 1
sleep 0.4
xdotool key Down Return
wait_probe "plane: rocker" || fail "the chooser did not switch the canvas to the rocker's plane"
wait_probe "faint bodies: crank" || fail "the crank is not faint on the rocker's plane"
wait_changed 3 4 || fail "the canvas did not change with the plane"

# A link drawn on the rocker's plane is of it.
xdotool mousemove 300 420 click 1
xdotool key l
click_mm -20 2
click_mm -8 14
xdotool key Return
wait_probe "history: Add link" || fail "the link was not drawn"
# Edit > Add Plane (Shift+P): the dialog's defaults (typed: the drawing plane's axes) with a
# name of ours, one undo step, the canvas on it.
xdotool key shift+p
wait_window "Add Plane" || fail "Shift+P did not open the Add Plane dialog"
xdotool key ctrl+a
xdotool type "feed"
xdotool key Return
wait_probe "plane: feed" || fail "the plane added is not the canvas's"
wait_probe "history: Add plane feed" || fail "adding a plane is not an undo step"
xdotool mousemove 300 420 click 1
xdotool key ctrl+s
wait_probe "modified: 0" || fail "Ctrl+S did not save"
design=$(probe design)
python3 - "$machine" <<'PY' || fail "the saved file lost something"
import json, sys
m = json.load(open(sys.argv[1]))
assert "rocker" in m["planes"] and "feed" in m["planes"], m.get("planes")
new = [b for b in m["bodies"] if b["name"] not in ("ground", "crank", "rocker")]
assert len(new) == 1 and new[0].get("plane") == "rocker", new
assert any(j["type"] == "ball-rod" for j in m["joints"]), m["joints"]
PY

# Opened again in a new editor: the same design.
kill "${pids[-1]}"
wait "${pids[-1]}" 2>/dev/null || true
rm -f "$work/probe.txt"
start_linkage "$linkage" "$machine"
wait_probe "title: rssr.linkage.json" || fail "the saved file did not open"
wait_probe "design: $design" || fail "the design read back is not the one saved ($(probe design) != $design)"
echo "ok: the 3D view shown and orbited, the plane chooser switched, a link drawn in the rocker's plane, a plane added, saved and reopened unchanged"
