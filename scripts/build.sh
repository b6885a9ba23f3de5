#!/usr/bin/env bash
# Configures and builds appell (Release, i.e. -O3, with the interval rigour flags) in ./build.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build build -j"$(nproc)"
