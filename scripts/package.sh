#!/usr/bin/env bash
# Builds the Debian package voxflame_VERSION_ARCH.deb (CPack) in the build folder and prints its
# path. Usage: scripts/package.sh [BUILD_DIR]; then: sudo apt-get install ./build/voxflame_*.deb
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
"$root/scripts/setup.sh" "$build"
cd "$build"
cpack -G DEB >/dev/null
ls -1 "$build"/voxflame_*.deb | tail -n 1
