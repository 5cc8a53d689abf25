#!/usr/bin/env bash
# Sets up and builds the programs, then runs them on the flagship example, the Wanzer needle
# bar, inversion 2: its structure and motion table (needle position, velocity, acceleration
# over one revolution of the disk at 240 rpm clockwise) from linkage-cli, then the editor on it.
# With a display the editor's window opens (close it to finish); without one (a server, CI) it
# is rendered to a PNG with its instant centres and plots, and the path is printed.
set -euo pipefail
cd "$(dirname "$0")/.."
echo "setting up and building (a few minutes on a fresh machine; build log in build/setup.log)..." >&2
mkdir -p build
if ! scripts/setup.sh build >build/setup.log 2>&1; then
  tail -30 build/setup.log >&2
  exit 1
fi
build/app/linkage-cli info wanzer-inversion-2
echo
build/app/linkage-cli analyze wanzer-inversion-2 --steps 36 "$@"
echo
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  echo "opening the editor on wanzer-inversion-2 (Space plays, I shows the instant centres)" >&2
  exec build/app/linkage wanzer-inversion-2
fi
shot=build/wanzer-inversion-2.png
build/app/linkage --screenshot "$shot" wanzer-inversion-2 --ics --plots --size 1400x1000
echo "no display: the editor's window, rendered offscreen, is in $shot" >&2
