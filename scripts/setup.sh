#!/usr/bin/env bash
# Installs the Debian packages voxflame needs (only those missing), then configures and builds
# it. Used by both README commands. Usage: scripts/setup.sh [BUILD_DIR] [extra cmake args...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
shift || true

mapfile -t packages < <(grep -v '^\s*#' "$root/scripts/packages.txt" | sed '/^\s*$/d')
missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "voxflame setup: installing ${missing[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends "${missing[@]}"
fi

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE="${VOXFLAME_BUILD_TYPE:-Release}" "$@" >/dev/null
# VOXFLAME_BUILD_TARGET may name several targets, separated by spaces.
# shellcheck disable=SC2086
cmake --build "$build" -j "$(nproc)" ${VOXFLAME_BUILD_TARGET:+--target $VOXFLAME_BUILD_TARGET}
