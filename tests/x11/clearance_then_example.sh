#!/usr/bin/env bash
# Issue 26, item 4, in a real X window driven by xdotool: the lockstitch machine opened by its
# example's name, the Cycle dock shown (Shift+C), the clearance "hook.K needlebar.N" typed in
# its line, computed and marked on the canvas (the marks carry labels); then File > Examples >
# slider-crank-22a-masses, Discard at the prompt (which takes the window's focus: the
# autosave writes its copy then). Opening the example fitted the view, which restyled the
# canvas's items from a list of them taken before the marks made their labels anew: the editor
# crashed (a zoom with the marks shown did too: tests/ui/test_document_stress.cpp). It must
# survive and show the new example.
#   tests/x11/clearance_then_example.sh path/to/linkage   (linkage-cli beside it)
set -euo pipefail
linkage=$1
cli="$(dirname "$linkage")/linkage-cli"
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
start_linkage "$linkage" lockstitch-machine
app=${pids[-1]}
wait_probe "title: lockstitch-machine" || fail "the lockstitch machine did not open"
alive() { kill -0 "$app" 2>/dev/null || fail "the editor stopped ($(tail -5 "$work/linkage.log"))"; }

xdotool mousemove 640 300 click 1   # the canvas has the keyboard
xdotool key shift+c
wait_probe "at cycle kind" || fail "Shift+C did not show the Cycle dock"
sleep 0.5
# The kind box: Clearance (typed to it), then the two points in the line.
xdotool mousemove $(probe "at cycle kind") click 1
sleep 0.3
xdotool type --delay 20 "Clearance"
xdotool key Return
wait_probe "cycle kind: Clearance" || fail "the kind box did not take Clearance"
xdotool mousemove $(probe "at cycle line") click 1
xdotool type --delay 20 "hook.K needlebar.N"
xdotool key Return
# (The example ships the hook point's clearance to the needle as a segment: this is the second.)
wait_probe "cycle entry Clearance 1: hook.K needlebar.N => point needlebar.N: closest" ||
  fail "the clearance typed was not computed"
wait_probe "clearance marks: 2" || fail "the closest approach is not marked on the canvas"
wait_still marked || fail "the picture does not settle"
alive

# File > Examples > slider-crank-22a-masses (the menu's order is linkage-cli's).
index=$("$cli" examples | grep -nx "slider-crank-22a-masses" | cut -d: -f1)
[ -n "$index" ] || fail "no example slider-crank-22a-masses"
xdotool key alt+f
sleep 0.3
xdotool key e
sleep 0.3
for _ in $(seq 2 "$index"); do xdotool key Down; done
xdotool key Return
wait_probe "dialog: Unsaved Changes" || fail "no prompt for the unsaved clearance"
wait_probe "at dialog button Discard" || fail "the prompt has no Discard"
xdotool mousemove $(probe "at dialog button Discard") click 1
sleep 1
alive
wait_probe "title: slider-crank-22a-masses" || fail "the new example is not shown"
wait_probe_gone "dialog: " || fail "the prompt stayed"
wait_probe "clearance marks: 0" || fail "the old machine's clearance is still marked"
wait_probe "solved: 1" || fail "the new example is not solved"
# Its drawing fills the canvas: the view was fitted to it.
wait_still shown || fail "the picture does not settle"
xdotool mousemove 640 300
xdotool key ctrl+plus ctrl+minus
sleep 0.5
alive
echo "ok: a clearance marked, another example opened over it (Discard): the editor survived"
