#!/usr/bin/env bash
# The plots of a machine in space in a real X window driven by xdotool (issue 27): the distance
# from the needle's point to the hook's, chosen in the plots' component list and its "to" list
# as a user picks them; the values under the plots then name it ("d to hook.K") and the
# elevation box of a tilted direction is offered (a machine in space).
#   tests/x11/plots_distance_in_space.sh path/to/linkage
set -euo pipefail
linkage=$1
examples="$(cd "$(dirname "$0")/../../resources/examples" && pwd)"
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
model="$work/bevel.linkage.json"
cp "$examples/lockstitch-bevel.linkage.json" "$model"
start_linkage "$linkage" "$model"
wait_probe "title: bevel.linkage.json" || fail "no probe"
wait_probe "at combo plotComponent" || fail "the plots show no component list"
probe_has_not() { ! grep -qF -- "$1" "$work/probe.txt"; }
probe_has_not "at combo plotDistanceTo" || fail "a 'to' list before a distance is chosen"

# The component: the list opened with a click, its last entry ("distance") chosen by the keys.
xdotool mousemove $(probe "at combo plotComponent") click 1
sleep 0.5
xdotool key End Return
wait_probe "combo plotComponent: distance" || fail "distance was not chosen"
wait_probe "at combo plotDistanceTo" || fail "no 'to' list beside the distance"

# The point to measure to: the list opened, hook.K typed and taken.
xdotool mousemove $(probe "at combo plotDistanceTo") click 1
sleep 0.5
xdotool type --delay 20 "hook.K"
xdotool key Return
wait_probe "combo plotDistanceTo: hook.K" || fail "hook.K was not chosen"
wait_probe "d to hook.K" || fail "the values under the plots do not name the distance"
shot 1
echo "plots_distance_in_space: ok"
