#!/usr/bin/env bash
# Installs what is missing, builds, and runs the game. Arguments go to `sightline play`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset default >/dev/null
cmake --build --preset default -j "$(nproc)"
exec ./build/sightline play "$@"
