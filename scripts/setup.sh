#!/usr/bin/env bash
# Installs the Debian packages frictionlab needs, and only those that are missing.
# Usage: scripts/setup.sh [extra-package ...]
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  ccache  # repeated builds (a second checkout, the fuzz and Python builds) reuse compiled objects
  libeigen3-dev libceres-dev libsundials-dev libcli11-dev nlohmann-json3-dev
  libyaml-cpp-dev libmatio-dev zlib1g-dev libdeflate-dev libssl-dev libgtest-dev libgmock-dev libbenchmark-dev
  pybind11-dev python3-dev python3-numpy python3-matplotlib python3-scipy python3-pytest
  python3-distributed  # frictionlab.batch on Dask (a LocalCluster or any Client); optional at import
  python3-venv python3-pip python3-setuptools python3-wheel gnuplot-nox
  chromium  # the headless browser of the report test (tests/cli/report_browser.sh)
  libmujoco-dev  # MuJoCo's C library: tests/export loads and runs the MJCF that export --mjcf writes
  python3-sphinx python3-myst-parser doxygen  # the documentation site (make docs): Sphinx reads docs/*.md through MyST; Doxygen makes the C++ reference
  clang libfuzzer-14-dev libclang-rt-14-dev  # the libFuzzer targets (with ASan and UBSan runtimes) of tests/fuzz/ (make fuzz, and a bounded run in make test)
)
packages+=("$@")

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "frictionlab setup: installing ${missing[*]}" >&2
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "frictionlab setup: need root or sudo to install ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
