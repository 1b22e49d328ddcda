#!/usr/bin/env bash
# Installs the build into a fresh prefix and runs the installed game from / : it must find its
# shaders and levels in <prefix>/share/sightline, not in the source tree or the current directory.
# usage: install_test.sh <cmake> <build dir>
set -euo pipefail
cmake_command=$1
build_dir=$2

prefix=$(mktemp -d "${TMPDIR:-/tmp}/sightline-install-test.XXXXXX")
trap 'rm -rf "$prefix"' EXIT

"$cmake_command" --install "$build_dir" --prefix "$prefix" > "$prefix/install.log" ||
  { cat "$prefix/install.log"; echo "FAIL: cmake --install"; exit 1; }

level="$prefix/share/sightline/levels/01_first_light.json"
cd /
# An explicit data directory would hide a wrong install layout.
unset SIGHTLINE_DATA_DIR

"$prefix/bin/sightline" validate "$level" || { echo "FAIL: installed validate"; exit 1; }
"$prefix/bin/sightline" render "$level" --size 32x18 --out "$prefix/x.png" ||
  { echo "FAIL: installed render"; exit 1; }
[[ -s "$prefix/x.png" ]] || { echo "FAIL: installed render wrote no $prefix/x.png"; exit 1; }

# A level copied out of levels/ (a player's own folder) still finds the game's assets: a path
# starting with "assets/" names the installed asset directory wherever the level is.
mkdir -p "$prefix/my levels"
cp "$level" "$prefix/my levels/copy.json"
"$prefix/bin/sightline" validate "$prefix/my levels/copy.json" ||
  { echo "FAIL: a copied level outside levels/ cannot use assets/"; exit 1; }

# The build tree's shaders would also be found (the binary knows its source directory), so prove
# the installed ones are read: break one and the render must fail naming it. A private shader
# cache keeps the good compile from being reused.
echo '#error the installed shader is the one compiled' >> "$prefix/share/sightline/shaders/raygen.rgen"
if SIGHTLINE_SHADER_CACHE="$prefix/shader-cache" "$prefix/bin/sightline" render "$level" \
    --size 32x18 --out "$prefix/y.png" 2> "$prefix/broken.log"; then
  echo "FAIL: the installed render did not read $prefix/share/sightline/shaders"; exit 1
fi
grep -q "$prefix/share/sightline/shaders/raygen.rgen" "$prefix/broken.log" ||
  { cat "$prefix/broken.log"; echo "FAIL: the shader error does not name the installed file"; exit 1; }
echo "PASS: the installed game validates and renders from /, with its installed data"
