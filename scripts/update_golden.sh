#!/usr/bin/env bash
# Renders the golden reference images in tests/golden again (after an intended change to the
# picture). Look at every PNG it writes before committing them.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
VOXFLAME_BUILD_TARGET=gl_tests "$root/scripts/setup.sh" "$root/build"
mkdir -p "$root/tests/golden"
VOXFLAME_UPDATE_GOLDEN=1 "$root/build/tests/gl_tests" --gtest_filter='Presets/GoldenImage.*'
ls -l "$root/tests/golden"
