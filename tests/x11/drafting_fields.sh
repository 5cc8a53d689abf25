#!/usr/bin/env bash
# Drafting (issue 19, items 6, 8, 9) in a real X window driven by xdotool: a plate's side typed
# and the file saved holds it; "-29.34" then L typed in a point's x field commits -29.34 and
# takes the Link tool; a slider block selected by clicking on it again and renamed. Checked
# through the editor's probe and the saved files.
#   tests/x11/drafting_fields.sh path/to/linkage
set -euo pipefail
linkage=$1
examples="$(cd "$(dirname "$0")/../../resources/examples" && pwd)"
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
fourbar="$work/four-bar.linkage.json"
slider="$work/slider.linkage.json"
cp "$examples/four-bar-crank-rocker.linkage.json" "$fourbar"
cp "$examples/slider-crank-22a-lambda-0.3.linkage.json" "$slider"
point() {  # x y of a point of a saved file
  python3 -c "import json,sys; m=json.load(open(sys.argv[1])); b,p=sys.argv[2].split('.');
print(*next(x['points'][p] for x in m['bodies'] if x['name']==b))" "$1" "$2"
}
start_linkage "$linkage" "$fourbar"
wait_probe "title: four-bar.linkage.json" || fail "no probe"

# 8. The coupler plate (clicked inside, away from its points): side AP typed, re-solved, saved.
click_mm 37.7 40.3
wait_probe "properties: Link coupler" || fail "a click inside the coupler did not select it"
click_field "Side AP [mm]"
xdotool key ctrl+a; xdotool type --delay 10 "40"; xdotool key Return
wait_probe "field Side AP [mm]: 40" || fail "the side was not taken"
[ "$(probe solved)" = 1 ] || fail "not solved after the side was typed"
xdotool mousemove 200 150 click 1
xdotool key ctrl+s
wait_probe "modified: 0" || fail "Ctrl+S did not save"
python3 - "$fourbar" <<'PY' || fail "the saved coupler's side AP is not 40"
import json, math, sys
m = json.load(open(sys.argv[1]))
c = next(b for b in m["bodies"] if b["name"] == "coupler")["points"]
assert abs(math.dist(c["A"], c["P"]) - 40) < 1e-9, math.dist(c["A"], c["P"])
PY

# 6. "-29.34" then L in coupler.P's x: the value committed, the Link tool taken.
read -r px py < <(point "$fourbar" coupler.P)
click_mm "$px" "$py"
wait_probe "properties: Point coupler.P" || fail "a click on coupler.P did not select it"
click_field "x [mm]"
xdotool key ctrl+a; xdotool type --delay 10 -- "-29.34l"
wait_probe "hint: Link:" || fail "L in the number field did not take the Link tool"
wait_probe "field x [mm]: -29.34" || fail "the field does not hold -29.34"
[ "$(probe focus)" = "linkage::ui::CanvasView" ] || fail "the keyboard did not go to the canvas"
grep -q "field x \[mm\]: -29.34l" "$work/probe.txt" && fail "the L went into the field"
xdotool key Escape ctrl+s
wait_probe "modified: 0" || fail "Ctrl+S did not save"
[ "$(point "$fourbar" coupler.P | cut -d' ' -f1)" = "-29.34" ] || fail "coupler.P's x is not -29.34"

# 9. The slider-crank's block: a click on it again selects it; renamed, saved.
xdotool key ctrl+o
wait_window "Open Mechanism" || fail "Ctrl+O did not open the dialog"
sleep 0.5
xdotool key ctrl+a; xdotool type --delay 10 "$slider"; xdotool key Return
wait_probe "title: slider.linkage.json" || fail "the slider-crank did not open"
xdotool mousemove 200 150 click 1
for _ in 1 2 3; do
  click_mm 0 65
  grep -q "properties: Link needlebar" "$work/probe.txt" && break
  sleep 0.3
  grep -q "properties: Link needlebar" "$work/probe.txt" && break
done
wait_probe "properties: Link needlebar" || fail "clicks on the block did not select it"
click_field "Name"
xdotool key ctrl+a; xdotool type --delay 10 "slider"; xdotool key Return
wait_probe "field Name: slider" || fail "the block was not renamed"
xdotool mousemove 200 150 click 1
xdotool key ctrl+s
wait_probe "modified: 0" || fail "Ctrl+S did not save"
grep -q '"name": "slider"' "$slider" || fail "the saved file has no body \"slider\""
echo "ok: a plate's side typed, -29.34 then L, a slider block selected and renamed"
