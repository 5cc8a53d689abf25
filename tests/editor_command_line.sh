#!/bin/sh
# The editor's command line (app/linkage_main.cpp), every option docs/editor.md documents, read
# by one parser: --version and --help print on standard output alone (nothing on standard
# error: no display is looked for), --screenshot writes a picture of the asked size with the
# options in any order, a bad option or a second model exits 2 naming it.
#   editor_command_line.sh LINKAGE VERSION
set -u
linkage=$1
version=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
unset DISPLAY WAYLAND_DISPLAY QT_QPA_PLATFORM XDG_RUNTIME_DIR
failed=0
fail() {
  echo "FAIL: $*"
  failed=1
}

# Exit status, standard output and standard error of one run.
run() {
  "$linkage" "$@" >"$work/out" 2>"$work/err"
  status=$?
}

# The width and height of a PNG (big-endian at bytes 16 and 20).
png_size() {
  set -- $(od -An -tu1 -j16 -N8 "$1")
  echo "$(($1 * 16777216 + $2 * 65536 + $3 * 256 + $4))x$(($5 * 16777216 + $6 * 65536 + $7 * 256 + $8))"
}

for v in --version -v; do
  run $v
  [ $status -eq 0 ] || fail "$v exits $status"
  [ "$(cat "$work/out")" = "linkage $version" ] || fail "$v printed: $(cat "$work/out")"
  [ ! -s "$work/err" ] || fail "$v wrote on standard error: $(cat "$work/err")"
done

run --help
[ $status -eq 0 ] || fail "--help exits $status"
[ ! -s "$work/err" ] || fail "--help wrote on standard error: $(cat "$work/err")"
for o in --screenshot --angle --ics --plots --forces --size --dark --extremes --transmission \
  --checks --3d --plane --version --help; do
  grep -q -- "$o" "$work/out" || fail "--help does not list $o"
done
grep -q -- "--benchmark" "$work/out" && fail "--help lists the moved benchmark options"

# Every screenshot option, before and after the model, as --opt value and --opt=value.
run --screenshot "$work/a.png" wanzer-inversion-2 --angle 30 --ics --plots --forces --size 900x700 \
  --dark --extremes --transmission --checks
[ $status -eq 0 ] || fail "--screenshot with every option exits $status: $(cat "$work/err")"
[ -s "$work/a.png" ] && [ "$(png_size "$work/a.png")" = "900x700" ] ||
  fail "--size 900x700 gave $(png_size "$work/a.png")"
run --size=1000x640 --angle=-30 four-bar-crank-rocker --screenshot="$work/b.png"
[ $status -eq 0 ] || fail "--opt=value forms exit $status: $(cat "$work/err")"
[ "$(png_size "$work/b.png")" = "1000x640" ] || fail "--size=1000x640 gave $(png_size "$work/b.png")"

# --3d: the picture is the 3D view alone, of the asked size (not the window's picture).
run --screenshot "$work/w.png" rssr-crank-rocker --size 640x480
run --screenshot "$work/v.png" rssr-crank-rocker --3d --size 640x480 --plane rocker
[ $status -eq 0 ] || fail "--3d exits $status: $(cat "$work/err")"
[ "$(png_size "$work/v.png")" = "640x480" ] || fail "--3d --size 640x480 gave $(png_size "$work/v.png")"
cmp -s "$work/w.png" "$work/v.png" && fail "--3d gave the window's picture"

# Refusals: exit 2, the cause named on standard error.
expect_refusal() {
  what=$1
  shift
  run "$@"
  [ $status -eq 2 ] || fail "$* exits $status, not 2"
  grep -q -- "$what" "$work/err" || fail "$* does not say \"$what\": $(cat "$work/err")"
}
expect_refusal bogus --bogus
expect_refusal bogus --screenshot "$work/c.png" --bogus wanzer-inversion-2
expect_refusal "one model" --screenshot "$work/c.png" wanzer-inversion-2 four-bar-crank-rocker
expect_refusal "--size" --screenshot "$work/c.png" wanzer-inversion-2 --size big
expect_refusal "--angle" --screenshot "$work/c.png" wanzer-inversion-2 --angle ten
expect_refusal "no example" --screenshot "$work/c.png" no-such-example
expect_refusal "no plane \"nowhere\"" --screenshot "$work/c.png" rssr-crank-rocker --plane nowhere
expect_refusal linkage_frames_bench --benchmark-frames 5 wanzer-inversion-2
expect_refusal linkage_frames_bench --benchmark-drag 5
[ ! -e "$work/c.png" ] || fail "a refused screenshot was written"

[ $failed -eq 0 ] && echo "editor command line: all good"
exit $failed
