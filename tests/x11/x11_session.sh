# Shared by the X11 tests: a private Xvfb display, the editor started in it with fresh
# settings, screenshots, and comparisons of them. Everything started is stopped on exit.
for tool in Xvfb xdotool import compare; do
  command -v "$tool" >/dev/null || { echo "missing $tool (scripts/setup.sh --tests installs it)"; exit 1; }
done
work=$(mktemp -d /tmp/linkage-x11.XXXXXX)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  wait 2>/dev/null || true
  [ -n "${KEEP_SHOTS:-}" ] || rm -rf "$work"
}
trap cleanup EXIT
fail() {
  echo "FAIL: $*"
  echo "screenshots: $work (kept)"
  KEEP_SHOTS=1
  exit 1
}

start_x11() {
  # A display number nobody uses: Xvfb -displayfd picks one.
  exec 5>"$work/display"
  Xvfb -displayfd 5 -screen 0 1280x900x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
  pids+=($!)
  for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.05; done
  [ -s "$work/display" ] || fail "Xvfb did not start"
  export DISPLAY=":$(cat "$work/display")"
  unset QT_QPA_PLATFORM
  # Fresh settings and no session bus: a newcomer's first start.
  export XDG_CONFIG_HOME="$work/config" HOME="$work/home" XDG_RUNTIME_DIR="$work/run"
  mkdir -p "$XDG_CONFIG_HOME" "$HOME" "$XDG_RUNTIME_DIR"
  chmod 700 "$XDG_RUNTIME_DIR"
}

start_linkage() {
  "$@" >"$work/linkage.log" 2>&1 &
  pids+=($!)
  xdotool search --sync --onlyvisible --name "Linkage" >/dev/null 2>&1 &
  local search=$!
  for _ in $(seq 200); do
    kill -0 "$search" 2>/dev/null || break
    sleep 0.05
  done
  kill "$search" 2>/dev/null && fail "no Linkage window appeared ($(cat "$work/linkage.log"))"
  win=$(xdotool search --onlyvisible --name "Linkage" | head -1)
  xdotool windowmove "$win" 0 0 windowsize "$win" 1280 900
  sleep 0.5
}

shot() { import -window root "$work/shot$1.png"; }
# Pixels that differ between two screenshots.
diffpixels() { compare -metric AE "$work/shot$1.png" "$work/shot$2.png" null: 2>&1 || true; }
changed() { [ "$(diffpixels "$1" "$2")" != "0" ]; }
same() { [ "$(diffpixels "$1" "$2")" = "0" ]; }
# A loaded machine handles keys late: poll for what a key must do, for up to 10 s, rather than
# trusting a fixed pause. Each takes shot $2 (or $1) as the picture it waited for.
wait_changed() {  # until shot $2 differs from shot $1
  for _ in $(seq 50); do shot "$2"; changed "$1" "$2" && return 0; sleep 0.2; done
  return 1
}
wait_same() {  # until shot $2 equals shot $1
  for _ in $(seq 50); do shot "$2"; same "$1" "$2" && return 0; sleep 0.2; done
  return 1
}
wait_still() {  # until two shots 0.3 s apart are the same; shot $1 is the second
  shot "$1"
  for _ in $(seq 30); do
    sleep 0.3
    cp "$work/shot$1.png" "$work/shot$1-before.png"
    shot "$1"
    same "$1-before" "$1" && return 0
  done
  return 1
}
# Until a window with this title is shown (a dialog), for up to 10 s.
wait_window() {
  for _ in $(seq 100); do
    xdotool search --onlyvisible --name "$1" >/dev/null 2>&1 && return 0
    sleep 0.1
  done
  return 1
}

# The canvas's origin in a screenshot: where its two axes cross. The axes are one pixel wide,
# the longest straight runs of mid grey on the canvas (darker than the grid, lighter than text).
axes_of() {
  convert "$1" -colorspace gray -depth 8 txt:- | awk -F'[,: ()]+' '
    NR > 1 { v = $(NF-1); if (v >= 100 && v <= 180) { col[$1]++; row[$2]++ } }
    END {
      for (c in col) if (col[c] > bc) { bc = col[c]; x = c }
      for (r in row) if (row[r] > br) { br = row[r]; y = r }
      if (bc < 200 || br < 200) exit 1
      print x, y
    }'
}

# What the editor shows, in words (LINKAGE_PROBE, ui/window/probe.h): set before start_linkage.
use_probe() { export LINKAGE_PROBE="$work/probe.txt"; }
# Until the probe holds this line fragment, for up to 10 s.
wait_probe() {
  for _ in $(seq 100); do
    grep -qF -- "$1" "$work/probe.txt" 2>/dev/null && return 0
    sleep 0.1
  done
  echo "--- probe:"; cat "$work/probe.txt" 2>/dev/null | head -80
  return 1
}
# Until the probe no longer holds it.
wait_probe_gone() {
  for _ in $(seq 100); do
    grep -qF -- "$1" "$work/probe.txt" 2>/dev/null || return 0
    sleep 0.1
  done
  echo "--- probe:"; cat "$work/probe.txt" 2>/dev/null | head -80
  return 1
}
# The value of the probe's first line "KEY: value".
probe() { grep -m1 -F -- "$1: " "$work/probe.txt" | cut -d" " -f$(( $(wc -w <<<"$1") + 1 ))-; }
# The screen position of millimetre (x, y) of the drawing, from the probe's canvas line.
screen_of() {
  read -r ox oy z < <(probe canvas)
  awk -v ox="$ox" -v oy="$oy" -v z="$z" -v x="$1" -v y="$2" \
    'BEGIN { printf "%d %d\n", ox + x * z + 0.5, oy - y * z + 0.5 }'
}
click_mm() {
  local sx sy
  read -r sx sy < <(screen_of "$1" "$2")
  xdotool mousemove "$sx" "$sy"; sleep 0.1; xdotool click 1; sleep 0.2
}
# A Properties field (by its label) or a dock's tab (by its text), clicked.
click_field() { xdotool mousemove $(probe "at field $1") click 1; sleep 0.2; }
click_tab() { xdotool mousemove $(probe "tab $1") click 1; sleep 0.2; }
