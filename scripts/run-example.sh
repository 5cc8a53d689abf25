#!/usr/bin/env bash
# Sets up and builds the project, then runs the main job on the flagship example: the motion
# table of the Wanzer needle bar, inversion 2 (needle position, velocity, acceleration over one
# revolution of the disk at 240 rpm clockwise). The editor will take this place when it exists.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build >/dev/null
build/app/linkage-cli info wanzer-inversion-2
echo
build/app/linkage-cli analyze wanzer-inversion-2 --steps 36 "$@"
