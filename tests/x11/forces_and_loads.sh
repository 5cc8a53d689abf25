#!/usr/bin/env bash
# Forces in a real X window driven by xdotool (issue 17): a link's mass typed in its Properties,
# View > Forces by its key (the reactions drawn: the picture changes), a load added by the
# right-click menu's key at a point and its force typed, saved with Ctrl+S; the saved file holds
# them and `linkage-cli dynamics` computes its forces.
#   tests/x11/forces.sh path/to/linkage
set -euo pipefail
linkage=$1
cli="$(dirname "$linkage")/linkage-cli"
examples="$(cd "$(dirname "$0")/../../resources/examples" && pwd)"
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
fourbar="$work/four-bar.linkage.json"
cp "$examples/four-bar-crank-rocker.linkage.json" "$fourbar"
start_linkage "$linkage" "$fourbar"
wait_probe "title: four-bar.linkage.json" || fail "no probe"

click_mm 37.7 40.3
wait_probe "properties: Link coupler" || fail "a click inside the coupler did not select it"
click_field "Mass [kg]"
xdotool key ctrl+a; xdotool type --delay 10 "0.3"; xdotool key Return
wait_probe "field Mass [kg]: 0.3" || fail "the mass was not taken"
wait_probe "dynamics: masses 1 loads 0 reactions 0" || fail "no centre of mass drawn"

xdotool mousemove 200 150 click 1   # the canvas has the keyboard
wait_still 1 || fail "the picture does not settle"
xdotool key shift+f
wait_probe "forces: reactions: 10 mm = " || fail "Shift+F did not show the forces"
wait_probe "dynamics: masses 1 loads 0 reactions 4" || fail "not one reaction per joint"
wait_changed 1 2 || fail "the reactions were not drawn"

read -r px py < <(python3 -c "import json,sys; m=json.load(open(sys.argv[1]));
print(*next(b for b in m['bodies'] if b['name']=='coupler')['points']['P'])" "$fourbar")
read -r sx sy < <(screen_of "$px" "$py")
xdotool mousemove "$sx" "$sy"; sleep 0.2; xdotool click 3; sleep 0.5
xdotool key l
wait_probe "dynamics: masses 1 loads 1" || fail "the menu's L did not add a load"
wait_probe "properties: Point coupler.P" || fail "the load's point is not selected"
click_field "Load 1"
xdotool key ctrl+a; xdotool type --delay 10 "0, -25"; xdotool key Return
wait_probe "history: Load" || fail "the force was not taken"
xdotool mousemove 200 150 click 1
xdotool key ctrl+s
wait_probe "modified: 0" || fail "Ctrl+S did not save"
python3 - "$fourbar" <<'PY' || fail "the saved file lacks the mass or the load"
import json, sys
m = json.load(open(sys.argv[1]))
c = next(b for b in m["bodies"] if b["name"] == "coupler")
assert c["mass"]["kg"] == 0.3, c
assert m["loads"] == [{"point": "coupler.P", "force_N": [0, -25]}], m["loads"]
PY
"$cli" dynamics "$fourbar" --steps 12 >"$work/forces.csv" || fail "linkage-cli dynamics refused the file"
[ "$(wc -l <"$work/forces.csv")" -eq 14 ] || fail "not 13 rows of forces"
echo "ok: mass typed, forces shown, load added and typed, saved, computed"
