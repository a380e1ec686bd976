#!/usr/bin/env bash
# Requirement: on bad input xcrack exits with status 1 before any work, with a
# message that names the culprit (and the line of the parameter file where
# ParameterHandler knows it), and leaves the results of an earlier run in the
# output directory untouched. A valid run writes its VTU and CSV files.
# --print-parameters lists every entry with its documentation.
#
#   input_errors.sh XCRACK_EXECUTABLE THIS_DIRECTORY
set -u
xcrack="$1"
here="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0

fail() { echo "FAILED: $*"; failures=$((failures + 1)); }

# expect_error NAME EXPECTED_REGEX < prm text
expect_error() {
  local name="$1" regex="$2"
  cat > "$name.prm"
  "$xcrack" "$name.prm" > "$name.log" 2>&1
  local status=$?
  [ "$status" -eq 1 ] || fail "$name: exit status $status, expected 1"
  grep -Ezq -- "$regex" "$name.log" || { fail "$name: message does not match '$regex':"; cat "$name.log"; }
}

# An earlier run's results, which no failed start may touch.
cp "$here/valid.prm" valid.prm
"$xcrack" valid.prm > valid.log 2>&1 || { fail "valid run: exit status $?"; cat valid.log; }
for f in out/statistics.csv out/solution.pvd out/solution-000.00.pvtu out/solution-000.01.pvtu out/parameters.prm; do
  [ -s "$f" ] || fail "valid run did not write $f"
done
grep -q "^step,mesh,cycles,cells,dofs," out/statistics.csv || fail "statistics.csv header"
[ "$(wc -l < out/statistics.csv)" -eq 3 ] || fail "statistics.csv should have a header and 2 rows"
snapshot="$(cd out && ls -l --time-style=full-iso && md5sum ./*)"

expect_error unknown_entry "Line <5> of file <unknown_entry.prm>: No entry with name <Subdivision>" \
  < <(sed 's/set Subdivisions = 2, 2/set Subdivision = 2, 2/' valid.prm)
expect_error wrong_type "Line <12>.*two.*Number of meshes" \
  < <(sed 's/set Number of meshes = 2/set Number of meshes = two/' valid.prm)
expect_error missing_mesh "Mesh/File name = .*/missing.msh: cannot open" \
  < <(sed 's/set Subdivisions = 2, 2/set Type = file\n  set File name = missing.msh/' valid.prm)
expect_error both_kinds_on_one_boundary "boundary id 0 has both a full displacement and a traction" \
  < <(sed 's/set Neumann   = 1: 1; 0/set Neumann = 0: 1; 0/' valid.prm)
expect_error unknown_boundary "Neumann: boundary id 9 does not exist on the mesh" \
  < <(sed 's/set Neumann   = 1: 1; 0/set Neumann = 9: 1; 0/' valid.prm)
expect_error no_support "Pinned points are empty" < <(printf 'set Dimension = 2\n')
"$xcrack" does_not_exist.prm > nofile.log 2>&1
[ $? -eq 1 ] && grep -q "Cannot open the parameter file 'does_not_exist.prm'" nofile.log ||
  fail "missing parameter file"

# Two cracks on an 8 x 8 mesh (both resolved by the first mesh).
two_cracks() {
  sed 's/set Subdivisions = 2, 2/set Subdivisions = 8, 8/' valid.prm
  printf 'subsection Cracks\n  set Number of cracks = 2\n'
  printf '  subsection Crack 1\n    set Start point = 0.1, 0.45\n    set End point = 0.4, 0.45\n  end\n'
  printf '  subsection Crack 2\n    set Start point = %s\n    set End point = %s\n  end\nend\n' "$1" "$2"
}
expect_error cracks_too_close "Cracks/Crack 1 and Crack 2: their enriched zones meet near" \
  < <(two_cracks "0.6, 0.45" "0.9, 0.45")

# The growth model: a crack that grows (valid.prm plus these lines).
growth() {
  cat valid.prm
  printf 'subsection Cracks\n  set Number of cracks = 1\n  subsection Crack 1\n'
  printf '    set Start point = -1, 0.45\n    set End point = 0.4, 0.45\n    set Tips = end\n  end\nend\n'
  printf 'subsection Propagation\n  set Number of steps = 3\n  set Maximum advance = %s\n' "${1:-0.1}"
  printf '  set Load ratio = %s\n' "${2:-0}"
  printf '  subsection Growth law\n    set Model name = %s\n' "${3:-paris}"
  printf '    subsection Paris\n      set C = %s\n      set m = %s\n    end\n  end\nend\n' "${4:-1e-3}" "${5:-3}"
}
expect_error growth_no_advance "Propagation/Maximum advance = 0: must be positive" < <(growth 0)
expect_error growth_ratio "Propagation/Load ratio = 1: must be below 1" < <(growth 0.1 1)
expect_error growth_c "Propagation/Growth law/Paris/C = -1: must be positive" < <(growth 0.1 0 paris -1)
expect_error growth_m "Propagation/Growth law/Paris/m = 0: must be positive" < <(growth 0.1 0 paris 1e-3 0)
# The upwind level-set update: its grid needs a spacing, its band the advance.
upwind() {
  growth 0.1
  printf 'subsection Propagation\n  subsection Level set update\n    set Model name = upwind\n'
  printf '    subsection Upwind\n      set %s\n    end\n  end\nend\n' "$1"
}
expect_error upwind_spacing "Propagation/Level set update/Upwind/Grid spacing = 0: must be positive" \
  < <(upwind "Grid spacing = 0")
expect_error upwind_band "Propagation/Level set update/Upwind/Band radius = 0.05 is narrower than Propagation/Maximum advance = 0.1" \
  < <(upwind "Band radius = 0.05")
# The simplex update: its band too.
expect_error simplex_band "Propagation/Level set update/Simplex/Band radius = 0.05 is narrower than Propagation/Maximum advance = 0.1" \
  < <(upwind "Band radius = 0.05" | sed 's/upwind/simplex/; s/Upwind/Simplex/')
expect_error growth_forman "Model name = forman needs the fracture toughness: set Material/Fracture toughness" \
  < <(growth 0.1 0 forman)
expect_error growth_failure_check "'fracture toughness' needs Material/Fracture toughness" \
  < <(growth; printf 'subsection Termination criteria\n  set Termination criteria = fracture toughness\nend\n')
# The minimum of the load cycle: given twice, or loads on supports it cannot
# change, or on a boundary the mesh lacks.
minimum() {
  growth 0.1 "${1:-0}"
  printf 'subsection Propagation\n  subsection Minimum loads\n    set %s\n  end\nend\n' "$2"
}
expect_error minimum_twice "Load ratio = 0.5 and Propagation/Minimum loads both give the minimum" \
  < <(minimum 0.5 "Neumann = 1: 0.5; 0")
expect_error minimum_new_support "Minimum loads/Dirichlet: boundary 2 is not a Dirichlet boundary of Boundary conditions/Dirichlet" \
  < <(minimum 0 "Dirichlet = 2: 0; 0")
expect_error minimum_unknown_boundary "Minimum loads/Neumann: boundary id 9 does not exist on the mesh" \
  < <(minimum 0 "Neumann = 9: 1; 0")
expect_error minimum_both_kinds "Minimum loads/Neumann: boundary id 0 has a full displacement" \
  < <(minimum 0 "Neumann = 0: 1; 0")
# Contact: a coefficient that is not positive; lips that do not exist.
expect_error contact_penalty "Contact/Penalty/Penalty coefficient = -1: must be positive" \
  < <(growth; printf 'subsection Contact\n  set Formulation = penalty\n  subsection Penalty\n    set Penalty coefficient = -1\n  end\nend\n')
# The augmented Lagrangian's coefficient; a formulation that does not exist.
expect_error augmented_coefficient "Contact/Augmented Lagrangian/Augmentation coefficient = 0: must be positive" \
  < <(growth; printf 'subsection Contact\n  set Formulation = augmented lagrangian\n  subsection Augmented Lagrangian\n    set Augmentation coefficient = 0\n  end\nend\n')
expect_error contact_unknown "mortar.*for the entry named.*Formulation" \
  < <(growth; printf 'subsection Contact\n  set Formulation = mortar\nend\n')
# Lagrange multipliers: a saddle point that only the direct solver takes, a
# multiplier space that gathered tip DoFs cannot meet, a space that does not
# exist.
expect_error lagrange_cg "Linear solver/Type = cg amg cannot solve the saddle-point systems of Contact/Formulation = lagrange.*use Type = direct" \
  < <(growth; printf 'subsection Contact\n  set Formulation = lagrange\nend\nsubsection Linear solver\n  set Type = cg amg\nend\n')
expect_error lagrange_gathering "Contact/Formulation = lagrange with Enrichment/Gather tip DoFs = true" \
  < <(growth; printf 'subsection Contact\n  set Formulation = lagrange\nend\nsubsection Enrichment\n  set Tip enrichment = geometric\n  set Enrichment radius = 0.2\n  set Gather tip DoFs = true\nend\n')
expect_error lagrange_space "nodes.*for the entry named.*Multiplier space" \
  < <(growth; printf 'subsection Contact\n  set Formulation = lagrange\n  subsection Lagrange\n    set Multiplier space = nodes\n  end\nend\n')
# Friction: a negative coefficient; friction on lips that do not touch; a
# tangential penalty that is not positive; a solver for symmetric systems.
expect_error friction_negative "Contact/Friction coefficient = -0.1: must be zero \\(frictionless\\) or positive" \
  < <(growth; printf 'subsection Contact\n  set Formulation = penalty\n  set Friction coefficient = -0.1\nend\n')
expect_error friction_without_contact "Contact/Friction coefficient = 0.3 with Contact/Formulation = none" \
  < <(growth; printf 'subsection Contact\n  set Friction coefficient = 0.3\nend\n')
expect_error friction_tangential "Contact/Penalty/Tangential penalty coefficient = 0: must be positive" \
  < <(growth; printf 'subsection Contact\n  set Formulation = penalty\n  set Friction coefficient = 0.3\n  subsection Penalty\n    set Tangential penalty coefficient = 0\n  end\nend\n')
expect_error friction_cg "Linear solver/Type = cg amg cannot solve the unsymmetric systems of this scene .*use Type = direct or gmres amg" \
  < <(growth; printf 'subsection Contact\n  set Formulation = penalty\n  set Friction coefficient = 0.3\nend\nsubsection Linear solver\n  set Type = cg amg\nend\n')
expect_error contact_no_crack "Contact/Formulation = penalty but there is no crack" \
  < <(cat valid.prm; printf 'subsection Contact\n  set Formulation = penalty\nend\n')
expect_error growth_no_crack "Propagation/Number of steps > 0 but there is no crack" \
  < <(cat valid.prm; printf 'subsection Propagation\n  set Number of steps = 2\n  set Maximum advance = 0.1\nend\n')
expect_error growth_coarsening "Mesh refinement/Front/Coarsening band = 3: must exceed twice the Front band" \
  < <(cat valid.prm; printf 'subsection Mesh refinement\n  set Strategy = front\n  subsection Front\n    set Front band = 2\n    set Coarsening band = 3\n  end\nend\n')
"$xcrack" --resume out > resume.log 2>&1
[ $? -eq 1 ] && grep -q "no checkpoint there" resume.log ||
  { fail "--resume of a directory without a checkpoint"; cat resume.log; }

[ "$snapshot" = "$(cd out && ls -l --time-style=full-iso && md5sum ./*)" ] ||
  fail "a failed start changed the earlier results in out/"

"$xcrack" --print-parameters > params.log 2>&1 || fail "--print-parameters: exit status $?"
for entry in "Dimension" "Output directory" "Young's modulus" "Dirichlet components" "Number of meshes" \
  "Maximum advance" "Termination criteria"; do
  grep -q "set $entry" params.log || fail "--print-parameters does not list '$entry'"
done

if [ "$failures" -eq 0 ]; then
  echo "cli/input_errors: all checks passed"
else
  echo "cli/input_errors: $failures check(s) failed"
  exit 1
fi
