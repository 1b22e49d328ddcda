#!/usr/bin/env bash
# Installs everything Sightline needs to build, run and test on Debian 12 (bookworm).
# Idempotent: when every package is present it only checks and returns.
set -euo pipefail

packages=(
  build-essential cmake pkg-config ninja-build clang-format
  libvulkan-dev vulkan-validationlayers vulkan-tools
  glslang-dev glslang-tools spirv-tools
  libglm-dev libglfw3-dev libtinygltf-dev nlohmann-json3-dev libstb-dev
  libx11-dev libxcb1-dev libxrandr-dev  # the window's own X connection (render/window_surface.hpp)
  libgtest-dev libgmock-dev libbenchmark-dev libimgui-dev fonts-dejavu-core libembree-dev
  xvfb xauth xdotool
  clang libclang-rt-14-dev python3 python3-jsonschema
  python3-pil  # tests/play_window_test.sh reads the window's captures
)
# Mesa >= 24.1 is the first lavapipe with ray tracing; bookworm has 22.3, backports 25.x.
mesa_min_version="24.1"

manual_hint() {
  echo "Install by hand: a C++20 compiler, CMake >= 3.25, the Vulkan loader and headers," \
    "the Khronos validation layers, glslang (library and tools), GLM, GLFW 3, tinygltf," \
    "nlohmann-json, stb, GoogleTest, Embree 3, Xvfb, and a Vulkan driver with ray tracing" \
    "(Mesa >= ${mesa_min_version} lavapipe, or an NVIDIA/AMD driver)." >&2
}

if [ ! -r /etc/os-release ] || ! grep -q '^VERSION_CODENAME=bookworm' /etc/os-release; then
  echo "setup: this script knows Debian 12 (bookworm) only; this machine is something else." >&2
  manual_hint
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive

mesa_version() { dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || true; }
mesa_is_new_enough() {
  local version
  version=$(mesa_version)
  [ -n "$version" ] && dpkg --compare-versions "$version" ge "$mesa_min_version"
}
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q 'install ok installed' ||
    missing+=("$package")
done
if [ ${#missing[@]} -eq 0 ] && mesa_is_new_enough; then
  echo "setup: all packages present (mesa-vulkan-drivers $(mesa_version))."
  exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    exec sudo -n -E bash "$0" "$@"
  fi
  echo "setup: installing ${missing[*]:-mesa-vulkan-drivers (>= ${mesa_min_version})} needs root (run it as root or with sudo)." >&2
  manual_hint
  exit 1
fi

# Derive bookworm-backports from the mirror this machine already uses (no host is named here).
backports_list=/etc/apt/sources.list.d/sightline-backports.sources
if ! grep -rqs 'bookworm-backports' /etc/apt/sources.list /etc/apt/sources.list.d/; then
  mirror=""
  if [ -r /etc/apt/sources.list.d/debian.sources ]; then
    mirror=$(awk 'BEGIN{RS=""} /Suites:[^\n]*bookworm([ \n]|$)/ {
        if (match($0, /URIs: *[^\n]+/)) { s = substr($0, RSTART + 5, RLENGTH - 5); sub(/^ +/, "", s); split(s, u, " "); print u[1]; exit } }' \
      /etc/apt/sources.list.d/debian.sources)
  fi
  if [ -z "$mirror" ] && [ -r /etc/apt/sources.list ]; then
    mirror=$(awk '$1=="deb" && $3=="bookworm" {print $2; exit}' /etc/apt/sources.list)
  fi
  if [ -z "$mirror" ]; then
    echo "setup: found no apt source for bookworm to derive bookworm-backports from." >&2
    manual_hint
    exit 1
  fi
  keyring=/usr/share/keyrings/debian-archive-keyring.gpg
  {
    echo "Types: deb"
    echo "URIs: ${mirror}"
    echo "Suites: bookworm-backports"
    echo "Components: main"
    [ -r "$keyring" ] && echo "Signed-By: ${keyring}"
  } >"$backports_list"
  echo "setup: added bookworm-backports from ${mirror}"
fi

apt-get update -qq
apt-get install -y -qq --no-install-recommends "${packages[@]}"
apt-get install -y -qq --no-install-recommends -t bookworm-backports mesa-vulkan-drivers
if ! mesa_is_new_enough; then
  echo "setup: mesa-vulkan-drivers $(mesa_version) is older than ${mesa_min_version}: lavapipe has no ray tracing." >&2
  exit 1
fi
echo "setup: ready (mesa-vulkan-drivers $(mesa_version))."
