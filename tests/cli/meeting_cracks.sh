# Two cracks that approach each other (issue 42), with each level-set update
# method: prm/benchmarks/en_passant_2d.prm on coarser cells (2/64 at the
# tips) and advances of 0.04, so that the tips pass each other in ten steps.
# Each method must
# - end the run before the cracks meet, with the clear message of the
#   enrichment ("End: step N cannot be solved: Cracks/Crack 1 and Crack 2:
#   their enriched zones meet"), exit status 0, run.json completed, N >= 11;
# - keep one tip per crack (no piece of crack) and the scene's symmetry (the
#   tips at step 10 opposite within 1e-3);
# - put the tip of step 10 within a quarter of a cell (0.008) of the
#   geometric update's, past the other tip (x > 0.15) and turned back
#   towards the other crack (y > -0.08).
# Before the extension planes were straightened (the band's lsn ahead of
# the front, and the ring beyond it), `upwind` put that tip 0.016 behind and
# `simplex` 0.02 away, the two tips no longer opposite.
#
#   meeting_cracks.sh XCRACK_EXECUTABLE SOURCE_DIRECTORY
set -u
xcrack="$1"
scene="$2/prm/benchmarks/en_passant_2d.prm"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
fail() { echo "FAILED: $*"; failures=$((failures + 1)); }

# tips DIR STEP: the tips of the front file of step STEP, "x y" per line.
tips() { awk -F, 'NR > 1 { print $3, $4 }' "$1/front_$(printf %03d "$2").csv"; }

for method in geometric "crack mesh" upwind simplex; do
  out="out_${method// /_}"
  "$xcrack" -s "Output directory=$out" \
    -s "Propagation/Level set update/Model name=$method" \
    -s "Mesh refinement/Number of meshes=3" \
    -s "Propagation/Maximum advance=0.04" \
    -s "Output/Timing summary=false" "$scene" > "$out.log" 2>&1
  status=$?
  end=$(grep -o "End: step [0-9]* cannot be solved: Cracks/Crack 1 and Crack 2: their enriched zones meet" "$out.log")
  step=$(echo "$end" | awk '{ print $3 }')
  if [ $status -ne 0 ] || [ -z "$end" ] || [ "$step" -lt 11 ]; then
    fail "$method: no clear end before the cracks meet (status $status)"
    tail -3 "$out.log"
    continue
  fi
  grep -q '"status": "completed"' "$out/run.json" || fail "$method: run.json not completed"
  [ "$(tips "$out" 10 | wc -l)" -eq 2 ] || fail "$method: step 10 has $(tips "$out" 10 | wc -l) tips, not 2"
  tips "$out" 10 | tr '\n' ' ' | awk -v m="$method" '{
      if ((($1 + $3) ^ 2 + ($2 + $4) ^ 2) ^ 0.5 > 1e-3)
        { print "FAILED: " m ": tips at step 10 not opposite: " $0; exit 1 } }' ||
    failures=$((failures + 1))
  echo "$method: ends at step $step (the enriched zones would meet); tip of crack 1 at step 10: $(tips "$out" 10 | head -1)"
done

# The paths: crack 1's tip at step 10 against the geometric update's.
read -r gx gy < <(tips out_geometric 10 | head -1)
for method in geometric "crack mesh" upwind simplex; do
  out="out_${method// /_}"
  [ -f "$out/front_010.csv" ] || continue
  tips "$out" 10 | head -1 | awk -v m="$method" -v gx="$gx" -v gy="$gy" '{
      d = (($1 - gx) ^ 2 + ($2 - gy) ^ 2) ^ 0.5
      if (d > 0.008 || $1 <= 0.15 || $2 <= -0.08)
        { printf "FAILED: %s: tip of step 10 at (%s %s), %.4f from the geometric update'"'"'s\n", m, $1, $2, d; exit 1 } }' ||
    failures=$((failures + 1))
done

[ $failures -eq 0 ] && echo "meeting_cracks: all checks passed"
exit $failures
