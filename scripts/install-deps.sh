#!/usr/bin/env bash
# Installs every Debian package symmesh's build, tests and demo use. Idempotent: packages already
# present are not reinstalled, and apt-get update runs only when something is missing.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build ccache pkg-config git clang-format
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev libboost-graph-dev
  libeigen3-dev libtbb-dev
  libgtest-dev libgmock-dev librapidcheck-dev
  libgraphviz-dev graphviz librsvg2-bin
  libcli11-dev nlohmann-json3-dev
  libgmsh-dev gmsh
  libtet1.5-dev
  petsc-dev openmpi-bin
  zlib1g-dev
  python3-meshio python3-matplotlib python3-vtk9
  time
  pybind11-dev python3-pybind11 python3-dev python3-pytest python3-networkx python3-numpy
)

# Optional groups: --fuzz adds clang-14 and its libFuzzer/sanitizer runtime (fuzz/run.sh).
if [ "${1:-}" = "--fuzz" ]; then
  PACKAGES+=(clang-14 libclang-rt-14-dev)
fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
