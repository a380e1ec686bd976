#!/usr/bin/env bash
# Install, only when missing, the Debian 12 packages xcrack needs to build, test and plot.
# Idempotent: a second call checks with dpkg and returns at once.
set -euo pipefail
case "${1:-}" in
  -h|--help)
    sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "${BASH_SOURCE[0]}"
    exit 0 ;;
esac

packages=(
  cmake g++ make ccache numdiff
  libmetis-dev            # METIS: the ordering xcrack hands to MUMPS
  libdeal.ii-dev          # deal.II 9.4.1 with MPI, p4est, Trilinos, PETSc (+ MUMPS)
  openmpi-bin             # mpirun for the parallel tests and runs
  libopenblas0-pthread    # optimised BLAS: MUMPS is 18x faster than with reference BLAS
  nlohmann-json3-dev      # the JSON writer of run.json (header only)
  python3 python3-matplotlib python3-numpy
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "xcrack: installing missing Debian packages: ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
