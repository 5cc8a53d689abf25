#!/usr/bin/env bash
# A four-bar drawn in a real X window (Xvfb) with xdotool clicks and key presses, as a user
# would: two ground pivots, three links, the driver, an output point; saved with Ctrl+S through
# the file dialog; then checked with linkage-cli: 4 bodies, 4 pins, one degree of freedom, a
# full revolution.
#   tests/x11/draw_four_bar.sh path/to/linkage   (linkage-cli beside it)
set -euo pipefail
linkage=$1
cli="$(dirname "$linkage")/linkage-cli"
source "$(dirname "$0")/x11_session.sh"
start_x11
start_linkage "$linkage"

# Where the canvas's origin is: a new document shows (0, 0) in the middle of the canvas, its
# axes drawn through it; Ctrl+1 makes a millimetre 96 / 25.4 pixels (Xvfb runs at 96 dpi).
xdotool mousemove 400 300 click 1   # an empty place on the canvas: it has the keyboard
xdotool key ctrl+1
sleep 0.3
wait_still origin || fail "the canvas does not settle"
read -r ox oy < <(axes_of "$work/shotorigin.png") || fail "no axes found on the canvas"
echo "canvas origin at $ox,$oy"
mm() { awk -v ox="$ox" -v oy="$oy" -v x="$1" -v y="$2" \
  'BEGIN { s = 96 / 25.4; printf "%d %d\n", ox + x * s + 0.5, oy - y * s + 0.5 }'; }
at() { read -r sx sy < <(mm "$1" "$2"); xdotool mousemove "$sx" "$sy"; sleep 0.05; xdotool click 1; sleep 0.1; }

xdotool key g; at 0 0; at 60 0
xdotool key l; at 0 0; at 10 20; xdotool key Return
xdotool key l; at 10 20; at 70 50; xdotool key Return
xdotool key l; at 70 50; at 60 0; xdotool key Return
xdotool key m; at 0 0
xdotool key o; at 70 50
xdotool key s
wait_still drawn || fail "the canvas does not settle after drawing"

out="$work/four-bar.linkage.json"
xdotool key ctrl+s
wait_window "Save Mechanism As" || fail "Ctrl+S did not open the save dialog"
sleep 0.5
# Qt's own file dialog: its file name field has the keyboard; a full path is taken as typed.
xdotool key ctrl+a
xdotool type --delay 15 "$out"
xdotool key Return
for _ in $(seq 100); do [ -s "$out" ] && break; sleep 0.1; done
shot saved
[ -s "$out" ] || fail "the file was not saved through the dialog"

info=$("$cli" info "$out")
echo "$info"
grep -q "bodies: 4, joints: 4" <<<"$info" || fail "not 4 bodies and 4 joints"
[ "$(grep -c '^  joints\[[0-9]\] (pin ' <<<"$info")" -eq 4 ] || fail "not 4 pins"
grep -q "degrees of freedom: 1 " <<<"$info" || fail "not one degree of freedom"
rows=$("$cli" analyze "$out" --steps 36 | wc -l) || fail "analyze failed"
[ "$rows" -eq 38 ] || fail "analyze gave $rows lines, not a header and 37 rows"
echo "ok: drawn, saved through the dialog, 4 bodies, 4 pins, 1 DOF, a full revolution"
