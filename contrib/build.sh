#!/usr/bin/env bash
# Build xcrack in build/<type> (type: release or debug), installing the Debian
# packages it needs first if they are missing. Idempotent: a second call only
# rebuilds what changed.
#
#   contrib/build.sh release    # optimised, for runs and studies
#   contrib/build.sh debug      # deal.II's debug library, for the test suite
set -euo pipefail
case "${1:-}" in
  -h|--help)
    sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "${BASH_SOURCE[0]}"
    exit 0 ;;
esac

type="${1:-release}"
case "$type" in
  release) cmake_type=Release ;;
  debug)   cmake_type=Debug ;;
  *) echo "contrib/build.sh: build type must be 'release' or 'debug', not '$type'" >&2; exit 1 ;;
esac

top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$top/contrib/install_dependencies.sh"

build="$top/build/$type"
mkdir -p "$build"
# Configure every time (a few seconds): deal.II picks up tests by globbing
# at configure time, so a new test file needs it.
cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE="$cmake_type" > "$build/cmake.log" \
  || { cat "$build/cmake.log"; exit 1; }
cmake --build "$build" -- -j"$(nproc)"
