#!/usr/bin/env bash
# Builds the Debian package, installs it with apt-get (as root or through sudo), renders a shipped
# preset with /usr/bin/voxflame in an empty folder, lists the catalogue, checks the desktop entry,
# icon and MIME type are in place, and removes the package again (also when a check fails).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
if dpkg-query -W -f='${Status}' voxflame 2>/dev/null | grep -q "install ok installed"; then
  echo "test_package.sh: a voxflame package is already installed; remove it first" >&2
  exit 1
fi
deb="$("$root/scripts/package.sh" "${1:-$root/build}" | tail -n 1)"
echo "built $deb"
work="$(mktemp -d)"
cleanup() {
  DEBIAN_FRONTEND=noninteractive $sudo apt-get remove -y voxflame >/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends "$deb" >/dev/null
[ "$(command -v voxflame)" = /usr/bin/voxflame ] || { echo "voxflame is not /usr/bin/voxflame" >&2; exit 1; }
for file in /usr/share/applications/voxflame.desktop /usr/share/icons/hicolor/256x256/apps/voxflame.png \
  /usr/share/mime/packages/voxflame.xml /usr/share/voxflame/presets/lorenz-heart.json \
  /usr/share/voxflame/presets/meshes/sphere.obj /usr/share/voxflame/presets/gallery/lorenz-heart.png \
  /usr/share/voxflame/blender/voxflame_blender.zip /usr/share/voxflame/blender/voxflame_import.py; do
  [ -f "$file" ] || { echo "the package lacks $file" >&2; exit 1; }
done
cd "$work"
/usr/bin/voxflame render /usr/share/voxflame/presets/lorenz-heart.json -o still.png --width 160 --height 100 \
  --points 2000000
[ -s still.png ] || { echo "the installed voxflame wrote no image" >&2; exit 1; }
/usr/bin/voxflame list | grep -q '^lorenz84 ' || { echo "voxflame list lacks lorenz84" >&2; exit 1; }
echo "package test: installed, rendered, listed and removed $(basename "$deb")"
