#!/usr/bin/env bash
# Issue 26, item 9, in a real X window driven by xdotool: the window's one-letter keys (S, flip
# X, instant centres I, fit F, then the tools L G T B P M O) typed into every kind of field: the
# Properties' names, numbers, angles and "x, y" pairs, the docks' number boxes and the Cycle
# dock's line, a choice box. No tool is chosen, the document and its history stay as they were, the keyboard
# stays in the field; a number field keeps its value (and says why the letters were not
# typed), a text field has them as its text. "abc" in Mass chose the Slider block tool before.
#   tests/x11/letters_in_fields.sh path/to/linkage
set -euo pipefail
linkage=$1
examples="$(cd "$(dirname "$0")/../../resources/examples" && pwd)"
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
masses="$work/masses.linkage.json"
cp "$examples/slider-crank-22a-masses.linkage.json" "$masses"
start_linkage "$linkage" "$masses"
wait_probe "title: masses.linkage.json" || fail "no probe"
keys="sxiflgtbpmo"  # the tools last: one left chosen would show in the hint
history() { grep -c "^history: " "$work/probe.txt" || true; }

# The keys typed into what is at $1 (screen x y), its content selected first. $2 names it for
# the messages; $3 the probe's line that shows it; $4 what it must show after ("" to skip).
type_into() {
  local at=$1 name=$2 line=$3 want=$4
  local design hist
  design=$(probe design); hist=$(history)
  xdotool mousemove $at click 1; sleep 0.2
  xdotool key ctrl+a
  xdotool type --delay 30 "$keys"
  sleep 0.6
  probe hint | grep -q "^Select:" || fail "$name: a key typed in it chose a tool ($(probe hint))"
  [ "$(probe design)" = "$design" ] || fail "$name: the keys changed the design"
  [ "$(history)" = "$hist" ] || fail "$name: the keys made an undo step"
  [ "$(probe focus)" != "linkage::ui::CanvasView" ] || fail "$name: the keyboard left the field"
  if [ -n "$want" ]; then
    wait_probe "$line: $want" || fail "$name shows \"$(probe "$line")\", not \"$want\""
  fi
}

# The mechanism's: a name (the letters are its text), a number, an angle.
name=$(probe "field Name")
type_into "$(probe "at field Name")" "Name" "field Name" "$keys"
xdotool key ctrl+a; xdotool type --delay 10 "$name"; xdotool key Return   # as it was
wait_probe "field Name: $name" || fail "the name was not put back"
for f in "Driver speed [rpm]" "Start angle [°]"; do
  was=$(probe "field $f")
  type_into "$(probe "at field $f")" "$f" "field $f" "$was"
  wait_probe "message: $f takes a number" || fail "$f does not say why the letters were not typed"
done

# A link's: its mass, its centre of mass (an "x, y" pair), its moment of inertia. The rod is
# clicked again until it is what is selected (the needle bar's guide runs under it).
for _ in 1 2 3 4; do
  click_mm 0 30
  grep -q "properties: Link rod" "$work/probe.txt" && break
  sleep 0.3
done
wait_probe "properties: Link rod" || fail "clicks on the rod did not select it"
for f in "Mass [kg]" "Moment of inertia [kg·mm²]"; do
  was=$(probe "field $f")
  type_into "$(probe "at field $f")" "$f" "field $f" "$was"
done
type_into "$(probe "at field Centre of mass")" "Centre of mass" "field Centre of mass" "$keys"
xdotool key Return   # refused: no x, y pair; its value back, no undo step
wait_probe "field Centre of mass: 0, 25" || fail "the refused pair was not put back"
[ "$(history)" = 0 ] || fail "the refused pair made an undo step"
# "e" in Mass is a number's exponent, never the Gear tool's key.
xdotool mousemove $(probe "at field Mass [kg]") click 1; sleep 0.2
xdotool key ctrl+a; xdotool type --delay 30 "e"
wait_probe "field Mass [kg]: e" || fail "e is not typed into Mass"
probe hint | grep -q "^Select:" || fail "e in Mass chose a tool ($(probe hint))"

# The docks' number boxes (the crank's, the plots'), then the Cycle dock's line (Shift+C).
for box in crankAngle crankStep plotSteps; do
  wait_probe "at spin $box" || fail "no $box in the probe"
  was=$(probe "spin $box")
  type_into "$(probe "at spin $box")" "$box" "spin $box" "$was"
done
# A choice box (the plotted component), as a user leaves it after choosing: clicked (its list
# opens), closed with Esc, the keyboard still in it. The letters find its entries; none is the
# window's.
wait_probe "at combo plotComponent" || fail "no plotComponent in the probe"
design=$(probe design); hist=$(history)
xdotool mousemove $(probe "at combo plotComponent") click 1; sleep 0.4
xdotool key Escape; sleep 0.3
wait_probe "focus: QComboBox" || fail "the component box does not have the keyboard"
xdotool type --delay 30 "$keys"
sleep 0.6
probe hint | grep -q "^Select:" || fail "a key typed in the choice box chose a tool ($(probe hint))"
[ "$(probe design)" = "$design" ] || fail "the keys typed in the choice box changed the design"
[ "$(history)" = "$hist" ] || fail "the keys typed in the choice box made an undo step"

xdotool mousemove 640 300 click 1
xdotool key shift+c
wait_probe "tab Cycle" || fail "Shift+C did not show the Cycle dock"
wait_still docked || fail "the picture does not settle"
type_into "$(probe "at cycle line")" "the Cycle dock's line" "" ""
shot typed
[ "$(history)" = 0 ] || fail "an undo step was made"
echo "ok: the window's keys typed into names, numbers, angles, pairs, the docks' boxes and line chose no tool"
