#!/usr/bin/env bash
# Installs every build and test dependency from Debian packages (README.md).
# Idempotent; works as root or through sudo. Mesa's lavapipe (with ray tracing) comes from
# bookworm-backports, added with the URI of this machine's own Debian source: no mirror is hard-coded.
# clang + libclang-rt-14-dev: libFuzzer for scripts/fuzz-check.sh (docs/viewer.md, "Fuzzing").
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

stamp=/var/lib/caustics-deps.v4   # bump when the package list changes
if [ -f "$stamp" ] && [ -z "${CAUSTICS_FORCE_DEPS:-}" ]; then exit 0; fi

debian_uri() {
  # The first Debian archive URI this machine already uses (deb822 or one-line format).
  local uri=""
  if ls /etc/apt/sources.list.d/*.sources >/dev/null 2>&1; then
    uri=$(awk '/^URIs:/{print $2}' /etc/apt/sources.list.d/*.sources | grep -v -- '-security' | grep -i debian | head -n1 || true)
  fi
  if [ -z "$uri" ] && [ -f /etc/apt/sources.list ]; then
    uri=$(awk '$1=="deb" && $0 !~ /security/ {for(i=2;i<=NF;i++) if ($i ~ /^(https?|file|ftp):/) {print $i; exit}}' /etc/apt/sources.list || true)
  fi
  echo "${uri:-}"
}

backports=/etc/apt/sources.list.d/caustics-bookworm-backports.list
if [ ! -f "$backports" ]; then
  uri=$(debian_uri)
  if [ -z "$uri" ]; then echo "install-deps: no Debian apt source found to derive bookworm-backports from" >&2; exit 1; fi
  echo "deb $uri bookworm-backports main" | $SUDO tee "$backports" >/dev/null
fi
# Backports are never preferred by default (priority 100); only Mesa is taken from there, by -t below.

export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends \
  build-essential cmake ninja-build pkg-config \
  libvulkan-dev vulkan-validationlayers glslang-tools spirv-tools vulkan-tools \
  libglm-dev libtinygltf-dev nlohmann-json3-dev libstb-dev libglfw3-dev libopenimageio-dev openimageio-tools \
  libgtest-dev libgmock-dev directx-headers-dev xvfb xauth \
  ccache libimgui-dev g++-mingw-w64-x86-64-posix python3-matplotlib \
  clang libclang-rt-14-dev
$SUDO apt-get install -y -q --no-install-recommends -t bookworm-backports mesa-vulkan-drivers
$SUDO touch "$stamp"
