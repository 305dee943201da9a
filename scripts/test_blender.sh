#!/usr/bin/env bash
# The Blender bridge for real: installs Debian's Blender (3.4, Cycles built in) and the OpenVDB
# Python module, exports two presets as VDB volumes with voxflame, brings each into Blender with
# scripts/blender/voxflame_import.py and renders it headless with Cycles on the CPU (small, few
# samples, no denoising: Debian's Blender has no OpenImageDenoise), then checks with
# scripts/blender/compare_lit_area.py that Blender's picture is lit where voxflame's own render of
# the same preset at the same size and camera is lit. The two presets cover both ways to the
# mesh: the built-in default names builtin:meshes/bunny.obj (passed with --mesh), lorenz-heart a
# file (found through the path stored in the volume). Also checks that the bridge's own reader of
# the VDB header finds the preset pyopenvdb finds. With VOXFLAME_BLENDER_OUTPUT set, the pictures
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
  "$voxflame" render $preset -o "$name-voxflame.png" --width "$width" --height "$height" --points "$points" | tail -n 1
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
grep -q "compiled into voxflame: pass --mesh" builtin.log || { cat builtin.log; exit 1; }

# The bridge reads the preset from the VDB header itself when pyopenvdb is missing; both agree.
blender_run --python-expr "
import importlib.util, sys, pyopenvdb
spec = importlib.util.spec_from_file_location('bridge', '$bridge')
bridge = importlib.util.module_from_spec(spec)
spec.loader.exec_module(bridge)
for path in ('default.vdb', 'lorenz-heart.vdb'):
    if bridge.read_vdb_file_metadata(path) != pyopenvdb.readMetadata(path):
        sys.exit('the VDB header reader disagrees with pyopenvdb on ' + path)
" >reader.log 2>&1 || { cat reader.log; exit 1; }
say "passed"
