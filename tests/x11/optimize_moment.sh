#!/usr/bin/env bash
# Issue 29's shaking moment as a Find Dimensions target in a real X window driven by xdotool: on
# the drop feed, the feed rock's counterweight (x and y) ticked, a target made shaking "moment"
# (its kind's list, then its "of" list), Find takes the peak moment from 2.4885 to 0.12587 N m
# (docs/optimize.md), Apply is one undo step and Ctrl+Z gives the design back.
#   tests/x11/optimize_moment.sh path/to/linkage
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
xdotool windowmove "$dialog" 540 60   # the canvas stays in reach for Ctrl+Z (no window manager)
wait_probe "optimize summary: Tick" || fail "the dialog is not in the probe"
sleep 0.5
at() { probe "at optimize $1" | cut -d' ' -f1-2; }
first=$(grep -m1 -F "at optimize vary " "$work/probe.txt" | sed 's/.*: //')
xdotool mousemove ${first% *} $(( ${first#* } + 20 ))
for _ in $(seq 80); do
  grep -qF "at optimize vary feedrock.counterweight.y: " "$work/probe.txt" && break
  xdotool click 5
  sleep 0.25
done
wait_probe "at optimize vary feedrock.counterweight.y: " || fail "the feed rock's counterweight rows never came into sight"
sleep 0.3
for axis in x y; do
  xdotool mousemove $(at "vary feedrock.counterweight.$axis") click 1
  wait_probe "optimize vary feedrock.counterweight.$axis: 1" || fail "the counterweight's $axis was not ticked"
done
xdotool mousemove $(at "button optAddTarget") click 1
wait_probe "optimize target 1: stroke" || fail "Add Target added no stroke target"
xdotool mousemove $(at "target 1 kind") click 1
sleep 0.5
xdotool key Down Down Down Down Return   # stroke, position, path, transmission, shaking
wait_probe "optimize target 1: shaking | fx | 0 |  | 1" || fail "the target did not become shaking"
wait_probe "at optimize target 1 of: " || fail "the target's list is not in the probe"
xdotool mousemove $(at "target 1 of") click 1
sleep 0.5
xdotool key Down Down Down Return        # fx, fy, force, moment
wait_probe "optimize target 1: shaking | moment | 0 |  | 1" || fail "the target did not become the shaking moment"
shot target
xdotool mousemove $(at "button optFind") click 1
wait_probe "optimize result: peak shaking moment |m| (N m) | 2.48851" || fail "Find gave no peak moment"
wait_probe "| 0.12587" || fail "the peak moment after is not 0.12587 N m"
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
echo "ok: Find Dimensions lowered the drop feed's shaking moment by the feed rock's counterweight, applied, undone"
