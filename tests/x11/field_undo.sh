#!/usr/bin/env bash
# Ctrl+Z right after a value is committed in a Properties field (issue 19): typed with xdotool
# into coupler.P's x field, committed with Return, then Ctrl+Z in the field undoes the
# document's edit (one entry in the history, the file's design again, not modified), the field
# shows the value undone, leaving the field commits nothing, and Ctrl+Shift+Z redoes the edit.
# Checked through the editor's probe.
#   tests/x11/field_undo.sh path/to/linkage
set -euo pipefail
linkage=$1
examples="$(cd "$(dirname "$0")/../../resources/examples" && pwd)"
source "$(dirname "$0")/x11_session.sh"
start_x11
use_probe
fourbar="$work/four-bar.linkage.json"
cp "$examples/four-bar-crank-rocker.linkage.json" "$fourbar"
start_linkage "$linkage" "$fourbar"
wait_probe "title: four-bar.linkage.json" || fail "no probe"
file_design=$(probe design)
history() { grep -c "^history: " "$work/probe.txt" || true; }

click_mm 30.292953508076334 55.24406326133892
wait_probe "properties: Point coupler.P" || fail "a click on coupler.P did not select it"
click_field "x [mm]"
xdotool key ctrl+a; xdotool type --delay 10 "31"; xdotool key Return
wait_probe "field x [mm]: 31" || fail "the x field did not take 31"
wait_probe "modified: 1" || fail "the edit did not modify the document"
[ "$(history)" = 1 ] || fail "$(history) entries in the history after one edit"
edited=$(probe design)

# Ctrl+Z in the field: the document's edit undone, the field shows the value undone.
xdotool key ctrl+z
wait_probe "modified: 0" || fail "Ctrl+Z in the field did not undo the document's edit"
# (shown rounded for people, 30.293; the design keeps 30.292953508076334, checked next)
wait_probe "field x [mm]: 30.293" || fail "the field does not show the value undone"
[ "$(probe design)" = "$file_design" ] || fail "the design after Ctrl+Z is not the file's"

# Leaving the field commits nothing: still one entry, not modified.
xdotool key Tab
sleep 0.6
[ "$(probe modified)" = 0 ] || fail "leaving the field saved its text again as an edit"
[ "$(history)" = 1 ] || fail "$(history) entries in the history after leaving the field"
[ "$(probe design)" = "$file_design" ] || fail "leaving the field changed the design"

# Back in the field, Ctrl+Shift+Z redoes the edit (the redo was kept).
click_field "x [mm]"
xdotool key ctrl+shift+z
wait_probe "modified: 1" || fail "Ctrl+Shift+Z did not redo the edit"
wait_probe "field x [mm]: 31" || fail "the field does not show the value redone"
[ "$(probe design)" = "$edited" ] || fail "the redone design is not the edited one"
echo "ok: Ctrl+Z in a committed field undoes the document's edit and commits nothing again"
