#!/usr/bin/env bash
# Installs the Debian package DEB with apt (its dependencies from the archive, no recommended
# packages) and checks the installed programs as a user would run them: versions, an analysis and
# the editor's window (offscreen) on an example found by name, a figure by linkage-plot, and the
# desktop files (entry, icon, MIME type, AppStream metadata) registered with the desktop's
# databases. Meant for a fresh machine with no source tree (scripts/package-test.sh runs it in a
# fresh Debian 12 root); as root.
#
#   scripts/package-check.sh DEB
set -euo pipefail
deb=$(realpath "$1")
fail() { echo "package-check: $*" >&2; exit 1; }
step() { echo "package-check: $*"; }
export DEBIAN_FRONTEND=noninteractive

t0=$(date +%s)
apt-get update -qq
apt-get install -y -qq --no-install-recommends "$deb" >/tmp/package-check-apt.log 2>&1 ||
  { tail -30 /tmp/package-check-apt.log; fail "apt-get install $deb failed"; }
installed=$(dpkg-query -W -f='${Package} ${Version} (${Installed-Size} KiB)' linkage)
step "installed $installed and $(grep -c '^Setting up' /tmp/package-check-apt.log) packages" \
  "in $(( $(date +%s) - t0 )) s"
step "Depends: $(dpkg-query -W -f='${Depends}' linkage)"
version=$(dpkg-query -W -f='${Version}' linkage)

for f in /usr/bin/linkage /usr/bin/linkage-cli /usr/bin/linkage-plot \
  /usr/share/applications/io.github.linkage.Linkage.desktop \
  /usr/share/icons/hicolor/scalable/apps/io.github.linkage.Linkage.svg \
  /usr/share/mime/packages/linkage.xml \
  /usr/share/metainfo/io.github.linkage.Linkage.metainfo.xml \
  /usr/share/doc/linkage/copyright /usr/share/doc/linkage/changelog.gz \
  /usr/share/linkage/examples/wanzer-inversion-2.linkage.json \
  /usr/lib/python3/dist-packages/linkage.cpython-*.so; do
  [ -s "$f" ] || fail "$f is not installed"
done
step "installed: programs, desktop entry, icon, MIME type, metainfo, copyright, changelog, examples"

# From an empty directory, with no display: nothing may come from a working or source tree.
work=$(mktemp -d)
cd "$work"
unset DISPLAY WAYLAND_DISPLAY QT_QPA_PLATFORM
# (set -e: either one exiting non-zero fails the check.)
editor_version=$(linkage --version 2>/dev/null)
cli_version=$(linkage-cli --version)
[ "$editor_version" = "linkage $version" ] || fail "linkage --version: $editor_version"
[ "$cli_version" = "linkage-cli $version" ] || fail "linkage-cli --version: $cli_version"
step "linkage --version: $editor_version; linkage-cli --version: $cli_version"

linkage-cli examples >examples.txt
grep -qx wanzer-inversion-2 examples.txt || fail "linkage-cli examples: no wanzer-inversion-2"
step "linkage-cli examples: $(wc -l <examples.txt) examples, from /usr/share/linkage/examples"
linkage-cli analyze wanzer-inversion-2 --steps 4 | tee table.csv
header='t_s,crank_deg,needlebar.G.x_mm,needlebar.G.y_mm,needlebar.G.vx_mm_s,needlebar.G.vy_mm_s,needlebar.G.ax_mm_s2,needlebar.G.ay_mm_s2'
[ "$(head -1 table.csv)" = "$header" ] || fail "analyze: not the motion table's header"
[ "$(wc -l <table.csv)" -eq 6 ] || fail "analyze: $(wc -l <table.csv) lines, not 6"

# The Python module, in Debian's own path, for /usr/bin/python3: the same table to the last bit
# (the command line writes 17 significant digits, which read back to the same double; -0 as 0).
/usr/bin/python3 - <<'PY' || fail "the Python module does not give linkage-cli's table"
import csv, linkage
m = linkage.load("wanzer-inversion-2")
assert m.path == "/usr/share/linkage/examples/wanzer-inversion-2.linkage.json", m.path
rows = list(csv.reader(open("table.csv")))
a = m.analyze(steps=4, points=["needlebar.G"])
assert m.columns(["needlebar.G"]) == rows[0]
assert ((a + 0.0).tobytes() == __import__("numpy").array(rows[1:], dtype=float).tobytes())
PY
step "python3: import linkage from $(/usr/bin/python3 -c 'import linkage; print(linkage.__file__)'), the same table"

linkage-cli plot wanzer-inversion-2 --point needlebar.G --out fig.svg 2>plot.log ||
  { cat plot.log; fail "linkage-cli plot failed"; }
grep -q "<svg" fig.svg || fail "linkage-cli plot wrote no SVG"
step "linkage-cli plot (linkage-plot): $(stat -c %s fig.svg) bytes of SVG"

QT_QPA_PLATFORM=offscreen linkage --screenshot /tmp/shot.png wanzer-inversion-2 2>shot.log ||
  { cat shot.log; fail "linkage --screenshot failed"; }
[ "$(head -c 8 /tmp/shot.png | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] ||
  fail "the screenshot is no PNG"
if grep -E "Could not (load|find) the Qt platform plugin|Cannot find font|QFontDatabase" \
  shot.log; then
  fail "Qt could not find its platform plugin or fonts"
fi
size=$(od -An -tu1 -j16 -N8 /tmp/shot.png | awk '{ print $3 * 256 + $4 "x" $7 * 256 + $8 }')
step "editor screenshot $size, $(stat -c %s /tmp/shot.png) bytes"

# A desktop: its MIME and desktop databases (what a desktop environment has) pick the files up,
# so that a double click on *.linkage.json runs "linkage %f".
apt-get install -y -qq --no-install-recommends shared-mime-info desktop-file-utils >/dev/null
update-mime-database /usr/share/mime
update-desktop-database /usr/share/applications
grep -qx 'application/x-linkage+json:\*\.linkage\.json' /usr/share/mime/globs ||
  fail "the MIME database has no *.linkage.json"
grep -q '^application/x-linkage+json=.*io\.github\.linkage\.Linkage\.desktop' \
  /usr/share/applications/mimeinfo.cache || fail "no desktop entry opens application/x-linkage+json"
desktop-file-validate /usr/share/applications/io.github.linkage.Linkage.desktop
step "*.linkage.json is application/x-linkage+json, opened by io.github.linkage.Linkage.desktop"
step "all checks passed"
