#!/usr/bin/env bash
# Requirement (issue 41): a growth run ends with correct results or with a
# clear reason, never with exit 0 and wrong or missing numbers, and writes
# nothing outside its output directory:
# - a growth law without a finite rate (Forman at K_Ic, a Paris exponent
#   that overflows): the run ends as a failure naming the point, and no CSV
#   holds inf;
# - a tip that runs into a hole: the run ends at that step and counts no
#   cycles for the advance that took the tip out;
# - compression without contact: K_I < 0 is closed lips, the point does not
#   grow, the run says so and the front file flags it;
# - a steep quasi-static exponent still moves the most loaded point by
#   Maximum advance; loads of 1e-169 give the kink and K_eq of unit loads
#   (scaled);
# - a link planted at a temporary file's name is not followed;
# - a parameter file that includes itself, `--resume` without a directory:
#   exit 1 with a message;
# - cracks that grow into each other: the run ends there (exit 0, the
#   reason in run.json), not with an input error;
# - a second run into the directory of a running one is refused, naming
#   it; a killed run leaves no lock behind;
# - a checkpoint edited, truncated or missing a file is refused by name;
# - bad input found in the first solve keeps the earlier run's results.
# The scene: the demo (prm/demo.prm), one mesh per step (step 0 on the
# initial mesh, the fronts refined to level 4 as the cracks grow).
#
#   growth_checks.sh XCRACK_EXECUTABLE SOURCE_DIRECTORY
set -u
xcrack="$1"
demo="$2/prm/demo.prm"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
fail() { echo "FAILED: $*"; failures=$((failures + 1)); }

# run STATUS NAME REGEX STEPS < extra prm lines: the demo with STEPS steps,
# into out_NAME, exit status STATUS and a screen matching REGEX.
run() {
  local status="$1" name="$2" regex="$3" steps="$4"
  {
    echo "include $demo"
    echo "set Output directory = out_$name"
    printf 'subsection Output\n  set Write vtu = false\n  set Timing summary = false\nend\n'
    printf 'subsection Mesh refinement\n  set Number of meshes = 1\n  set Growth level = 4\nend\n'
    printf 'subsection Propagation\n  set Number of steps = %s\nend\n' "$steps"
    cat
  } > "$name.prm"
  "$xcrack" "$name.prm" > "$name.log" 2>&1
  local got=$?
  [ "$got" -eq "$status" ] || { fail "$name: exit status $got, expected $status"; tail -3 "$name.log"; }
  grep -Ezq -- "$regex" "$name.log" || { fail "$name: message does not match '$regex':"; tail -3 "$name.log"; }
}
no_inf() {
  grep -Eiq "(^|,)[-+]?(nan|inf)(,|$)" "out_$1"/*.csv && fail "$1: nan or inf in a CSV"
}
law() { printf 'subsection Propagation\n  subsection Growth law\n    set Model name = %s\n%b  end\nend\n' "$1" "$2"; }

# 1. Rates that are not finite.
run 0 forman "Failure: the growth law gives no finite rate at \(-0.08 0.03\).*K_max reached the fracture toughness K_Ic = 10\): the part fails" 2 \
  < <(law forman ""; printf 'subsection Material\n  set Fracture toughness = 10\nend\n'
      printf 'subsection Termination criteria\n  set Termination criteria =\nend\n')
no_inf forman
grep -q '"reason": "Failure: the growth law' out_forman/run.json || fail "forman: run.json has not the reason"
run 0 paris_overflow "Failure: the growth law gives no finite rate .*the rate overflows" 2 \
  < <(law paris "    subsection Paris\n      set m = 300\n    end\n")
no_inf paris_overflow

# 2. A tip that runs into the hole (a straight crack ending 12 mm from the
# hole's centre, no termination criterion): step 3 ends the run and adds
# no cycles.
run 0 into_hole "End: crack 1 has 0 tips after the last advance instead of 1" 10 \
  < <(printf 'subsection Cracks\n  subsection Crack 1\n    set End point = -0.012, 0.03\n  end\nend\n'
      printf 'subsection Termination criteria\n  set Termination criteria =\nend\n')
python3 - out_into_hole/statistics.csv <<'PY' || fail "into_hole: the last step counts cycles"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
last, before = rows[-1], rows[-2]
print("into_hole: last step", last["step"], "delta_cycles", last["delta_cycles"])
sys.exit(0 if float(last["delta_cycles"]) == 0 and last["cycles"] == before["cycles"] else 1)
PY

# 3. Compression without contact: closed, no growth, flagged.
run 0 compression "Warning: K_I < 0 at 1 of 1 front points.*End: no front point grows any more \(K_I < 0 everywhere" 3 \
  < <(printf 'subsection Boundary conditions\n  set Neumann = 3: 0; -40\nend\n')
python3 - out_compression/front_000.csv <<'PY' || fail "compression: the front file does not flag the closed tip, or it advances"
import csv, sys
row = next(csv.DictReader(open(sys.argv[1])))
sys.exit(0 if row["closed"] == "1" and float(row["K_I"]) < 0 and float(row["advance"]) == 0 else 1)
PY

# 4. Underflow: a steep quasi-static law, loads of 1e-169.
run 0 quasi_static "Step 1: load factor" 1 \
  < <(law quasi-static "    subsection Quasi-static\n      set Exponent = 1000\n    end\n")
run 0 unit_loads "Step 1:" 1 < /dev/null
run 0 tiny_loads "Step 0:" 1 \
  < <(printf 'subsection Boundary conditions\n  set Neumann = 3: 0; 4e-169\nend\n')
python3 - out_unit_loads/front_000.csv out_tiny_loads/front_000.csv <<'PY' || fail "tiny_loads: the kink or K_eq differs from unit loads"
import csv, sys
unit = next(csv.DictReader(open(sys.argv[1])))
tiny = next(csv.DictReader(open(sys.argv[2])))
angle = abs(float(tiny["angle"]) - float(unit["angle"]))
k_eq = abs(float(tiny["K_eq"]) / 4e-169 * 40 - float(unit["K_eq"])) / float(unit["K_eq"])
print("tiny_loads: kink angle difference %.1e rad, K_eq relative difference %.1e" % (angle, k_eq))
sys.exit(0 if angle < 1e-9 and k_eq < 1e-9 and float(unit["angle"]) != 0 else 1)
PY

# 5. A link planted at a temporary file's name is not followed.
mkdir -p out_link && ln -s "$work/target.csv" out_link/statistics.csv.tmp
run 0 link "Step 1:" 1 < /dev/null
[ -e target.csv ] && fail "link: the run wrote through the planted link"
[ -f out_link/statistics.csv ] && [ ! -L out_link/statistics.csv ] || fail "link: no statistics.csv"
[ -e out_link/statistics.csv.tmp ] && fail "link: the planted link is still there"

# 6. Includes in a circle; --resume without a directory.
printf 'include b.prm\nset Dimension = 2\n' > a.prm
printf 'include a.prm\nset Dimension = 2\n' > b.prm
"$xcrack" a.prm > circle.log 2>&1
[ $? -eq 1 ] && grep -q "input error: Parameter file 'a.prm': includes run in a circle: 'a.prm' includes 'b.prm' includes 'a.prm'" circle.log ||
  { fail "circle: no clear message"; cat circle.log; }
"$xcrack" --resume > resume.log 2>&1
[ $? -eq 1 ] && grep -q "xcrack: --resume takes one argument, the output directory" resume.log ||
  { fail "resume: no clear message"; cat resume.log; }

# 7. Two cracks that grow into each other: the run ends at the step it
# cannot solve, the steps before stand (not an input error).
cat > meet.prm <<'PRM'
set Dimension = 2
set Output directory = out_meet
subsection Mesh
  set Lower corner = -1, -1
  set Upper corner = 1, 1
  set Subdivisions = 8, 8
  set Initial global refinement = 1
end
subsection Cracks
  set Number of cracks = 2
  subsection Crack 1
    set Start point = -0.6, 0.01
    set End point   = -0.2, 0.01
  end
  subsection Crack 2
    set Start point = 0.2, 0.01
    set End point   = 0.6, 0.01
  end
end
subsection Boundary conditions
  set Neumann       = 2: 0; -1 | 3: 0; 1
  set Pinned points = 0, -1: xy | 0, 1: x
end
subsection Propagation
  set Number of steps = 10
  set Maximum advance = 0.05
end
subsection Output
  set Write vtu = false
  set Timing summary = false
end
PRM
"$xcrack" meet.prm > meet.log 2>&1
[ $? -eq 0 ] && grep -q "End: step 2 cannot be solved: Cracks/Crack 1 and Crack 2: their enriched zones meet" meet.log ||
  { fail "meet: no clear end"; tail -3 meet.log; }
grep -q '"status": "completed"' out_meet/run.json && [ -f out_meet/front_001.csv ] ||
  fail "meet: the record or the steps before are missing"

# 8. One run per directory: a second run into the directory of one that is
# running is refused, naming it; once the first is killed, a run may start.
{ echo "include $demo"; echo "set Output directory = out_lock"
  printf 'subsection Output\n  set Write vtu = false\nend\n'; } > lock.prm
"$xcrack" lock.prm > lock_first.log 2>&1 &
first=$!
for _ in $(seq 1 3000); do [ -f out_lock/run.json ] && break; sleep 0.01; done
"$xcrack" lock.prm > lock_second.log 2>&1
[ $? -eq 1 ] && grep -q "input error: Output directory = out_lock: another run is writing there (process $first: " lock_second.log ||
  { fail "lock: the second run was not refused by name"; cat lock_second.log; }
kill -9 "$first" 2> /dev/null || fail "lock: the first run ended before it could be killed"
wait "$first" 2> /dev/null
run 0 lock_after_kill "Step 1:" 1 < <(echo "set Output directory = out_lock")

# 9. A checkpoint changed or damaged after it was written is refused by
# name before anything reads it.
run 0 checkpoint "Step 2:" 2 < /dev/null
resume_refused() {
  "$xcrack" --resume out_checkpoint > "resume_$1.log" 2>&1
  [ $? -eq 1 ] && grep -q "input error: --resume out_checkpoint: out_checkpoint/checkpoint/$2" "resume_$1.log" ||
    { fail "checkpoint $1: not refused by name"; cat "resume_$1.log"; }
}
cp -r out_checkpoint/checkpoint saved
echo "set Output directory = elsewhere" >> out_checkpoint/checkpoint/parameters.prm
resume_refused edited "parameters.prm is not the file the run wrote"
rm -rf out_checkpoint/checkpoint && cp -r saved out_checkpoint/checkpoint
truncate -s 100 out_checkpoint/checkpoint/mesh
resume_refused truncated "mesh is not the file the run wrote"
rm -rf out_checkpoint/checkpoint && cp -r saved out_checkpoint/checkpoint
rm out_checkpoint/checkpoint/mesh_fixed.data
resume_refused deleted "mesh_fixed.data is missing"

# 10. Bad input found in the first solve (crowns that hold no vertex) loses
# nothing of the earlier run in the directory.
run 0 keep "Step 1:" 1 < /dev/null
cp out_keep/front_001.csv kept.csv
run 1 keep_bad "input error: Fracture parameters/Crown radii: the crown of tip 1 .* holds no vertex" 1 \
  < <(echo "set Output directory = out_keep"
      printf 'subsection Fracture parameters\n  set Crown unit = absolute\n  set Crown radii = 1e-7, 1e-6\nend\n')
cmp -s kept.csv out_keep/front_001.csv && grep -q '"status": "completed"' out_keep/run.json &&
  [ -d out_keep/checkpoint ] && [ ! -e out_keep/.earlier ] ||
  fail "keep: the earlier run's results were not kept"
grep -q "1e-7" out_keep/parameters.prm && fail "keep: parameters.prm is the failed run's"

if [ "$failures" -eq 0 ]; then
  echo "cli/growth_checks: all checks passed"
else
  echo "cli/growth_checks: $failures check(s) failed"
  exit 1
fi
