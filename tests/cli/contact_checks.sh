#!/usr/bin/env bash
# Requirement (issue 40): the crack's VTU shows what is shut. On the closed
# crack with Coulomb friction (prm/benchmarks/closed_crack_friction_2d.prm,
# mu = 0.3, two meshes) every lip piece carries the contact pressure, the
# traction, the closed and slipping fractions, and every corner the gap
# and the slip; on slipping lips the traction obeys Coulomb's law (normal
# part = the pressure, tangential part = mu times it, against the slip),
# and the gap the penalty holds on closed lips is negative and small (less
# than a thousandth of the largest slip). Without contact the same compression
# makes the lips pass through each other: the gap is negative, and no
# contact field is written.
# A Newton loop that does not converge (the closed crack allowed one step
# where it needs two) stops with exit status 3, a message naming the load
# state, the residual and the statuses still changing, and the same reason
# in run.json.
#
#   contact_checks.sh XCRACK_EXECUTABLE SOURCE_DIRECTORY
set -u
xcrack="$1"
scene="$2/prm/benchmarks/closed_crack_friction_2d.prm"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
fail() { echo "FAILED: $*"; failures=$((failures + 1)); }

for formulation in penalty none; do
  friction=0.3
  [ "$formulation" = none ] && friction=0
  cat > "$formulation.prm" <<PRM
include $scene
set Output directory = out_$formulation
subsection Contact
  set Formulation = $formulation
  set Friction coefficient = $friction
end
subsection Mesh refinement
  set Number of meshes = 2
end
subsection Output
  set Write vtu = true
  set Timing summary = false
end
PRM
  "$xcrack" "$formulation.prm" > "$formulation.log" 2>&1 ||
    { fail "$formulation: exit status $?"; cat "$formulation.log"; }
done

python3 - out_penalty/crack-000.01.vtu out_none/crack-000.01.vtu <<'PY' || fail "crack VTU fields"
import math, re, sys

def arrays(name):
    text = open(name).read()
    found = {}
    m = re.search(r'<Points>\n<DataArray[^>]*>\n(.*?)</DataArray>', text, re.S)
    found["points"] = [[float(v) for v in line.split()]
                       for line in m.group(1).strip().split("\n")]
    for m in re.finditer(r'<DataArray[^>]*Name="([^"]+)"[^>]*>\n(.*?)</DataArray>', text, re.S):
        found[m.group(1)] = [[float(v) for v in line.split()]
                             for line in m.group(2).strip().split("\n")]
    return found

bad = 0
def check(condition, message):
    global bad
    if not condition:
        print(message)
        bad += 1

contact, none = arrays(sys.argv[1]), arrays(sys.argv[2])
for name in ("gap", "slip", "contact_pressure", "contact_gap", "contact_traction",
             "contact_closed", "contact_slipping"):
    check(name in contact, "penalty: no " + name)
for name in ("gap", "slip"):
    check(name in none, "none: no " + name)
check("contact_pressure" not in none, "none: contact fields without contact")
if bad == 0:
    points = contact["points"]
    # One line per cell: a lip piece is a segment of two corners.
    corners = contact["connectivity"]
    largest_slip = max(math.hypot(s[0], s[1]) for s in contact["slip"])
    # The penalty holds each cell's mean gap (contact_gap): closed lips
    # interpenetrate by p h / (1000 E) there. The corners' gap varies about
    # it as the jump does along a piece.
    held = [g[0] for g, closed, kind in zip(contact["contact_gap"],
            contact["contact_closed"], contact["kind"])
            if kind[0] == 0 and closed[0] == 1]
    check(len(held) > 0 and max(held) <= 0 and min(held) > -1e-3 * largest_slip,
          "penalty: closed lips' gaps from %g to %g" % (min(held), max(held)))
    slipping = 0
    for c, (p, t, closed, slides, kind) in enumerate(zip(
            contact["contact_pressure"], contact["contact_traction"],
            contact["contact_closed"], contact["contact_slipping"],
            contact["kind"])):
        if kind[0] != 0 or closed[0] != 1 or slides[0] != 1:
            continue
        slipping += 1
        a, b = int(corners[c][0]), int(corners[c][1])
        tangent = [points[b][i] - points[a][i] for i in (0, 1)]
        length = math.hypot(*tangent)
        tangent = [x / length for x in tangent]
        normal_part = abs(t[0] * tangent[1] - t[1] * tangent[0])
        tangential = t[0] * tangent[0] + t[1] * tangent[1]
        slip = contact["slip"][a]
        along = slip[0] * tangent[0] + slip[1] * tangent[1]
        check(abs(normal_part - p[0]) < 1e-9 * max(1, p[0]),
              "cell %d: normal traction %g, pressure %g" % (c, normal_part, p[0]))
        check(abs(abs(tangential) - 0.3 * p[0]) < 1e-9 * max(1, p[0]),
              "cell %d: tangential traction %g, mu p %g" % (c, tangential, 0.3 * p[0]))
        check(tangential * along < 0,
              "cell %d: friction does not oppose the slip" % c)
    check(slipping >= 8, "only %d slipping lip pieces" % slipping)
    check(min(g[0] for g in none["gap"]) < -0.1,
          "none: the lips should pass through each other (gap %g)" % min(g[0] for g in none["gap"]))
sys.exit(1 if bad else 0)
PY

cat > newton.prm <<PRM
include $2/prm/benchmarks/closed_crack_2d.prm
set Output directory = out_newton
subsection Mesh refinement
  set Number of meshes = 1
end
subsection Nonlinear solver
  set Maximum iterations = 1
end
PRM
"$xcrack" newton.prm > newton.log 2>&1
status=$?
[ "$status" -eq 3 ] || fail "Newton: exit status $status, expected 3"
regex="the Newton iterations of the maximum load of step 0 did not converge in 1 steps \(Nonlinear solver/Maximum iterations\): residual .* statuses still changing \(the first at"
grep -Eq "numerical failure: $regex" newton.log || { fail "Newton: message"; cat newton.log; }
grep -Eq "\"status\": \"failed\"" out_newton/run.json && grep -Eq "\"reason\": \"$regex" out_newton/run.json ||
  { fail "Newton: run.json"; cat out_newton/run.json; }

[ "$failures" -eq 0 ] || { echo "contact_checks: $failures check(s) failed"; exit 1; }
echo "contact_checks: all checks passed"
