#!/usr/bin/env bash
# The two new element kinds drawn in a real X window (Xvfb) with xdotool, as a user would: a
# crank on the main shaft, a second shaft below it coupled by a belt (the Gear tool, E, with
# Shift at the second click), an arc slot in the ground (the Slot tool, T, with Shift at the
# end and a third click on the way), a rod from the crank whose end runs in the arc (Pin in
# Slot, P). Saved through the file dialog, checked with linkage-cli (a gear, a three-point
# slot, a full revolution in closed form), then opened again in the editor, which animates it.
# Before saving, the arc's middle point is typed elsewhere in its Properties: the rod's end in it
# is then off the new arc, and the edit must leave the drawing assembled (issue 26: the file
# written then did not close, and every tool said the rod was moved 20 mm to assemble it).
#   tests/x11/draw_belt_and_arc.sh path/to/linkage   (linkage-cli beside it)
set -euo pipefail
linkage=$1
cli="$(dirname "$linkage")/linkage-cli"
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
start_linkage "$linkage"

xdotool mousemove 400 300 click 1   # an empty place on the canvas: it has the keyboard
xdotool key ctrl+1
sleep 0.3
wait_still origin || fail "the canvas does not settle"
read -r ox oy < <(axes_of "$work/shotorigin.png") || fail "no axes found on the canvas"
echo "canvas origin at $ox,$oy"
mm() { awk -v ox="$ox" -v oy="$oy" -v x="$1" -v y="$2" \
  'BEGIN { s = 96 / 25.4; printf "%d %d\n", ox + x * s + 0.5, oy - y * s + 0.5 }'; }
at() { read -r sx sy < <(mm "$1" "$2"); xdotool mousemove "$sx" "$sy"; sleep 0.05; xdotool click 1; sleep 0.1; }
shift_at() {
  read -r sx sy < <(mm "$1" "$2")
  xdotool mousemove "$sx" "$sy"; sleep 0.05
  xdotool keydown shift; xdotool click 1; xdotool keyup shift; sleep 0.1
}

# Everything within 50 mm above and below the origin: the canvas's height at this zoom.
# The main shaft's crank (10 mm) and the second shaft's arm, each on a ground pivot.
xdotool key g; at 0 0; at -50 -30
xdotool key l; at 0 0; at 10 0; xdotool key Return
xdotool key l; at -50 -30; at -38 -30; xdotool key Return
xdotool key m; at 0 0
# A belt from the crank's shaft to the second shaft.
xdotool key e; at 5 0; shift_at -44 -30
# An arc slot in the ground: from (80, 0), ending at (40, 40), through (64, 32) on the way
# (the circle of radius 40 about (40, 0)).
xdotool key t; at 80 0; shift_at 40 40; at 64 32
# The rod from the crank's end to a point on the arc, and that point made to run in it (a
# click on the arc where it has no point picks the slot).
xdotool key l; at 10 0; at 64 32; xdotool key Return
xdotool key p; at 64 32; at 72 24
xdotool key o; at 64 32
xdotool key s
wait_still drawn || fail "the canvas does not settle after drawing"
# The arc selected by a click on it away from its points (30 degrees about its centre), its
# middle point typed 2 mm further out.
at 74.641 20
wait_probe "properties: Slot ground.s1" || fail "a click on the arc did not select it"
click_field "xm [mm]"
xdotool key ctrl+a; xdotool type --delay 10 "66"; xdotool key Return
wait_probe "field xm [mm]: 66" || fail "the arc's middle point was not taken"
xdotool mousemove 400 300

out="$work/belt-and-arc.linkage.json"
xdotool key ctrl+s
wait_window "Save Mechanism As" || fail "Ctrl+S did not open the save dialog"
sleep 0.5
xdotool key ctrl+a
xdotool type --delay 15 "$out"
xdotool key Return
for _ in $(seq 100); do [ -s "$out" ] && break; sleep 0.1; done
shot saved
[ -s "$out" ] || fail "the file was not saved through the dialog"

info=$("$cli" info "$out")
echo "$info"
grep -q '(gear link2.A - link3.' <<<"$info" || fail "no gear from the crank's shaft to the second"
# (The file writes a gear's fields a line each; the arc's middle point is where the third click
# was, off the 10 mm grid.)
grep -A4 '"type": "gear"' "$out" | grep -q '"ratio": 1$' || fail "the gear is not a belt of ratio 1"
grep -qE '"s1": \[\[80, 0\], \[66, 3[12][.0-9]*\], \[40, 40\]\]' "$out" ||
  fail "no arc slot from (80, 0) through (66, about 32) to (40, 40)"
grep -q '(pin-in-slot link4\.' <<<"$info" || fail "the rod's end does not run in the slot"
grep -q "degrees of freedom: 1 " <<<"$info" || fail "not one degree of freedom"
grep -q "assembly: moved up to 0 mm" <<<"$info" || fail "the file written does not close"
grep -q "solve: in closed form" <<<"$info" || fail "not solved in closed form"
grep -q "group 2: geared link3" <<<"$info" || fail "the second shaft is not geared to the first"
rows=$("$cli" analyze "$out" --steps 36 | wc -l) || fail "analyze failed"
[ "$rows" -eq 38 ] || fail "analyze gave $rows lines, not a header and 37 rows"

# Opened again, it animates.
kill "${pids[-1]}" 2>/dev/null || true
wait "${pids[-1]}" 2>/dev/null || true
# Its window gone first: the next start must not find the old one.
for _ in $(seq 50); do
  xdotool search --onlyvisible --name "Linkage" >/dev/null 2>&1 || break
  sleep 0.1
done
start_linkage "$linkage" "$out"
xdotool mousemove 300 300 click 1
wait_still reopened || fail "the reopened design does not settle"
xdotool key space
wait_changed reopened playing || fail "Space did not animate the reopened design"
echo "ok: belt and arc slot drawn, saved, checked by linkage-cli, reopened and animated"
