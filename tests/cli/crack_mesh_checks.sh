#!/usr/bin/env bash
# Requirement (issue 42): a run started from the crack surface that the
# `crack mesh` level-set update wrote takes the step the earlier run took
# next, and such a file that does not fit the run is refused before any
# work:
# - tests/growth_crack_mesh_2d (the inclined centre crack, three kinked
#   steps on uniform meshes) writes crack_mesh-002.vtu; a run started from
#   it (`Shape = mesh`, `File name = .../crack_mesh-002.vtu`) solves on the
#   same meshes and finds the tips, K_I and K_II of the earlier run's step
#   2, then takes its step 3 (tips and K within 1e-9);
# - that 2D surface given to a 3D run, a 3D surface (a triangle, written
#   as the update writes) given to a 2D run, and a .vtu file that is not
#   such a surface: exit 1
#   with a message naming the entry, the file and what is wrong, and no
#   output directory.
#
#   crack_mesh_checks.sh XCRACK_EXECUTABLE TESTS_SOURCE_DIRECTORY
set -u
xcrack="$1"
tests="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
fail() { echo "FAILED: $*"; failures=$((failures + 1)); }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1

sed "s#@SOURCE_DIR@#$tests#; s#^set Output directory.*#set Output directory = first#" \
  "$tests/growth_crack_mesh_2d.prm.in" > first.prm
"$xcrack" first.prm > first.log 2>&1 || fail "the first run failed"
[ -f first/crack_mesh-002.vtu ] || fail "no first/crack_mesh-002.vtu"
grep -q '"crack_mesh-002.vtu"' first/run.json || fail "run.json does not list crack_mesh-002.vtu"

cat > again.prm <<PRM
include first.prm
set Output directory = again
subsection Cracks
  subsection Crack 1
    set Shape     = mesh
    set File name = first/crack_mesh-002.vtu
  end
end
subsection Propagation
  set Number of steps = 1
end
PRM
"$xcrack" again.prm > again.log 2>&1 || fail "the run started from the surface failed"

# same FILE_A FILE_B: the tips and their K's equal to 1e-9.
same() {
  python3 - "$1" "$2" <<'PYTHON'
import csv, sys
rows = [list(csv.DictReader(open(path))) for path in sys.argv[1:]]
columns = ("x", "y", "K_I", "K_II")
bad = [(c, a[c], b[c]) for a, b in zip(*rows) for c in columns
       if abs(float(a[c]) - float(b[c])) > 1e-9 * max(1, abs(float(a[c])))]
if len(rows[0]) != len(rows[1]) or not rows[0] or bad:
    print(f"  {sys.argv[1]} and {sys.argv[2]} differ: {bad[:4]}")
    sys.exit(1)
PYTHON
}
same first/front_002.csv again/front_000.03.csv ||
  fail "the run started from crack_mesh-002.vtu does not find step 2's tips and K"
same first/front_003.csv again/front_001.csv ||
  fail "the run started from crack_mesh-002.vtu does not take step 3"

# refused NAME DIMENSION FILE REGEX: a run of DIMENSION started from FILE
# exits 1 with a message matching REGEX and leaves no output directory.
refused() {
  local name="$1" dimension="$2" file="$3" regex="$4"
  if [ "$dimension" -eq 2 ]; then
    sed "s#^set Output directory.*#set Output directory = out_$name#" first.prm > "$name.prm"
  else
    { sed "s#@SOURCE_DIR@#$tests#" "$tests/growth_crack_mesh_3d.prm.in"
      echo "set Output directory = out_$name"; } > "$name.prm"
  fi
  printf 'subsection Cracks\n  subsection Crack 1\n    set Shape = mesh\n    set File name = %s\n  end\nend\n' \
    "$file" >> "$name.prm"
  "$xcrack" "$name.prm" > "$name.log" 2>&1
  local status=$?
  [ "$status" -eq 1 ] || fail "$name: exit status $status, not 1"
  grep -q -- "$regex" "$name.log" || { fail "$name: no message matching '$regex'"; cat "$name.log"; }
  [ ! -e "out_$name" ] || fail "$name: the refused run created out_$name"
}
refused two_in_three 3 "$work/first/crack_mesh-002.vtu" \
  "Crack 1/File name = .*crack_mesh-002.vtu: a surface of segments (a 2D crack) cannot start a 3D run"
# A 3D surface as the update writes it: one triangle and its front.
cat > triangle.vtu <<'VTU'
<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1">
<UnstructuredGrid>
<Piece NumberOfPoints="5" NumberOfCells="2">
<Points>
<DataArray type="Float64" Name="Points" NumberOfComponents="3" format="ascii">
0 0 0 1 0 0 0 1 0 1 0 0 0 1 0
</DataArray>
</Points>
<Cells>
<DataArray type="Int64" Name="connectivity" format="ascii">0 1 2 3 4</DataArray>
<DataArray type="Int64" Name="offsets" format="ascii">3 5</DataArray>
<DataArray type="UInt8" Name="types" format="ascii">5 4</DataArray>
</Cells>
<CellData>
<DataArray type="Int32" Name="step" format="ascii">0 -1</DataArray>
<DataArray type="Float64" Name="normal" NumberOfComponents="3" format="ascii">0 0 1 0 0 0</DataArray>
</CellData>
<PointData>
<DataArray type="Float64" Name="e1" NumberOfComponents="3" format="ascii">
0 0 0 0 0 0 0 0 0 0.7071 0.7071 0 0.7071 0.7071 0
</DataArray>
</PointData>
</Piece>
</UnstructuredGrid>
</VTKFile>
VTU
refused three_in_two 2 "$work/triangle.vtu" \
  "triangle.vtu: a surface of triangles (a 3D crack) cannot start a 2D run"
printf '<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid"></VTKFile>\n' > other.vtu
refused not_ours 2 "$work/other.vtu" \
  "other.vtu: not a crack surface written by xcrack's .crack mesh. level-set update"

if [ "$failures" -eq 0 ]; then
  echo "cli/crack_mesh_checks: all checks passed"
else
  echo "cli/crack_mesh_checks: $failures check(s) failed"
  exit 1
fi
