#!/usr/bin/env bash
# Renders every shipped preset (presets/*.json) to presets/gallery/<preset>.png and rewrites the
# README's gallery, the part between <!-- gallery:start --> and <!-- gallery:end -->, as a table
# of those images with each preset's name, attractors and mesh.
#
#   scripts/gallery.sh [VOXFLAME] [--table-only | PRESET.json...]
#
# VOXFLAME is the built binary (default: build/app/voxflame). Naming presets renders only those,
# --table-only renders none; the table always lists them all. GALLERY_WIDTH, GALLERY_HEIGHT and GALLERY_SAMPLES override the
# image size (640×400) and the jittered samples per pixel (4). The points are each preset's own.
# The share of each mesh the pattern covers (the render's statistics) goes in the table too.
# Animated presets (with keyframes) also get a looping GIF (GALLERY_ANIMATION_WIDTH ×
# GALLERY_ANIMATION_HEIGHT, default 320×200, through `voxflame animate` and ImageMagick).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
voxflame="$root/build/app/voxflame"
if [[ $# -gt 0 && "$1" != *.json && "$1" != --table-only ]]; then
  voxflame="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
  shift
fi
[[ -x "$voxflame" ]] || { echo "gallery.sh: no voxflame binary at $voxflame (build first, or pass its path)" >&2; exit 1; }
width="${GALLERY_WIDTH:-640}"
height="${GALLERY_HEIGHT:-400}"
samples="${GALLERY_SAMPLES:-4}"
readme="$root/README.md"
gallery="$root/presets/gallery"
mkdir -p "$gallery"
grep -q '^<!-- gallery:start -->$' "$readme" && grep -q '^<!-- gallery:end -->$' "$readme" ||
  { echo "gallery.sh: $readme lacks the <!-- gallery:start --> / <!-- gallery:end --> lines" >&2; exit 1; }

# The default preset first, then the others by file name.
presets=("$root/presets/default.json")
for file in "$root"/presets/*.json; do
  [[ "$file" == "$root/presets/default.json" ]] || presets+=("$file")
done

to_render=("$@")
[[ ${#to_render[@]} -gt 0 ]] || to_render=("${presets[@]}")
[[ "${to_render[0]}" != --table-only ]] || to_render=()
# Each render's share of the mesh covered by the pattern is kept in coverage.tsv for the table.
coverage="$gallery/coverage.tsv"
touch "$coverage"
for file in "${to_render[@]+"${to_render[@]}"}"; do
  stem="$(basename "$file" .json)"
  echo "rendering $stem"
  line="$("$voxflame" render "$file" -o "$gallery/$stem.png" --width "$width" --height "$height" \
    --samples "$samples" --bit-depth 8)"
  echo "$line"
  percent="$(grep -o 'covers [0-9]*%' <<<"$line" | grep -o '[0-9]*' || true)"
  { grep -v "^$stem	" "$coverage" || true; printf '%s\t%s\n' "$stem" "$percent"; } | sort >"$coverage.new"
  mv "$coverage.new" "$coverage"
  # An animated preset (one with keyframes) also becomes a looping GIF of its frames, shown in
  # the table in place of the still (which stays, as the preset's thumbnail).
  if grep -q '"keyframes"' "$file"; then
    command -v convert >/dev/null ||
      { echo "gallery.sh: $stem is animated; its GIF needs ImageMagick's convert (apt-get install imagemagick)" >&2; exit 1; }
    frames="$(mktemp -d)"
    "$voxflame" animate "$file" -o "$frames/%04d.png" --width "${GALLERY_ANIMATION_WIDTH:-320}" \
      --height "${GALLERY_ANIMATION_HEIGHT:-200}" >/dev/null
    fps="$(grep -o '"fps": *[0-9.]*' "$file" | head -n 1 | grep -o '[0-9.]*$' || echo 30)"
    delay="$(awk -v fps="$fps" 'BEGIN { printf "%d", 100 / fps + 0.5 }')"
    convert -delay "$delay" -loop 0 "$frames"/*.png -layers Optimize "$gallery/$stem.gif"
    rm -rf "$frames"
    echo "wrote $gallery/$stem.gif ($(ls "$gallery/$stem.gif" >/dev/null && echo "loop at $fps fps"))"
  fi
done

# Attractor ids to their catalogue names, from `voxflame list --json` (one object per attractor,
# its "id" and "name" at the first level of indentation).
declare -A attractor_names
while IFS=$'\t' read -r id name; do
  attractor_names["$id"]="$name"
done < <("$voxflame" list --json | awk '
  /^    "id": "/ { id = $0; sub(/^    "id": "/, "", id); sub(/",?$/, "", id) }
  /^    "name": "/ { name = $0; sub(/^    "name": "/, "", name); sub(/",?$/, "", name); print id "\t" name }')

# The first "name" in a preset is its title (layers have no name); the attractors are every
# layer's "attractor"; the mesh is the file name of "mesh.path" without its extension.
json_strings() { grep -o "\"$1\": *\"[^\"]*\"" "$2" | sed 's/^"[^"]*": *"//; s/"$//'; }
cell() {
  local file="$1" stem title mesh attractors="" id
  stem="$(basename "$file" .json)"
  title="$(json_strings name "$file" | head -n 1)"
  mesh="$(json_strings path "$file" | head -n 1)"
  mesh="$(basename "${mesh#builtin:}")"
  mesh="${mesh%.*}"
  # Each attractor once, in the order of its first layer (several layers of one attractor at
  # different rotations are one pattern).
  while read -r id; do
    attractors+="${attractors:+ + }${attractor_names[$id]:-$id}"
  done < <(json_strings attractor "$file" | awk '!seen[$0]++')
  # Chaos-game layers name their kind instead of an attractor.
  while read -r kind; do
    case "$kind" in
      flame) attractors+="${attractors:+ + }fractal flame" ;;
      quaternion_julia) attractors+="${attractors:+ + }quaternion Julia set" ;;
    esac
  done < <(json_strings kind "$file" | awk '!seen[$0]++')
  local covered
  covered="$(awk -F '\t' -v stem="$stem" '$1 == stem && $2 != "" { print " · covers " $2 "%" }' "$gallery/coverage.tsv" 2>/dev/null || true)"
  local image="$stem.png"
  [[ -f "$gallery/$stem.gif" ]] && grep -q '"keyframes"' "$file" && image="$stem.gif"
  printf '<td align="center"><a href="presets/%s.json"><img src="presets/gallery/%s" width="280" alt="%s"></a><br><b>%s</b><br><sub>%s · %s%s</sub></td>' \
    "$stem" "$image" "$title" "$title" "$attractors" "$mesh" "$covered"
}

table="$(mktemp)"
trap 'rm -f "$table"' EXIT
{
  echo '<table>'
  column=0
  for file in "${presets[@]}"; do
    [[ $column -eq 0 ]] && printf '<tr>'
    cell "$file"
    column=$(((column + 1) % 3))
    [[ $column -eq 0 ]] && printf '</tr>\n'
  done
  [[ $column -eq 0 ]] || printf '</tr>\n'
  echo '</table>'
} >"$table"

awk -v table="$table" '
  /^<!-- gallery:start -->$/ { print; while ((getline line < table) > 0) print line; skipping = 1; next }
  /^<!-- gallery:end -->$/ { skipping = 0 }
  !skipping { print }' "$readme" >"$readme.new"
mv "$readme.new" "$readme"
echo "updated the gallery in $readme (${#presets[@]} presets)"
