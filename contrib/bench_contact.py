#!/usr/bin/python3
"""The cost of contact: the same solve with and without it.

Runs the closed crack (prm/benchmarks/closed_crack_2d.prm, six meshes) and
the closed penny (prm/benchmarks/closed_penny_3d.prm, four meshes) with
`Contact/Formulation = none`, `penalty`, `augmented lagrangian`,
`lagrange` and (2D) penalty and lagrange with friction mu = 0.3, on one
and two MPI ranks, several times (in 3D `lagrange` without DOF gathering
and with MUMPS, against the scene without contact on that space)
(doc/verification.md has the 3D frictional run: MUMPS LU, minutes), and
prints
per case the medians, on the last mesh, of the Newton steps, the assembly
and solve times (statistics.csv: t_assemble, t_solve, summed over the Newton
steps) and of the whole solve (every phase of that row), with the ratio of
the last to the same scene without contact measured in the same session.
Without contact the lips pass through each other: the solve is the linear
one the scene would be without the contact term.

    contrib/build.sh release
    /usr/bin/python3 contrib/bench_contact.py [--runs 3] [--scenes 2d 3d]
"""
import argparse
import statistics
import tempfile

from xcrack_runs import benchmark_prm, run_xcrack
scenes = {"2d": ("closed_crack_2d", 6), "3d": ("closed_penny_3d", 4)}
cases = {
    "none": "set Formulation = none",
    "penalty": "set Formulation = penalty",
    "augmented lagrangian": "set Formulation = augmented lagrangian",
    "lagrange": "set Formulation = lagrange",
    "penalty, mu = 0.3": "set Formulation = penalty\n"
                         "  set Friction coefficient = 0.3",
    "lagrange, mu = 0.3": "set Formulation = lagrange\n"
                          "  set Friction coefficient = 0.3",
}
# The 3D penny gathers its tip DoFs and solves by CG with AMG; Lagrange
# multipliers need neither (a saddle point: MUMPS), so in 3D they are
# measured against the same scene without contact on the same space.
ungathered = {"3d": ["none, ungathered, direct", "lagrange"]}
cases["none, ungathered, direct"] = "set Formulation = none"
order = {
    "2d": ["none", "penalty", "augmented lagrangian", "lagrange",
           "penalty, mu = 0.3", "lagrange, mu = 0.3"],
    "3d": ["none", "penalty", "augmented lagrangian",
           "none, ungathered, direct", "lagrange"],
}


def run(work, scene, case, ranks):
    name, meshes = scenes[scene]
    # Friction's unsymmetric systems and the multipliers' saddle points:
    # MUMPS (CG takes only SPD ones); multipliers without gathered DoFs.
    direct = "mu" in case or "lagrange" in case or "direct" in case
    solver = ("subsection Linear solver\n  set Type = direct\nend\n"
              if direct else "")
    if case in ungathered.get(scene, []):
        solver += "subsection Enrichment\n  set Gather tip DoFs = false\nend\n"
    last = run_xcrack(benchmark_prm(name, work, f"""subsection Contact
  {cases[case]}
end
subsection Mesh refinement
  set Number of meshes = {meshes}
end
{solver}"""), work, ranks)[-1]
    phases = sum(float(v) for k, v in last.items()
                 if k.startswith("t_") and v != "")
    return (int(last["dofs"]), int(last["newton_iterations"]),
            float(last["t_assemble"]), float(last["t_solve"]), phases)


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--scenes", nargs="+", default=["2d", "3d"])
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="xcrack-bench-contact-")
    print("| scene | ranks | contact | DoFs | Newton steps | t_assemble (s) | "
          "t_solve (s) | solve, all phases (s) | ratio to none |")
    print("|---" * 9 + "|")
    for scene in args.scenes:
        for ranks in (1, 2):
            base = None
            for case in order[scene]:
                runs = [run(work, scene, case, ranks) for _ in range(args.runs)]
                dofs, steps = runs[0][0], runs[0][1]
                assemble, solve, total = (
                    statistics.median(r[i] for r in runs) for i in (2, 3, 4))
                base = total if case.startswith("none") else base
                print(f"| {scenes[scene][0]} | {ranks} | {case} | {dofs:,} | "
                      f"{steps} | {assemble:.2f} | {solve:.2f} | {total:.2f} | "
                      f"{total / base:.2f} |", flush=True)


if __name__ == "__main__":
    main()
