#!/usr/bin/env bash
# Installation as a user meets it. Usage: run.sh BUILD_DIR
#  - cmake --install of the build tree into a scratch prefix; the installed frictionlab tool runs
#    from there with no environment variables (RUNPATH $ORIGIN/../lib);
#  - the shared library exports the public API and no detail:: symbol, and has its soname;
#  - the consumer example (examples/cpp_consumer: a friction law and a short simulation) configures
#    with find_package(frictionlab) without a word about the library's private dependencies, builds
#    and runs, once against the installed prefix and once against the build tree, and once more
#    against the prefix built with Clang (the public headers must suit both compilers).
set -euo pipefail
build=$(cd "$1" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
source_dir=$(cd "$here/../.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
passed=0 failed=0
pass() { echo "install test: PASS  $1"; passed=$((passed + 1)); }
fail() { echo "install test: FAIL  $1" >&2; failed=$((failed + 1)); }

prefix="$scratch/prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null

# The installed tool, with a clean environment (no LD_LIBRARY_PATH, no PATH entry).
if out=$(env -i "$prefix/bin/frictionlab" --version 2>&1) && [[ -n "$out" ]]; then
  pass "installed frictionlab --version runs with no environment variables ($out)"
else
  fail "installed frictionlab --version: $out"
fi

# The shared library: soname, exports.
lib=$(ls "$prefix"/lib*/libfrictionlab.so.*.*.* 2>/dev/null | head -1)
soname=$(objdump -p "$lib" | awk '/SONAME/ {print $2}')
if [[ "$soname" =~ ^libfrictionlab\.so\.[0-9]+$ ]]; then pass "soname $soname"; else fail "soname '$soname' of $lib"; fi
exported=$(nm -DC --defined-only "$lib" | grep -c ' frictionlab::' || true)
# frictionlab::detail:: and frictionlab::<layer>::detail:: (not std::__detail:: in a signature).
detail_re='frictionlab::([A-Za-z0-9_]+::)*detail::'
detail=$(nm -DC --defined-only "$lib" | grep -cE "$detail_re" || true)
if ((exported > 0 && detail == 0)); then
  pass "$exported frictionlab:: symbols exported, none of detail::"
else
  fail "$exported frictionlab:: symbols exported, $detail of them detail:: (expected none)"
  nm -DC --defined-only "$lib" | grep -E "$detail_re" | head -20 >&2
fi
if [[ -d "$prefix/include/frictionlab" && -f "$prefix/include/frictionlab/export.hpp" ]] &&
   ! ls "$prefix/include/frictionlab/io/atomic_write.hpp" "$prefix/include/frictionlab/report" >/dev/null 2>&1; then
  pass "headers installed with export.hpp, internal headers not installed"
else
  fail "installed headers (export.hpp missing, or an internal header installed)"
fi

# The consumer example against a prefix (CMAKE_PREFIX_PATH) and against the build tree.
consumer() {
  local what=$1 path=$2 dir="$scratch/consumer-${1// /-}" log
  shift 2  # further arguments go to cmake (a compiler)
  if ! log=$(cmake -S "$source_dir/examples/cpp_consumer" -B "$dir" -DCMAKE_PREFIX_PATH="$path" -DCMAKE_BUILD_TYPE=Release "$@" 2>&1); then
    fail "consumer against the $what: configure failed"; echo "$log" >&2; return
  fi
  if grep -qi 'ceres\|sundials' <<<"$log"; then
    fail "consumer against the $what: configuring speaks of private dependencies:"; grep -i 'ceres\|sundials' <<<"$log" >&2
  fi
  if ! log=$(cmake --build "$dir" -j 2 2>&1); then
    fail "consumer against the $what: build failed"; echo "$log" >&2; return
  fi
  if out=$(env -i "$dir/cpp_consumer" 2>&1) && [[ "$out" == *"velocity after 1.0 s 0.9516 m/s"* ]]; then
    pass "consumer example against the $what: $out"
  else
    fail "consumer example against the $what printed: $out"
  fi
}
consumer prefix "$prefix"
consumer "build tree" "$build"
if command -v clang++ >/dev/null; then consumer "prefix with Clang" "$prefix" -DCMAKE_CXX_COMPILER=clang++; fi

echo "install-test: $passed passed, $failed failed"
((failed == 0))
