#!/usr/bin/env bash
# Installs frictionlab from the build tree into a scratch prefix, then configures, builds and
# runs a consumer project that finds it with find_package(frictionlab). Usage: run.sh BUILD_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cmake --install "$build" --prefix "$scratch/prefix" >/dev/null
cmake -S "$here/consumer" -B "$scratch/consumer" -DCMAKE_PREFIX_PATH="$scratch/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$scratch/consumer" -j 2 >/dev/null
out=$("$scratch/consumer/consumer")
expected="stribeck 1.5 1.0 consumer ok"
if [[ "$out" != "$expected" ]]; then
  echo "install test: consumer printed '$out', expected '$expected'" >&2
  exit 1
fi
echo "install test: a consumer found frictionlab with find_package, built and ran"
echo "install-test: 1 passed, 0 failed"
