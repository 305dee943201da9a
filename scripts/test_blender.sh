#!/usr/bin/env bash
# The Blender bridge for real: installs Debian's Blender (3.4, Cycles built in) and the OpenVDB
# Python module, exports two presets as VDB volumes with voxflame, brings each into Blender with
# scripts/blender/voxflame_import.py and renders it headless with Cycles on the CPU (small, few
# samples, no denoising: Debian's Blender has no OpenImageDenoise), then checks with
# scripts/blender/compare_lit_area.py that Blender's picture is lit where voxflame's own render of
# the same preset at the same size and camera is lit. The two presets cover both ways to the
# mesh: the built-in default names builtin:meshes/bunny.obj (passed with --mesh), lorenz-heart a
# file (found through the path stored in the volume). Also checks that the bridge's own reader of
# the VDB header finds the preset pyopenvdb finds, and installs the add-on zip the build makes and
# imports a still and a 4-frame sequence with it. With VOXFLAME_BLENDER_OUTPUT set, the pictures
# are copied there. Usage: scripts/test_blender.sh [VOXFLAME_BINARY]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
voxflame="$(realpath "${1:-$root/build/app/voxflame}")"
[ -x "$voxflame" ] || { echo "test_blender.sh: no voxflame binary at $voxflame (build it first)" >&2; exit 1; }
bridge="$root/scripts/blender/voxflame_import.py"
start=$SECONDS
say() { echo "test_blender.sh ($((SECONDS - start)) s): $*"; }

packages=(blender python3-openvdb)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  say "installing ${missing[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update >/dev/null
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends "${missing[@]}" >/dev/null
fi
say "$(blender --version 2>/dev/null | head -n 1)"

work="$(mktemp -d)"
cleanup() { rm -rf "$work"; }
trap cleanup EXIT
cd "$work"
width=320
height=200
points=3000000
# --python-exit-code: an exception in the bridge fails the run (Blender would exit 0 otherwise).
blender_run() { blender -b --factory-startup --python-exit-code 1 "$@"; }

# NAME PRESET (or "" for the built-in default) [bridge options...]
check() {
  local name="$1" preset="$2"
  shift 2
  "$voxflame" render $preset -o "$name.vdb" --points "$points" | tail -n 1
  # The volume method: Blender ray-marches the exported grid, so that is the picture to compare with.
  "$voxflame" render $preset -o "$name-voxflame.png" --width "$width" --height "$height" --points "$points" \
    --method volume | tail -n 1
  local seconds=$SECONDS
  blender_run --python "$bridge" -- "$name.vdb" "$@" --render "$name-blender.png" --width "$width" \
    --height "$height" --samples 16 >"$name-blender.log" 2>&1 || { cat "$name-blender.log"; exit 1; }
  grep '^voxflame_import' "$name-blender.log"
  say "Blender rendered $name in $((SECONDS - seconds)) s"
  python3 "$root/scripts/blender/compare_lit_area.py" "$name-voxflame.png" "$name-blender.png"
  if [ -n "${VOXFLAME_BLENDER_OUTPUT:-}" ]; then
    mkdir -p "$VOXFLAME_BLENDER_OUTPUT"
    cp "$name-voxflame.png" "$name-blender.png" "$VOXFLAME_BLENDER_OUTPUT/"
  fi
}

check default "" --mesh "$root/presets/meshes/bunny.obj"
check lorenz-heart "$root/presets/lorenz-heart.json"

# Without --mesh, a built-in mesh is named and the scene is still made (camera on the volume).
blender_run --python "$bridge" -- default.vdb >builtin.log 2>&1 || { cat builtin.log; exit 1; }
grep -q "compiled into voxflame: give its file" builtin.log || { cat builtin.log; exit 1; }

# The bridge reads the preset from the VDB header itself when pyopenvdb is missing; both agree.
blender_run --python-expr "
import sys, pyopenvdb
sys.path.insert(0, '$root/scripts/blender')
from voxflame_blender import importer
for path in ('default.vdb', 'lorenz-heart.vdb'):
    if importer.read_vdb_file_metadata(path) != pyopenvdb.readMetadata(path):
        sys.exit('the VDB header reader disagrees with pyopenvdb on ' + path)
" >reader.log 2>&1 || { cat reader.log; exit 1; }

# The add-on as an artist installs it: the build's zip through Blender's preferences, then File >
# Import > voxflame volume (.vdb) (its operator) on a still and on a 4-frame VDB sequence of a
# shipped animated preset (one frame a second, so the frames differ), with frames 1 and 4 rendered
# in Cycles. They must differ from each other and be lit where voxflame's own frames are.
addon="$(dirname "$voxflame")/../voxflame_blender.zip"
[ -f "$addon" ] || { echo "test_blender.sh: no add-on zip at $addon (build it first)" >&2; exit 1; }
animated="$root/presets/aizawa-breathing.json"
"$voxflame" animate "$animated" -o 'seq/%04d.vdb' --frames 0-3 --fps 1 --points "$points" | tail -n 1
"$voxflame" animate "$animated" -o 'seq-voxflame/%04d.png' --frames 0-3 --fps 1 --points "$points" \
  --width "$width" --height "$height" | tail -n 1
cat >addon.py <<'PYTHON'
import os, sys, bpy
addon, still, first, width, height = sys.argv[sys.argv.index("--") + 1:]
bpy.ops.preferences.addon_install(filepath=addon, overwrite=True)
bpy.ops.preferences.addon_enable(module="voxflame_blender")
scene = bpy.context.scene
scene.render.resolution_x, scene.render.resolution_y = int(width), int(height)
for obj in list(scene.objects):
    bpy.data.objects.remove(obj, do_unlink=True)
if bpy.ops.import_scene.voxflame_volume(filepath=still, sequence=False, shell="WIRE", emission_strength=1.5,
                                        absorption=0.5) != {"FINISHED"}:
    sys.exit("the still did not import")
if not any(o.type == "VOLUME" and not o.data.is_sequence for o in scene.objects):
    sys.exit("no still volume")
for obj in list(scene.objects):
    bpy.data.objects.remove(obj, do_unlink=True)
if bpy.ops.import_scene.voxflame_volume(filepath=first) != {"FINISHED"}:
    sys.exit("the sequence did not import")
volume = next(o for o in scene.objects if o.type == "VOLUME")
if not volume.data.is_sequence or volume.data.frame_duration != 4 or scene.frame_end != 4:
    sys.exit("the sequence is not one animated volume of 4 frames")
scene.cycles.samples = 32
for frame in (1, 4):
    scene.frame_set(frame)
    scene.render.filepath = os.path.abspath("seq-blender-%d.png" % frame)
    bpy.ops.render.render(write_still=True)
PYTHON
blender_run --python addon.py -- "$(realpath "$addon")" default.vdb seq/0000.vdb "$width" "$height" >addon.log 2>&1 ||
  { cat addon.log; exit 1; }
grep -E "^Info: (Modules Installed|voxflame:)" addon.log
python3 "$root/scripts/blender/compare_lit_area.py" seq-voxflame/0000.png seq-blender-1.png
python3 "$root/scripts/blender/compare_lit_area.py" seq-voxflame/0003.png seq-blender-4.png
python3 - "$root/scripts/blender" seq-blender-1.png seq-blender-4.png <<'PYTHON'
import sys
sys.path.insert(0, sys.argv[1])
from compare_lit_area import read_png
first, last = read_png(sys.argv[2]), read_png(sys.argv[3])
values = [(a, b) for row_a, row_b in zip(first, last) for pa, pb in zip(row_a, row_b) for a, b in zip(pa, pb)]
difference = sum(abs(a - b) for a, b in values) / max(1, len(values))
print("Blender's frames 1 and 4 differ by %.2f of 255 on average" % difference)
if difference < 1.0:
    sys.exit("Blender's frames 1 and 4 are the same picture: the sequence does not animate")
PYTHON
if [ -n "${VOXFLAME_BLENDER_OUTPUT:-}" ]; then cp seq-blender-1.png seq-blender-4.png "$VOXFLAME_BLENDER_OUTPUT/"; fi
say "passed"
