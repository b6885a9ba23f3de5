#!/usr/bin/env bash
# Installs the Debian packages appell needs, where they are missing.
set -euo pipefail
packages=(g++ make cmake libeigen3-dev libboost-dev libboost-test-dev libgmp-dev
          libmpfr-dev libmpfi-dev libflint-arb-dev libqd-dev nlohmann-json3-dev gnuplot-nox libbenchmark-dev
          valgrind libsimbody-dev libboost-mpi-dev libopenmpi-dev openmpi-bin libssl-dev libtinyxml2-dev dart-doc
          libdart-dev libdart-utils-urdf-dev liborocos-kdl-dev libkdl-parser-dev libmujoco-dev
          libbullet-dev liburdfdom-dev pkg-config ccache
          pybind11-dev python3-dev python3-numpy python3-pytest python3-mpmath python3-pandas python3-matplotlib)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "appell: installing Debian packages: ${missing[*]}" >&2
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
