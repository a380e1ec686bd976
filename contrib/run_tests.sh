#!/usr/bin/env bash
# Quick start, command 2: build xcrack against deal.II's debug library if
# needed and run the whole test suite (ctest, two jobs). Extra arguments go to
# ctest, e.g. `contrib/run_tests.sh -R manufactured`.
set -euo pipefail
case "${1:-}" in
  -h|--help)
    sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "${BASH_SOURCE[0]}"
    exit 0 ;;
esac
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$top/contrib/build.sh" debug
cd "$top/build/debug"
# Open MPI refuses to start as root unless told; CI runs as root.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Two MPI ranks on two cores: keep BLAS single-threaded to avoid oversubscription.
export OPENBLAS_NUM_THREADS=1
ctest -j"$(nproc)" --output-on-failure "$@"
