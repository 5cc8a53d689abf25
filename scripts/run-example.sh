#!/usr/bin/env bash
# Sets up and builds the project, then runs the main job on the flagship example: the motion
# table of the Wanzer needle bar, inversion 2 (needle position, velocity, acceleration over one
# revolution of the disk at 240 rpm clockwise). The editor will take this place when it exists.
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
