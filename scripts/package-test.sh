#!/usr/bin/env bash
# The Debian package on a newcomer's machine: builds it here (scripts/build-package.sh), or takes
# DEB, then in a fresh Debian 12 root (../shared/tools/fresh-debian.sh) installs it with apt and
# checks the installed programs (scripts/package-check.sh). The clean clone of HEAD that the root
# gets is removed before the checks: nothing may come from a source tree. Commit first: the root
# runs HEAD's package-check.sh.
#
#   scripts/package-test.sh [DEB]      (as root; FRESH_DEBIAN=... another fresh-root tool)
set -euo pipefail
cd "$(dirname "$0")/.."
fresh=${FRESH_DEBIAN:-../shared/tools/fresh-debian.sh}
start=$(date +%s)
if [ $# -ge 1 ]; then
  deb=$(realpath "$1")
else
  echo "== building the package (build log in build/package.log)"
  mkdir -p build
  scripts/build-package.sh build >build/package.path 2>build/package.log ||
    { tail -30 build/package.log; exit 1; }
  deb=$(tail -1 build/package.path)
  echo "package-test: built $deb ($(( $(date +%s) - start )) s)"
fi
[ -s "$deb" ] || { echo "package-test: no package $deb"; exit 1; }
name=$(basename "$deb")
sum=$(sha256sum "$deb" | cut -d' ' -f1)
echo "== installing $name in a fresh Debian 12 root"
# The root gets only the clone and ../shared: the package goes in on standard input.
"$fresh" "cat > /tmp/$name && echo '$sum  /tmp/$name' | sha256sum -c --quiet &&
  cp scripts/package-check.sh /tmp/ && cd / && rm -rf /project &&
  bash /tmp/package-check.sh /tmp/$name" 1200 <"$deb"
echo "package-test: passed ($(( $(date +%s) - start )) s)"
