#!/usr/bin/env bash
# Installs the Debian 12 packages gaitsynth needs, only those that are missing.
#   scripts/install_deps.sh [--tests]   (--tests adds what only the test suite needs)
set -euo pipefail
# libcli11-dev: the examples' command lines (header-only).
pkgs=(g++ cmake ninja-build libeigen3-dev libboost-dev nlohmann-json3-dev libcli11-dev)
if [[ "${1:-}" == "--tests" ]]; then
  # catch2 2.13: tests; libbenchmark-dev: benchmarks (built to keep them compiling);
  # libmujoco-dev: rigid-body oracle and benchmark peer; chromium: headless player test;
  # python3: plot scripts; python3-matplotlib: scripts/plot_convergence.py and its test;
  # libcgal-dev: the exact QP solver the QP tests compare with;
  # Open MPI: the MPI evaluator (gaitsynth::mpi) and its tests under mpirun.
  # libqhull-dev: libmujoco-dev exports its include dir without depending on it.
  # libtinyxml2-dev: an independent XML parser that reads the SVG and MJCF the tests write.
  pkgs+=(catch2 libbenchmark-dev libmujoco-dev libqhull-dev chromium python3 python3-matplotlib
         libcgal-dev libopenmpi-dev openmpi-bin libtinyxml2-dev)
fi
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "gaitsynth: installing ${missing[*]}"
  SUDO=""
  [[ $(id -u) -ne 0 ]] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
