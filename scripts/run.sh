#!/usr/bin/env bash
# README command 1: set up, build and open the explorer (on the default preset unless a preset
# is given). Without a display it renders the preset to a PNG and prints its path.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh" "$root/build"
exec "$root/build/app/voxflame" "$@"
