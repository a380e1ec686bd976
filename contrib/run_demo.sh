#!/usr/bin/env bash
# Quick start, command 1: build xcrack (Release) if needed and run the demo
# scene prm/demo.prm, a fatigue crack growing in a plate with a hole (well
# under a minute). Results go to output/demo/: the figures of the growth
# (PNG), the tables (CSV) and the fields (VTU, for ParaView).
set -euo pipefail
case "${1:-}" in
  -h|--help)
    sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "${BASH_SOURCE[0]}"
    exit 0 ;;
esac
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$top/contrib/build.sh" release
cd "$top"
"$top/build/release/xcrack" prm/demo.prm
"$top/contrib/plot_growth.py" output/demo --length-unit m --stress-unit MPa > /dev/null
echo "Results in $top/output/demo: growth_cycles.png, growth_path.png, growth_rate.png;"
echo "open solution.pvd and crack.pvd in ParaView to watch the crack grow."
