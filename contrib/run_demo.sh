#!/usr/bin/env bash
# Quick start, command 1: build xcrack (Release) if needed and run the demo
# scene prm/demo.prm. Results go to output/demo/ (VTU fields and CSV tables).
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$top/contrib/build.sh" release
cd "$top"
"$top/build/release/xcrack" prm/demo.prm
echo "Results in $top/output/demo (open solution.pvd in ParaView)."
