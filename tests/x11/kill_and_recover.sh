#!/usr/bin/env bash
# No work lost (issue 19): an edit typed in a real X window, the window left (another opened:
# the copy is written), the editor killed with kill -9; started again, it offers the work,
# Recover (the default, Return) opens it unsaved with the user's file untouched, and the
# recovered design is the edited one byte for byte (the SHA-1 of what Save writes, before the
# kill and after the recovery, and of the file saved with Ctrl+S).
#   tests/x11/kill_and_recover.sh path/to/linkage
set -euo pipefail
linkage=$1
examples="$(cd "$(dirname "$0")/../../resources/examples" && pwd)"
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
file="$work/four-bar.linkage.json"
cp "$examples/four-bar-crank-rocker.linkage.json" "$file"
cp "$file" "$work/original.json"
start_linkage "$linkage" "$file"
wait_probe "title: four-bar.linkage.json" || fail "no probe"

# The edit: coupler.P's x typed.
click_mm 30.293 55.244
wait_probe "properties: Point coupler.P" || fail "a click on coupler.P did not select it"
click_field "x [mm]"
xdotool key ctrl+a; xdotool type --delay 10 "31.25"; xdotool key Return
wait_probe "field x [mm]: 31.25" || fail "the typed x was not taken"
wait_probe "modified: 1" || fail "the edit did not make the document modified"
edited=$(probe design)
# Leaving the window (another one opened, and the keyboard given to it) writes the copy.
xdotool key ctrl+shift+n
wait_window "untitled" || fail "Ctrl+Shift+N did not open another window"
xdotool windowfocus "$(xdotool search --onlyvisible --name "untitled" | head -1)"
copies="$HOME/.local/share"
for _ in $(seq 100); do
  find "$copies" -name '*.meta.json' 2>/dev/null | grep -q . && break
  sleep 0.1
done
find "$copies" -name '*.meta.json' | grep -q . || fail "no copy written when the window lost focus"
sleep 0.3
kill -9 "${pids[-1]}"
wait "${pids[-1]}" 2>/dev/null || true
for _ in $(seq 50); do
  xdotool search --onlyvisible --name "Linkage" >/dev/null 2>&1 || break
  sleep 0.1
done
cmp -s "$file" "$work/original.json" || fail "the file changed before any save"

# Started again: the offer, Recover.
rm -f "$work/probe.txt"
"$linkage" >"$work/linkage2.log" 2>&1 &
pids+=($!)
wait_window "Recover Unsaved Work" || fail "no offer to recover ($(cat "$work/linkage2.log"))"
sleep 0.3
shot offer
xdotool key Return
wait_probe "title: four-bar.linkage.json" || fail "the recovered work did not open"
wait_probe "modified: 1" || fail "the recovered work is not marked unsaved"
[ "$(probe design)" = "$edited" ] || fail "the recovered design differs from the edited one"
cmp -s "$file" "$work/original.json" || fail "recovering wrote over the file"
find "$copies" -name '*.meta.json' | grep -q . && sleep 1  # the recovered copy removed
win=$(xdotool search --onlyvisible --name "four-bar" | head -1)
xdotool windowmove "$win" 0 0 windowsize "$win" 1280 900
# The window active and settled where it was put before the key (on a loaded machine the
# click could land while it was still moving, and the key go nowhere).
xdotool windowactivate --sync "$win" 2>/dev/null || true
wait_still settled || fail "the recovered window does not settle"
xdotool mousemove 200 150 click 1
wait_probe "focus: linkage::ui::CanvasView" || fail "the canvas did not take the keyboard"
xdotool key ctrl+s
wait_probe "modified: 0" || fail "Ctrl+S did not save the recovered work"
[ "$(sha1sum <"$file" | cut -d' ' -f1)" = "$edited" ] || fail "the saved file is not the edited design"
echo "ok: edited, killed with kill -9, recovered unsaved, saved: byte for byte the edited design"
