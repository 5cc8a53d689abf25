#!/usr/bin/env bash
# Issue 29's Find Dimensions in a real X window driven by xdotool: Ctrl+Shift+F opens it on the
# drop feed; the lower shaft's counterweight (x and y) ticked, a target added and made a shaking
# fx target, Find meets seed 003's least peak (2.382152373 N, docs/optimize.md), Apply changes
# the design as one undo step, and Ctrl+Z gives the design back as it was.
#   tests/x11/optimize_dialog.sh path/to/linkage
set -euo pipefail
linkage=$1
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
start_linkage "$linkage" drop-feed
wait_probe "title: " || fail "no probe"
wait_probe "design: " || fail "no design in the probe"
before=$(probe design)
xdotool mousemove 640 120 click 1   # the canvas has the keyboard
xdotool key ctrl+shift+f
wait_window "Find Dimensions" || fail "Ctrl+Shift+F did not open Find Dimensions"
dialog=$(xdotool search --onlyvisible --name "Find Dimensions" | tail -1)
# To the right, so that the canvas stays in reach for Ctrl+Z (no window manager here).
xdotool windowmove "$dialog" 540 60
wait_probe "optimize summary: Tick" || fail "the dialog is not in the probe"
sleep 0.5
shot opened
# The counterweights' rows follow the dimensions': the wheel over the table brings them up.
at() { probe "at optimize $1" | cut -d' ' -f1-2; }
first=$(grep -m1 -F "at optimize vary " "$work/probe.txt" | sed 's/.*: //')
xdotool mousemove ${first% *} $(( ${first#* } + 20 ))
for _ in $(seq 60); do
  grep -qF "at optimize vary lowershaft.counterweight.y: " "$work/probe.txt" && break
  xdotool click 5
  sleep 0.25
done
wait_probe "at optimize vary lowershaft.counterweight.y: " || fail "the counterweight rows never came into sight"
sleep 0.3
for axis in x y; do
  xdotool mousemove $(at "vary lowershaft.counterweight.$axis") click 1
  wait_probe "optimize vary lowershaft.counterweight.$axis: 1" || fail "the counterweight's $axis was not ticked"
done
xdotool mousemove $(at "button optAddTarget") click 1
wait_probe "optimize target 1: stroke" || fail "Add Target added no stroke target"
# Its kind: the list opened, four down (stroke, position, path, transmission, shaking), chosen.
xdotool mousemove $(at "target 1 kind") click 1
sleep 0.5
xdotool key Down Down Down Down Return
wait_probe "optimize target 1: shaking | fx | 0 |  | 1" || fail "the target did not become shaking fx <= 0"
shot target
xdotool mousemove $(at "button optFind") click 1
wait_probe "optimize result: peak shaking |fx| (N) | 20.5497" || fail "Find gave no shaking peak"
wait_probe "| 2.38215237" || fail "the peak after is not seed 003's least (2.382152373 N)"
wait_probe "at optimize button optApply: " || fail "no Apply"
sleep 0.5
shot found
grep -F "optimize result: " "$work/probe.txt"
xdotool mousemove $(at "button optApply") click 1
wait_probe "history: Find Dimensions" || fail "Apply made no undo step"
for _ in $(seq 50); do [ "$(probe design)" != "$before" ] && break; sleep 0.1; done
[ "$(probe design)" != "$before" ] || fail "Apply did not change the design"
sleep 0.5
shot applied
xdotool mousemove 200 500 click 1   # the canvas, left of the dialog
xdotool key ctrl+z
for _ in $(seq 50); do [ "$(probe design)" = "$before" ] && break; sleep 0.1; done
[ "$(probe design)" = "$before" ] || fail "Ctrl+Z did not give the design back"
sleep 0.5
shot undone
echo "ok: Find Dimensions balanced the drop feed's fx by the lower shaft's counterweight, applied, undone"
