#!/usr/bin/env bash
# Builds the Debian package, BUILD_DIR/linkage_<version>_<arch>.deb (CPack, cmake/Package.cmake),
# and prints its path as the last line of standard output: the programs' packages and build
# (scripts/setup.sh, without the tests), dpkg-dev for dpkg-shlibdeps, which finds the package's
# dependencies from the libraries the programs load, and file, with which CPack finds the programs
# to give it (neither is in a minimal Debian).
#
#   scripts/build-package.sh [BUILD_DIR]      (default: build; as root, or with sudo)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${1:-build}
scripts/setup.sh "$BUILD_DIR" >&2
missing=()
for p in dpkg-dev file; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO=sudo
  echo "build-package: installing ${missing[*]}" >&2
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
fi
rm -f "$BUILD_DIR"/linkage_*.deb
cmake --build "$BUILD_DIR" --target package >&2
debs=("$BUILD_DIR"/linkage_*.deb)
[ -s "${debs[0]}" ] || { echo "build-package: CPack made no package in $BUILD_DIR" >&2; exit 1; }
realpath "${debs[0]}"
