#!/usr/bin/env bash
# Installs the Debian packages exact-hlr needs (only when something is missing),
# then configures and builds Release into build/ (HLR_BUILD_TARGET: one target only). Idempotent;
# works as root or via sudo.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${HLR_BUILD_DIR:-$ROOT/build}"
BUILD_TYPE="${HLR_BUILD_TYPE:-Release}"

PACKAGES=(build-essential cmake pkg-config
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libeigen3-dev libopenmesh-dev
  libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
  libtbb-dev                              # oneTBB: the parallel loop
  libcairo2-dev libdxflib-dev             # PDF/PNG (cairo) and DXF (dxflib) output
  libmuparser-dev libpng-dev              # hlr horizon: expressions of x and z, PNG heightmaps
  zlib1g-dev                              # the PDF writer's compression
  poppler-utils librsvg2-bin              # tests: pdfinfo/pdftoppm read our PDFs, rsvg-convert our SVGs
  netpbm                                  # tests: pngtopnm turns pictures into pixels to compare
  clang-format                            # tests: the house style on changed lines (.clang-format)
  parallel                                # tests: the tile example of docs/usage.md runs GNU parallel
  python3-dev python3-pybind11 python3-pytest   # the Python module and its tests
  python3-numpy python3-venv python3-pip python3-build   # the Python package: numpy arrays, pip install ., wheels
  libgtest-dev libbenchmark-dev time   # time: peak memory in scripts/bench_render.sh
  clang libclang-rt-14-dev   # the sanitizer build and the libFuzzer targets
  libocct-data-exchange-dev libocct-modeling-algorithms-dev   # STEP and IGES models (Open CASCADE)
  libtinygltf-dev lib3mf-dev              # glTF 2 and 3MF models
  python3-ezdxf                           # tests: ezdxf audits our DXF files
  occt-misc assimp-testmodels             # tests: real STEP, IGES, glTF and 3MF models
  assimp-utils                            # docs: IFC buildings converted to glTF
  libcgal-demo)   # libcgal-demo ships data.tar.gz, the mesh corpus used by tests and benchmarks

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then
    if ! command -v sudo >/dev/null 2>&1; then
      echo "setup: missing packages (${missing[*]}); run as root or install sudo" >&2
      exit 1
    fi
    SUDO="sudo"
  fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

JOBS="$(nproc 2>/dev/null || echo 2)"
cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE="$BUILD_TYPE" "$@" >/dev/null
# HLR_BUILD_TARGET=hlr builds the program alone (the demo); unset: everything (tests, benchmarks,
# the Python package).
cmake --build "$BUILD_DIR" -j "$JOBS" ${HLR_BUILD_TARGET:+--target "$HLR_BUILD_TARGET"}
