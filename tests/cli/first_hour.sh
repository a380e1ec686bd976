#!/usr/bin/env bash
# Requirement (issue 43, a user's first hour):
# - a scene run from another directory finds its included file and its mesh
#   (relative to the file that names them); a missing include names the
#   full path looked for; an entry set in one file and again in the file
#   that includes it is no warning;
# - a solve whose crown reaches the boundary is flagged in the files: the
#   front file (unreliable, reason), statistics.csv (unreliable_points,
#   reason, unreliable_cycles), run.json (the solves and the cycles), and
#   the ParaView series are timed by the cycles;
# - `--version`, and `--check`, which passes a good scene (and the shipped
#   demo and getting_started scenes) without writing anything and stops a
#   bad one with exit status 1;
# - `-s` sets an entry (in the run, in parameters.prm and in run.json's
#   overrides) and refuses one that does not exist; the step lines say the
#   time left;
# - a point with three coordinates in a 2D scene is an error (unless the
#   third is zero);
# - contrib/plot_growth.py and plot_front.py run as commands on a growth
#   run's output and draw their figures; every contrib/ script answers
#   --help without running.
#
#   first_hour.sh XCRACK_EXECUTABLE SOURCE_DIRECTORY
set -u
xcrack="$1"
top="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
fail() { echo "FAILED: $*"; failures=$((failures + 1)); }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1

# --- Paths relative to the file that names them.
mkdir -p scene/meshes scene/cases elsewhere
cp "$top/tests/mesh/distorted_2d.msh" scene/meshes/plate.msh
cat > scene/base.prm <<'EOF'
set Dimension = 2
set Output directory = out
subsection Mesh
  set Type      = file
  set File name = meshes/plate.msh
end
subsection Boundary conditions
  set Dirichlet = 0: 0; 0
  set Neumann   = 1: 1; 0
end
EOF
printf 'include ../base.prm\nset Output directory = from_elsewhere\n' > scene/cases/run.prm
(cd elsewhere && "$xcrack" ../scene/cases/run.prm > run.log 2>&1) ||
  { fail "paths: a scene run from another directory"; cat elsewhere/run.log; }
[ -s elsewhere/from_elsewhere/statistics.csv ] || fail "paths: no results"
grep -q "File name *= $work/scene/meshes/plate.msh" elsewhere/from_elsewhere/parameters.prm ||
  fail "paths: parameters.prm does not hold the absolute mesh file"
grep -q "Warning" elsewhere/run.log && fail "paths: an override of an included entry warned"
printf 'include missing.prm\nset Dimension = 2\n' > scene/cases/broken.prm
(cd elsewhere && "$xcrack" ../scene/cases/broken.prm > broken.log 2>&1)
[ $? -eq 1 ] && grep -q "looked for $work/scene/cases/missing.prm" elsewhere/broken.log ||
  { fail "paths: a missing include does not name the path looked for"; cat elsewhere/broken.log; }

# --- --version and --check.
"$xcrack" --version > version.log 2>&1 && grep -Eq '^xcrack [0-9a-f]+.* \(deal.II 9' version.log ||
  { fail "--version"; cat version.log; }
for shipped in "$top/prm/demo.prm" "$top/prm/getting_started.prm"; do
  "$xcrack" --check "$shipped" > shipped.log 2>&1 || { fail "--check $shipped"; cat shipped.log; }
done
sed 's#^set Output directory.*#set Output directory = checked/not_made#' scene/base.prm > scene/check.prm
"$xcrack" --check scene/check.prm > check.log 2>&1 && grep -q "every input check passed" check.log ||
  { fail "--check of a good scene"; cat check.log; }
[ -e scene/checked ] && fail "--check created the output directory"
sed 's#set Neumann   = 1: 1; 0#set Neumann = 9: 1; 0#' scene/check.prm > scene/bad.prm
"$xcrack" --check scene/bad.prm > bad.log 2>&1
[ $? -eq 1 ] && grep -q "boundary id 9 does not exist" bad.log || { fail "--check of a bad scene"; cat bad.log; }

# --- A point with three coordinates in 2D.
cat > point.prm <<'EOF'
set Dimension = 2
set Output directory = point
subsection Mesh
  set Subdivisions = 4, 4
end
subsection Boundary conditions
  set Dirichlet = 0: 0; 0
  set Neumann   = 1: 1; 0
end
subsection Cracks
  set Number of cracks = 1
  subsection Crack 1
    set Start point = 0, 0.45, 0.5
    set End point   = 0.5, 0.45
    set Tips        = end
  end
end
EOF
"$xcrack" --check point.prm > point.log 2>&1
[ $? -eq 1 ] && grep -q "Start point = '0, 0.45, 0.5': three coordinates in a 2D scene" point.log ||
  { fail "a 3-coordinate point in 2D"; cat point.log; }
sed -i 's/0, 0.45, 0.5/0, 0.45, 0/' point.prm
"$xcrack" --check point.prm > point0.log 2>&1 || { fail "a 2D point with z = 0"; cat point0.log; }

# --- A growth run whose crowns reach the boundary, set from the command line.
demo=(-s "Output directory=grow" -s "Propagation/Number of steps=2"
      -s "Fracture parameters/Crown radii=6, 12")
"$xcrack" "${demo[@]}" "$top/prm/demo.prm" > grow.log 2>&1 || { fail "growth run"; cat grow.log; }
# (With the timing summary on, each step says the time left.)
[ "$(grep -c '^Step [01]: .* s left)$' grow.log)" -eq 2 ] || { fail "no time left on the step lines"; cat grow.log; }
grep -q "Unreliable: .* of the .* cycles" -i grow.log || { fail "no end summary of the flags"; cat grow.log; }
"$xcrack" -s "Propagation/Maximum advanc=1" "$top/prm/demo.prm" > typo.log 2>&1
[ $? -eq 1 ] && grep -q "Maximum advanc" typo.log || fail "-s with an entry that does not exist"
python3 - grow <<'PYTHON' || fail "the flags in the files"
import csv, json, sys
d = sys.argv[1]
record = json.load(open(f"{d}/run.json"))
assert record["overrides"][1] == "Propagation/Number of steps=2", record["overrides"]
flagged = record["unreliable"]
assert "001" in flagged["solves"] and "002" in flagged["solves"], flagged
assert flagged["reasons"] == ["crown reaches the boundary or another front"], flagged
assert abs(flagged["cycles"] - record["cycles"]) < 1e-9 * record["cycles"], flagged
rows = list(csv.DictReader(open(f"{d}/statistics.csv")))
last = rows[-1]
assert int(last["unreliable_points"]) == 1 and last["reason"] != "", last
assert float(last["unreliable_cycles"]) == float(last["cycles"]) > 0, last
front = list(csv.DictReader(open(f"{d}/front_002.csv")))
assert front[0]["unreliable"] == "1" and front[0]["reason"].startswith("crown"), front[0]
steps = [l for l in open(f"{d}/parameters.prm") if "Number of steps" in l]
assert steps and steps[0].split("=")[1].strip() == "2", steps
# ParaView time: the cycles of each step's last solve.
import re
times = [float(t) for t in re.findall(r'timestep="([^"]*)"', open(f"{d}/solution.pvd").read())]
cycles = {}
for r in rows:
    cycles[int(r["step"])] = float(r["cycles"])
expected = [cycles[s] for s in sorted(cycles)]
assert len(times) == len(expected) and all(
    abs(t - c) <= 1e-9 * max(1., c) for t, c in zip(times, expected)), (times, cycles)
PYTHON

# --- The plot scripts, as the README shows them, with the system Python.
"$top/contrib/plot_growth.py" grow > plot_growth.log 2>&1 &&
  [ -s grow/growth_cycles.png ] && [ -s grow/growth_path.png ] && [ -s grow/growth_rate.png ] ||
  { fail "contrib/plot_growth.py"; cat plot_growth.log; }
grep -q "crown reaches the boundary" plot_growth.log || fail "plot_growth.py does not show the flags"
"$top/contrib/plot_front.py" grow > plot_front.log 2>&1 && [ -s grow/front.png ] ||
  { fail "contrib/plot_front.py"; cat plot_front.log; }
touch help.log
for script in "$top"/contrib/*.py "$top"/contrib/*.sh; do
  case "$script" in *xcrack_runs.py) continue ;; esac
  [ -x "$script" ] || fail "$script is not executable"
  before="$(ls -A)"
  timeout 60 "$script" --help > help.log 2>&1 && grep -qi "usage\|^[A-Z]" help.log ||
    { fail "$script --help"; cat help.log; }
  [ "$(ls -A)" = "$before" ] || fail "$script --help wrote files"
done

if [ "$failures" -eq 0 ]; then
  echo "cli/first_hour: all checks passed"
else
  echo "cli/first_hour: $failures check(s) failed"
  exit 1
fi
