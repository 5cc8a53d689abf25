#!/usr/bin/env bash
# The editor's folders are layers (issue 26): each folder of ui/ includes only its own files and
# the folders its line below names, all of them on lines above its own, so that no folder
# includes one that includes it back (draw and the element kinds below the canvas, the tools and
# the Properties; the window on top). Every #include of a ui/ folder is checked; a forbidden one
# fails naming the file, the line and the include. The solver's headers (linkage/...) and Qt's
# are not ui/ folders and are not checked here.
#   tests/ui_layers.sh [UI_DIR]     (default: the ui/ beside tests/)
#   tests/ui_layers.sh --self-test  (the check itself: an upward include and an unknown folder
#                                    planted in a copy of ui/ must fail, naming them)
set -euo pipefail

# Bottom to top: a folder, then the folders it may include; "*" is every folder above its line.
# A new folder goes on the line above the first folder that includes it.
layers='
document:
draw:
forms:       document
figures:
docks:       figures
elements:    document draw forms
canvas:      document draw elements
tools:       document draw elements canvas
view3d:      document draw tools
properties:  document forms elements tools
mechanisms:  document tools
animation:   document
centres:     document docks
export:      document figures
plots:       document docks figures export
forces:      document draw forms docks figures canvas export plots
design:      document draw docks figures canvas plots
cycle:       document docks figures canvas tools export plots forces
cam:         document docks figures canvas
window:      *
'

# Single includes allowed against the table until the change named takes them away: FILE (in
# ui/), the include, why. One that no longer occurs fails the test too: delete its line.
exceptions='
'

self=$(cd "$(dirname "$0")" && pwd)/$(basename "$0")

self_test() {
  local out
  tmp=$(mktemp -d)  # global: the trap reads it at exit
  trap 'rm -rf "$tmp"' EXIT
  cp -r "$(dirname "$self")/../ui" "$tmp/ui"
  "$self" "$tmp/ui" >/dev/null || { echo "FAIL: the tree as it is does not pass"; exit 1; }
  printf '#include "canvas/canvas_scene.h"\n' >>"$tmp/ui/elements/element_ui.h"
  local line
  line=$(wc -l <"$tmp/ui/elements/element_ui.h")
  if out=$("$self" "$tmp/ui" 2>&1); then
    echo "FAIL: an include of canvas/ from elements/ passed"
    exit 1
  fi
  grep -qF "ui/elements/element_ui.h:$line: #include \"canvas/canvas_scene.h\": elements may not include canvas" <<<"$out" ||
    { echo "FAIL: the upward include is not named: $out"; exit 1; }
  cp "$(dirname "$self")/../ui/elements/element_ui.h" "$tmp/ui/elements/element_ui.h"
  mkdir "$tmp/ui/newfolder"
  printf '#include "document/document.h"\n' >"$tmp/ui/newfolder/thing.h"
  if out=$("$self" "$tmp/ui" 2>&1); then
    echo "FAIL: a folder the table does not name passed"
    exit 1
  fi
  grep -qF "ui/newfolder: a folder the layer table does not name" <<<"$out" ||
    { echo "FAIL: the unknown folder is not named: $out"; exit 1; }
  echo "ok: an upward include and an unknown folder fail, named"
}
[ "${1:-}" = "--self-test" ] && { self_test; exit 0; }

ui=$(cd "${1:-$(dirname "$self")/../ui}" && pwd)
errors=0
error() {
  echo "$*"
  errors=$((errors + 1))
}

# The table: each folder's allowed folders, checked to name only folders above it.
declare -A allowed=() known=()
above=""
while read -r folder rest; do
  [ -n "$folder" ] || continue
  folder=${folder%:}
  list=""
  read -r -a names <<<"$rest"
  for a in "${names[@]}"; do
    if [ "$a" = "*" ]; then
      list="$list $above"
    elif [ -z "${known[$a]:-}" ]; then
      error "tests/ui_layers.sh: $folder may include $a, which is not on a line above it"
    else
      list="$list $a"
    fi
  done
  allowed[$folder]=" $list "
  known[$folder]=1
  above="$above $folder"
  [ -d "$ui/$folder" ] || error "tests/ui_layers.sh: the table names ui/$folder, which does not exist"
done <<<"$layers"

declare -A excused=() used=()
while read -r file include _; do
  [ -n "$file" ] && excused["$file $include"]=1
done <<<"$exceptions"

# Every folder with sources is in the table.
for dir in "$ui"/*/; do
  folder=$(basename "$dir")
  [ -n "$(find "$dir" \( -name '*.h' -o -name '*.cpp' \) -print -quit)" ] || continue
  [ -n "${known[$folder]:-}" ] ||
    error "ui/$folder: a folder the layer table does not name: add its line to tests/ui_layers.sh (bottom to top, above the folders that include it)"
done

checked=0
pattern='^[[:space:]]*#[[:space:]]*include[[:space:]]*["<]([^">]+)[">]'
while IFS= read -r hit; do
  path=${hit%%:*}
  rest=${hit#*:}
  line=${rest%%:*}
  text=${rest#*:}
  [[ $text =~ $pattern ]] || continue
  include=${BASH_REMATCH[1]}
  file=${path#"$ui"/}
  [[ $file == */* ]] || { error "ui/$file: not in a folder of ui/"; continue; }
  from=${file%%/*}
  # A relative include, resolved; one with no folder is looked for beside the file first.
  if [[ $include == ./* || $include == ../* ]]; then
    target=$(realpath -m --relative-to="$ui" "$(dirname "$path")/$include")
  elif [[ $include == */* ]]; then
    target=$include
  else
    continue
  fi
  to=${target%%/*}
  [[ $target == ../* || ! -d "$ui/$to" ]] && continue  # not a folder of ui/
  checked=$((checked + 1))
  [ "$to" = "$from" ] && continue
  [ -n "${known[$from]:-}" ] || continue  # said once, above
  if [ -n "${excused["$file $include"]:-}" ]; then
    used["$file $include"]=1
    continue
  fi
  [[ ${allowed[$from]} == *" $to "* ]] && continue
  read -r -a may <<<"${allowed[$from]}"
  error "ui/$file:$line: #include \"$include\": $from may not include $to (it may include: ${may[*]:-no other folder})"
done < <(grep -rnE '^[[:space:]]*#[[:space:]]*include' "$ui" --include='*.h' --include='*.cpp' | sort -t: -k1,1 -k2,2n)

for key in "${!excused[@]}"; do
  [ -n "${used[$key]:-}" ] ||
    error "tests/ui_layers.sh: the exception \"$key\" no longer occurs: delete its line"
done

if [ "$errors" -gt 0 ]; then
  echo "FAIL: $errors error(s) against the layers of ui/ (the table at the top of tests/ui_layers.sh)"
  exit 1
fi
echo "ok: $checked includes of ui/ folders keep the layers of tests/ui_layers.sh"
