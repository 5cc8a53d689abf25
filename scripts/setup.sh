#!/usr/bin/env bash
# Installs what the project needs on Debian 12 (as root, or with sudo) and builds it.
#
#   scripts/setup.sh [--tests] [BUILD_DIR]      (default build dir: build)
#
# Without --tests: only what the programs need (compiler, Eigen, JSON, Qt), and only the programs
# are built. With --tests: also the test, benchmark and headless-display packages, and everything
# is built. Each package set is complete on its own: a fresh Debian 12 root (debootstrap minbase)
# is how CI proves it (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."

tests=0
if [ "${1:-}" = "--tests" ]; then
  tests=1
  shift
fi
BUILD_DIR=${1:-build}

# The programs: linkage-cli (solver, file format; COIN-OR CLP for the balancing programmes, whose
# pkg-config file names -lz: zlib1g-dev; CLI11, header-only, for its options and linkage-plot's)
# and the editor linkage (Qt 6 Widgets, Svg, QCustomPlot's Qt 6 build, giflib for animated
# GIFs); dxflib for cams' profiles as DXF; NLopt (its C++ header over the C library) for
# `optimize`; a font so that labels are not boxes; ccache, which every build compiles through (a
# build after a small change compiles only what changed); the Python module `linkage` (pybind11
# and Python's headers to build it, numpy for its arrays: app/python).
packages=(cmake ninja-build g++ pkg-config libeigen3-dev nlohmann-json3-dev coinor-libclp-dev
  zlib1g-dev libcli11-dev qt6-base-dev qt6-svg-dev libqcustomplot-dev libgif-dev libdxflib-dev
  libnlopt-cxx-dev
  fonts-dejavu-core ccache pybind11-dev python3-dev python3-numpy)
# The tests: GoogleTest and GoogleMock (separate packages on Debian 12), Google Benchmark, a real X
# server and a way to drive it (Xvfb, xdotool, ImageMagick's import), a comma-decimal locale,
# pdftotext (poppler-utils) to read the labels of exported PDF figures, the freedesktop validators
# of the desktop entry and the AppStream metadata (desktop-file-utils, appstream); pytest for the
# Python module's tests (tests/python), numba for its benchmark's four-bar loop (bench/).
test_packages=(libgtest-dev libgmock-dev libbenchmark-dev locales xvfb xauth xdotool imagemagick
  poppler-utils desktop-file-utils appstream python3-pytest python3-numba)
if [ $tests -eq 1 ]; then packages+=("${test_packages[@]}"); fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO=sudo
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
fi

if [ $tests -eq 1 ]; then
  # A comma-decimal locale, so the tests can prove output does not depend on the locale.
  if ! locale -a 2>/dev/null | grep -qi '^de_DE.utf8$'; then
    $SUDO sed -i 's/^# *de_DE.UTF-8 UTF-8/de_DE.UTF-8 UTF-8/' /etc/locale.gen
    $SUDO locale-gen >/dev/null
  fi
  cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release -DLINKAGE_BUILD_TESTS=ON \
    -DLINKAGE_BUILD_BENCH=ON >/dev/null
  cmake --build "$BUILD_DIR"
else
  cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release -DLINKAGE_BUILD_TESTS=OFF \
    -DLINKAGE_BUILD_BENCH=OFF >/dev/null
  cmake --build "$BUILD_DIR" --target linkage linkage-cli linkage-plot linkage_python
fi
