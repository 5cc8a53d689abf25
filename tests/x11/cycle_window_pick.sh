#!/usr/bin/env bash
# A timing window made by picking (issue 26 item 8) in a real X window driven by xdotool: the
# lockstitch machine, which ships its windows; the Cycle dock by Shift+C; Window in its kind box
# shows the window form; its Pick, then a click on the take-up eye on the canvas chooses
# takeup.E; "above" chosen in its box, the name typed, Return adds it (one undo step); its
# threshold line dragged down on the diagram: the window's text and ends follow before the
# release, the release is one undo step; Ctrl+S: the file holds the window at the level the
# dock shows, and linkage-cli timing of the saved file gives the crank angles the dock shows.
#   tests/x11/cycle_window_pick.sh path/to/linkage   (linkage-cli beside it)
set -euo pipefail
linkage=$1
cli="$(dirname "$linkage")/linkage-cli"
examples="$(cd "$(dirname "$0")/../../resources/examples" && pwd)"
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
machine="$work/machine.linkage.json"
cp "$examples/lockstitch-machine.linkage.json" "$machine"
start_linkage "$linkage" "$machine"
wait_probe "title: machine.linkage.json" || fail "no probe"

xdotool mousemove 640 300 click 1   # the canvas has the keyboard
xdotool key shift+c
wait_probe "cycle entry Window 0: needle=needlebar.N:y<-185 => 131.59°–228.41°" ||
  fail "Shift+C did not show the machine's own windows"
wait_still 1 || fail "the picture does not settle"

# Window in the kind box (typed to it) shows the form; Pick, then the take-up eye E, at
# (52.258, 79.192) at crank 0, clicked on the canvas.
grep -q "at cycle window pick" "$work/probe.txt" && fail "the window form is shown before it is asked for"
xdotool mousemove $(probe "at cycle kind") click 1
sleep 0.3
xdotool key W Return
wait_probe "at cycle window pick: " || fail "choosing Window did not show the window form"
xdotool mousemove $(probe "at cycle window pick") click 1
wait_probe "cycle picking: 1" || fail "Pick did not start picking"
wait_probe "hint: Pick the window's point" || fail "the status bar does not say what to click"
click_mm 52.258 79.192
wait_probe "cycle window: new; name takeup; point takeup.E; axis y; below;" ||
  fail "the click on the eye did not choose takeup.E"
wait_probe "cycle picking: 0" || fail "picking did not end with the click"
# The threshold was put in the eye's stroke (about 30 to 79 mm).
level=$(probe "cycle window" | sed -n 's/.*; level \([^;]*\);.*/\1/p')
awk -v l="$level" 'BEGIN { exit !(l > 40 && l < 70) }' || fail "the threshold $level is not mid-stroke"

# Above, chosen in its box; the name typed; Return in it adds the window.
xdotool mousemove $(probe "at cycle window compare") click 1
sleep 0.3
xdotool key a Return
wait_probe "cycle window: new; name takeup; point takeup.E; axis y; above;" ||
  fail "the comparison box did not take above"
xdotool mousemove $(probe "at cycle window name") click 1
xdotool key ctrl+a
xdotool type --delay 20 'eye'
xdotool key Return
wait_probe "history: Add window" || fail "Return in the name did not add the window"
wait_probe "cycle entry Window 3: eye=takeup.E:y>$level => " || fail "the window is not in the list"
wait_probe "cycle window: edit 3; name eye;" || fail "the form does not edit the window added"
wait_probe "at cycle threshold eye: " || fail "the window's threshold line is not drawn"
wait_still 2 || fail "the picture does not settle"
before=$(grep -m1 -F "cycle entry Window 3: " "$work/probe.txt" | sed 's/.*=> //')

# The line dragged down 10 pixels (a row is about 35 pixels for the eye's 49 mm: the level stays
# in the stroke); before the release the window's text and ends follow.
read -r x y < <(probe "at cycle threshold eye")
xdotool mousemove "$x" "$y"
sleep 0.2
xdotool mousedown 1
for dy in 2 4 6 8 10; do xdotool mousemove "$x" $((y + dy)); sleep 0.1; done
sleep 0.5
dragged=$(probe "cycle window" | sed -n 's/.*; level \([^;]*\);.*/\1/p')
awk -v a="$dragged" -v b="$level" 'BEGIN { exit !(a < b - 1) }' ||
  fail "the drag did not lower the threshold ($level to $dragged)"
wait_probe "cycle entry Window 3: eye=takeup.E:y>$dragged => " ||
  fail "the window's text does not follow the drag"
grep -q "history: Edit" "$work/probe.txt" && fail "the drag made an undo step before the release"
xdotool mouseup 1
wait_probe "history: Edit the window eye" || fail "the release made no undo step"
[ "$(grep -c "^history: " "$work/probe.txt")" = 2 ] || fail "the drag is not one undo step"
wait_still 3 || fail "the picture does not settle"
after=$(grep -m1 -F "cycle entry Window 3: " "$work/probe.txt" | sed 's/.*=> //')
[ "$after" != "$before" ] || fail "the window's ends did not move ($before)"
case "$after" in *°–*°) ;; *) fail "the window dragged holds no interval: $after" ;; esac

xdotool mousemove 640 300 click 1
xdotool key ctrl+s
wait_probe "modified: 0" || fail "Ctrl+S did not save"
python3 - "$machine" "$dragged" <<'PY' || fail "the saved file does not hold the window dragged"
import json, sys
t = json.load(open(sys.argv[1]))["timing"]
w = t["windows"]
assert w[:3] == ["needle=needlebar.N:y<-185", "hook=hook.K:x<0", "feed=feedbar.T:y>-185"], w
name, rest = w[3].split("=", 1)
assert name == "eye" and rest.startswith("takeup.E:y>"), w
assert float(rest.split(">", 1)[1]) == float(sys.argv[2]), (w, sys.argv[2])
assert t["conflicts"] == [["needle", "feed"]], t
PY
# The command line's ends for the saved window, as the dock shows them (two decimals).
"$cli" timing "$machine" | awk -F, -v shown="$after" '
  $1 == "eye" { got = got (got ? "; " : "") sprintf("%.2f°–%.2f°", $2, $3) }
  END { if (got != shown) { print "cli: " got "; dock: " shown; exit 1 } }' ||
  fail "linkage-cli timing of the saved file does not give the dock's ends"
echo "ok: a window picked on the canvas, added, its threshold dragged as one undo step, saved"
