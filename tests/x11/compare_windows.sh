#!/usr/bin/env bash
# Comparing with another window (issue 19, item 9) in a real X window driven by xdotool: a
# four-bar's plots overlaid with a second window's Wanzer, which has no point of the same name
# (its first output is taken, not "no point"), then at a point chosen in the "against" list.
# Checked through the editor's probe (the values under the plots name the point compared).
#   tests/x11/compare_windows.sh path/to/linkage
set -euo pipefail
linkage=$1
examples="$(cd "$(dirname "$0")/../../resources/examples" && pwd)"
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
fourbar="$work/four-bar.linkage.json"
wanzer="$work/wanzer.linkage.json"
cp "$examples/four-bar-crank-rocker.linkage.json" "$fourbar"
cp "$examples/wanzer-inversion-2.linkage.json" "$wanzer"
start_linkage "$linkage" "$fourbar"
wait_probe "title: four-bar.linkage.json" || fail "no probe"
first=$win
# Until the first window's values under the plots (the probe lists it first) hold this.
wait_plots() {
  for _ in $(seq 100); do
    probe plots | grep -qF -- "$1" && return 0
    sleep 0.1
  done
  echo "--- plots: $(probe plots)"
  return 1
}

# A second window (File > New Window), the Wanzer opened in it with the file dialog.
xdotool mousemove 200 150 click 1
sleep 0.2
xdotool key ctrl+shift+n
wait_probe "title: untitled" || fail "Ctrl+Shift+N opened no second window"
# Over the first (no window manager here: the keyboard goes to the window under the pointer).
wait_window "untitled" || fail "the second window is not shown"
second=$(xdotool search --onlyvisible --name "untitled" | head -1)
xdotool windowmove "$second" 0 0 windowsize "$second" 1280 900 windowraise "$second"
sleep 0.5
xdotool mousemove 200 150 click 1
sleep 0.2
xdotool key ctrl+o
wait_window "Open Mechanism" || fail "Ctrl+O did not open the dialog"
sleep 0.5
xdotool key ctrl+a; xdotool type --delay 10 "$wanzer"; xdotool key Return
wait_probe "title: wanzer.linkage.json" || fail "the Wanzer did not open in the second window"

# Back to the four-bar's window (no window manager here: the others, over it, are unmapped;
# their documents stay open for the comparison).
for other in $(xdotool search --onlyvisible --name " — Linkage"); do
  [ "$other" = "$first" ] || xdotool windowunmap --sync "$other"
done
xdotool windowraise "$first"
sleep 0.5
wait_probe "at combo compare" || fail "the four-bar's plots show no comparison choice"
xdotool mousemove $(probe "at combo compare") click 1
sleep 0.5
xdotool key Down Return
wait_probe "combo compare: Overlay" || fail "Overlay was not chosen"
# The four-bar has no needlebar.G: not "no point" but the Wanzer's first output, its values.
wait_probe "combo against: against: same name" || fail "no 'against' list beside the comparison"
wait_plots ": needlebar.G at " || fail "the Wanzer's first output is not compared"

# Another point chosen in the list, by typing its name in the open list.
xdotool mousemove $(probe "at combo against") click 1
sleep 0.5
xdotool type --delay 20 "against triangle.G"
xdotool key Return
wait_probe "combo against: against triangle.G" || fail "triangle.G was not chosen"
wait_plots ": triangle.G at " || fail "the plots do not compare at triangle.G"
probe plots | grep -qF "needlebar.G" && fail "the plots still compare at needlebar.G"
echo "ok: compared with another window at its first output, then at the point chosen"
