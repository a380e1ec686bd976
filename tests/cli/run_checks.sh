#!/usr/bin/env bash
# Requirement: a run that passes the input checks writes numbers a user can
# trust, or stops with a message that names the cause:
# - data that is not finite where it is used: exit 1 naming the entry;
# - a rigid-body motion the supports leave free: exit 1 before any work;
#   a singular system the checks cannot see (a piece cut loose by the
#   crack): exit 3, "numerical failure";
# - a write that fails: exit 2 naming the file;
# - a crack or a tip the mesh cannot see, crowns that hold no vertex, a
#   refinement that repeats one mesh, a parameter file that is a directory,
#   empty, or sets an entry twice: exit 1 (the last one a warning);
# - a run writes run.json (running / completed / failed) and removes the
#   numbered files of an earlier run, so that a shorter run or a killed one
#   leaves no stale file beside its own, and contrib/ readers warn about an
#   incomplete run.
# The scene: a 2D square [-1,1]^2, 4 x 4 cells refined once, an edge crack.
#
#   run_checks.sh XCRACK_EXECUTABLE CONTRIB_DIRECTORY
set -u
xcrack="$1"
contrib="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
fail() { echo "FAILED: $*"; failures=$((failures + 1)); }

cat > base.prm <<'EOF'
set Dimension = 2
set Output directory = out
subsection Mesh
  set Lower corner = -1, -1
  set Upper corner = 1, 1
  set Subdivisions = 4, 4
  set Initial global refinement = 1
end
subsection Boundary conditions
  set Dirichlet = 2: 0; 0
  set Neumann = 3: 0; 1
end
subsection Cracks
  set Number of cracks = 1
  subsection Crack 1
    set Start point = -2, 0.1
    set End point = 0.1, 0.1
    set Tips = end
  end
end
subsection Output
  set Write vtu = false
  set Timing summary = false
end
EOF

# expect STATUS NAME REGEX < extra prm lines: base.prm plus the lines (later
# entries win), exit status STATUS and a message matching REGEX.
expect() {
  local status="$1" name="$2" regex="$3"
  { cat base.prm; cat; } > "$name.prm"
  "$xcrack" "$name.prm" > "$name.log" 2>&1
  local got=$?
  [ "$got" -eq "$status" ] || { fail "$name: exit status $got, expected $status"; tail -3 "$name.log"; }
  grep -Ezq -- "$regex" "$name.log" || { fail "$name: message does not match '$regex':"; tail -3 "$name.log"; }
}
bc() { printf 'subsection Boundary conditions\n  set %s\nend\n' "$1"; }
crack() {
  printf 'subsection Cracks\n  subsection Crack 1\n    set Start point = %s\n' "$1"
  printf '    set End point = %s\n    set Tips = %s\n  end\nend\n' "$2" "$3"
}

# 1. Data that is not finite where it is used.
expect 1 dirichlet_inf "input error: Boundary conditions/Dirichlet \(boundary 2\) is not finite at" \
  < <(bc "Dirichlet = 2: 1/x; 0")
expect 1 body_force_nan "input error: Boundary conditions/Body force is not finite at" \
  < <(bc "Body force = sqrt(-1-x*x); 0")
expect 1 lip_pressure_nan "input error: Boundary conditions/Lip pressure is not finite on the lips" \
  < <(bc "Lip pressure = log(x)")
expect 1 neumann_inf "input error: Boundary conditions/Neumann \(boundary 3\) is not finite at" \
  < <(bc "Neumann = 3: 0; 1e308*10")
# A zero reference K: absolute errors, never inf in a CSV.
expect 0 reference_zero "K_I = " \
  < <(printf 'subsection Fracture parameters\n  set Reference K = 0; 0\nend\n')
grep -q "K_I_error" out/statistics.csv || fail "reference_zero: no K_I_error column"
grep -Eiq "(^|,)[-+]?(nan|inf)" out/statistics.csv out/front_*.csv && fail "reference_zero: nan or inf in a CSV"

# 2. Singular systems.
expect 1 rollers_only "input error: Boundary conditions: the Dirichlet data and Pinned points leave the body free to move \(a translation along y" \
  < <(bc "Dirichlet components = 2: x")
expect 1 pins_in_a_line "input error: Boundary conditions: .* leave the body free to move \(a rotation about z\)" \
  < <(printf 'subsection Boundary conditions\n  set Dirichlet =\n  set Pinned points = -1, -1: xy | 1, -1: x\nend\n')
expect 3 cut_loose "numerical failure: .*a crack that cuts a piece loose" \
  < <(crack "-2, 0.1" "2, 0.1" none)
grep -q '"status": "failed"' out/run.json || fail "cut_loose: run.json does not say failed"

# 3. Writes that fail. statistics.csv a directory: named. A link to a full
# device: the file is written beside it and renamed over the link.
mkdir -p out && rm -rf out/* && mkdir out/statistics.csv
expect 2 unwritable "could not write out/statistics.csv" < /dev/null
rm -rf out && mkdir out && ln -s /dev/full out/statistics.csv
expect 0 full_device "K_I = " < /dev/null
[ -f out/statistics.csv ] && [ ! -L out/statistics.csv ] && [ "$(wc -l < out/statistics.csv)" -eq 2 ] ||
  fail "full_device: statistics.csv was not written"
touch a_file
expect 1 output_directory "input error: Output directory = a_file/out: cannot create it" \
  < <(echo "set Output directory = a_file/out")

# 4. Cracks the mesh cannot see, crowns too small, meshes that repeat.
expect 1 short_crack "input error: Cracks/Crack 1: the mesh does not see this crack" \
  < <(crack "0.05, 0.1" "0.15, 0.1" both)
expect 1 tip_on_boundary "input error: Cracks/Crack 1: the tip at \(-1 0.1\) lies on the boundary" \
  < <(crack "-1, 0.1" "0.1, 0.1" both)
expect 1 crack_on_face "input error: Cracks/Crack 1: the tip at \(0 -1\) lies on the boundary" \
  < <(crack "-1, -1" "0, -1" end)
expect 1 tiny_crowns "input error: Fracture parameters/Crown radii: the crown of tip 1 .* holds no vertex" \
  < <(printf 'subsection Fracture parameters\n  set Crown unit = absolute\n  set Crown radii = 1e-7, 1e-6\nend\n')
expect 1 maximum_level "input error: Mesh refinement/Maximum level = 0: the initial mesh already reaches level 1" \
  < <(printf 'subsection Mesh refinement\n  set Number of meshes = 3\n  set Maximum level = 0\nend\n')
expect 1 three_components "input error: Cracks/Crack 1/Start point = '-2, 0, abc': 'abc' is not a number" \
  < <(crack "-2, 0, abc" "0.1, 0.1" end)

# 5. The parameter file itself.
mkdir -p a_directory.prm
"$xcrack" a_directory.prm > directory.log 2>&1
[ $? -eq 1 ] && grep -q "input error: The parameter file 'a_directory.prm' is a directory" directory.log ||
  { fail "a parameter file that is a directory"; cat directory.log; }
: > empty.prm
"$xcrack" empty.prm > empty.log 2>&1
[ $? -eq 1 ] && grep -q "input error: The parameter file 'empty.prm' sets no entry" empty.log ||
  { fail "an empty parameter file"; cat empty.log; }
expect 0 set_twice "Warning: set_twice.prm: Mesh/Subdivisions is set on lines 6 and [0-9]+; the value on line [0-9]+ is used" \
  < <(printf 'subsection Mesh\n  set Subdivisions = 2, 2\nend\n')

# 6. Stale results: a 4-step growth run, then a 2-step one in the same
# directory: none of the first run's later files remain, run.json says
# completed and lists what the run wrote.
growth() {
  cat base.prm
  printf 'subsection Cracks\n  subsection Crack 1\n    set End point = -0.4, 0.1\n  end\nend\n'
  printf 'subsection Output\n  set Write vtu = true\nend\n'
  printf 'subsection Propagation\n  set Number of steps = %s\n  set Maximum advance = %s\n' "$1" "${2:-0.02}"
  printf '  subsection Growth law\n    subsection Paris\n      set C = 1e-3\n      set m = 3\n    end\n  end\nend\n'
}
growth 4 > four.prm && growth 2 > two.prm
rm -rf out
"$xcrack" four.prm > four.log 2>&1 || { fail "four steps: exit status $?"; tail -3 four.log; }
[ -f out/front_004.csv ] || fail "four steps: no front_004.csv"
"$xcrack" two.prm > two.log 2>&1 || { fail "two steps: exit status $?"; tail -3 two.log; }
for f in out/front_003.csv out/front_004.csv out/crack-004.vtu out/solution-004.pvtu; do
  [ -e "$f" ] && fail "two steps after four: the stale $f remains"
done
grep -q '"status": "completed"' out/run.json || fail "two steps: run.json does not say completed"
grep -q '"front_002.csv"' out/run.json || fail "two steps: run.json does not list front_002.csv"

# A run killed (SIGKILL) at a random moment after it started writing: every
# result file is its own, run.json says running, and the contrib/ reader
# warns that the run is incomplete.
# Short advances: 200 steps that stay inside the body (0.4 in all).
growth 200 0.002 > long.prm
sleep 1.1
touch marker
"$xcrack" long.prm > long.log 2>&1 &
pid=$!
for i in $(seq 1 600); do
  [ out/run.json -nt marker ] && grep -q '"status": "running"' out/run.json 2>/dev/null && break
  sleep 0.1
done
sleep "$(awk -v seed="$RANDOM" 'BEGIN { srand(seed); printf "%.2f", rand() * 3 }')"
kill -9 "$pid" 2> /dev/null || { fail "the long run ended before it could be killed"; tail -20 long.log; }
wait "$pid" 2> /dev/null
grep -q '"status": "running"' out/run.json || fail "killed: run.json does not say running"
stale="$(find out -maxdepth 1 -type f ! -newer marker)"
[ -z "$stale" ] || fail "killed: files of the earlier run remain: $stale"
python3 -c "import sys; sys.path.insert(0, '$contrib'); import xcrack_runs; xcrack_runs.run_files('out', r'front_.*\.csv')" \
  2> reader.log
grep -q "warning: the run in out is running" reader.log || { fail "killed: the reader does not warn"; cat reader.log; }

if [ "$failures" -eq 0 ]; then
  echo "cli/run_checks: all checks passed"
else
  echo "cli/run_checks: $failures check(s) failed"
  exit 1
fi
