#!/usr/bin/python3
"""Contact on the crack lips: accuracy and cost of the penalty formulation.

Runs the closed crack benchmark (prm/benchmarks/closed_crack_2d.prm: an
inclined centre crack under uniaxial compression, frictionless lips, the
exact closed-crack field on the boundary) and prints Markdown tables:

1. per mesh, for each pressure space (`lip points`, the naive one, and
   `cells`): K_I over the load's K scale p sqrt(pi a), the K_II error, the
   Newton steps, the closed fraction of the lips and the range of the
   contact pressure (exact: 0.75 everywhere);
2. against the penalty coefficient (pressure space `cells`, one mesh): the
   same, and the relative L2 error of the displacement.

With --friction, the frictional closed crack instead
(prm/benchmarks/closed_crack_friction_2d.prm, one mesh): K_II against the
closed form -p sqrt(pi a) cos(beta) (sin(beta) - mu cos(beta))_+ over the
friction coefficient mu (the lips stick from mu = tan(beta) = 0.577 on),
and against the tangential penalty coefficient on both sides of the
transition.

    contrib/build.sh release
    /usr/bin/python3 contrib/study_contact.py [--meshes 6] [--sweep-mesh 4]
    /usr/bin/python3 contrib/study_contact.py --friction [--sweep-mesh 4]

With --augmented, the frictionless closed crack (one mesh) for the penalty
and the augmented Lagrangian formulation against their coefficient, and
for Lagrange multipliers on the vital nodes: K's, Newton steps, the
largest interpenetration, the L2 error and the time of the solve (assembly
and linear solves). --friction gives the table over mu for Lagrange
multipliers too.
    /usr/bin/python3 contrib/study_contact.py --augmented [--sweep-mesh 4]
"""
import argparse
import math
import subprocess
import tempfile

from xcrack_runs import benchmark_prm, run_xcrack

k_scale = math.sqrt(math.pi)  # p sqrt(pi a), p = a = 1


beta = math.radians(30)


def k_ii_exact(mu):
    """K_II of the closed crack with Coulomb friction mu (p = a = 1)."""
    return -k_scale * math.cos(beta) * max(
        0., math.sin(beta) - mu * math.cos(beta)) + 0.


def run(work, meshes, space, coefficient, mu=None, tangential=1000,
        formulation="penalty"):
    scene = "closed_crack_2d" if mu is None else "closed_crack_friction_2d"
    friction = "" if mu is None else f"""
  set Friction coefficient = {mu}
  subsection Penalty
    set Tangential penalty coefficient = {tangential}
  end"""
    exact = "" if mu is None else f"""
subsection Exact solution
  set Friction coefficient = {mu}
end
subsection Fracture parameters
  set Reference K = 0; {k_ii_exact(mu):.10f}
end"""
    section, name = (("Augmented Lagrangian", "Augmentation")
                     if formulation == "augmented lagrangian"
                     else ("Penalty", "Penalty"))
    springs = f"""
  subsection {section}
    set Pressure space = {space}
    set {name} coefficient = {coefficient}
  end"""
    if formulation == "lagrange":
        springs = f"""
  subsection Lagrange
    set Multiplier space = {space}
  end"""
    return run_xcrack(benchmark_prm(scene, work, f"""subsection Contact
  set Formulation = {formulation}{friction}{springs}
end{exact}
subsection Mesh refinement
  set Number of meshes = {meshes}
end
"""), work)


def row(r):
    return (f"{int(r['dofs']):,} | {abs(float(r['K_I_1'])) / k_scale:.2e} | "
            f"{float(r['K_II_error']):.2e} | {r['newton_iterations']} | "
            f"{float(r['contact_closed']):.3f} | "
            f"{float(r['contact_pressure_min']):.3f} to "
            f"{float(r['contact_pressure_max']):.3f}")


def friction_row(r, mu):
    k_ii = 0.5 * (float(r["K_II_1"]) + float(r["K_II_2"]))
    k_i = max(abs(float(r["K_I_1"])), abs(float(r["K_I_2"])))
    return (f"{k_ii_exact(mu) / k_scale:.4f} | {k_ii / k_scale:.4f} | "
            f"{abs(k_ii - k_ii_exact(mu)) / k_scale:.1e} | "
            f"{k_i / k_scale:.1e} | "
            + (f"{float(r['contact_slipping']):.3f}" if mu > 0 else "-")
            + f" | {r['newton_iterations']} | {float(r['L2_error']):.2e}")


def friction_tables(work, mesh):
    """K_II against the friction coefficient and the tangential penalty."""
    header = ("K_II / p sqrt(pi a), exact | computed | error / p sqrt(pi a) | "
              "abs(K_I) / p sqrt(pi a) | slipping | Newton steps | L2 error |")
    print("| mu | " + header)
    print("|---" * 8 + "|")
    for mu in (0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.55, 0.6, 0.7, 1.0):
        r = run(work, mesh + 1, "cells", 1000, mu)[-1]
        print(f"| {mu} | {friction_row(r, mu)} |")
    print("\nLagrange multipliers (vital nodes):\n")
    print("| mu | " + header)
    print("|---" * 8 + "|")
    for mu in (0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.55, 0.6, 0.7, 1.0):
        r = run(work, mesh + 1, "vital nodes", 0, mu,
                formulation="lagrange")[-1]
        print(f"| {mu} | {friction_row(r, mu)} |")
    print()
    print("| mu | tangential coefficient | " + header)
    print("|---" * 9 + "|")
    for mu in (0.3, 0.7):
        for c in (1e1, 1e2, 1e3, 1e4, 1e5):
            r = run(work, mesh + 1, "cells", 1000, mu, c)[-1]
            print(f"| {mu} | {c:.0e} | {friction_row(r, mu)} |")


def augmented_table(work, mesh):
    """Penalty against augmented Lagrangian over the coefficient."""
    print("| formulation | coefficient | abs(K_I) / p sqrt(pi a) | K_II error | "
          "Newton steps | smallest gap | L2 error | t_assemble + t_solve (s) |")
    print("|---" * 8 + "|")
    for formulation in ("penalty", "augmented lagrangian"):
        for c in (1e1, 1e2, 1e3, 1e4, 1e5):
            try:
                r = run(work, mesh + 1, "cells", c,
                        formulation=formulation)[-1]
            except subprocess.CalledProcessError:
                print(f"| {formulation} | {c:.0e} | Newton loop did not "
                      "converge | | | | | |")
                continue
            print(f"| {formulation} | {c:.0e} | "
                  f"{abs(float(r['K_I_1'])) / k_scale:.2e} | "
                  f"{float(r['K_II_error']):.2e} | {r['newton_iterations']} | "
                  f"{float(r['contact_gap_min']):.1e} | "
                  f"{float(r['L2_error']):.3e} | "
                  f"{float(r['t_assemble']) + float(r['t_solve']):.2f} |")
    r = run(work, mesh + 1, "vital nodes", 0, formulation="lagrange")[-1]
    print(f"| lagrange (vital nodes) | - | "
          f"{abs(float(r['K_I_1'])) / k_scale:.2e} | "
          f"{float(r['K_II_error']):.2e} | {r['newton_iterations']} | "
          f"{float(r['contact_gap_min']):.1e} | "
          f"{float(r['L2_error']):.3e} | "
          f"{float(r['t_assemble']) + float(r['t_solve']):.2f} |")


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--meshes", type=int, default=6)
    parser.add_argument("--sweep-mesh", type=int, default=4,
                        help="the mesh (0-based) of the coefficient sweep")
    parser.add_argument("--friction", action="store_true",
                        help="the frictional closed crack's tables instead")
    parser.add_argument("--augmented", action="store_true",
                        help="penalty against augmented Lagrangian instead")
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="xcrack-contact-")
    if args.augmented:
        augmented_table(work, args.sweep_mesh)
        return
    if args.friction:
        friction_tables(work, args.sweep_mesh)
        return
    print("| space | DoFs | abs(K_I) / p sqrt(pi a) | K_II error | Newton "
          "steps | closed | contact pressure |")
    print("|---|---|---|---|---|---|---|")
    for space in ("lip points", "cells"):
        for r in run(work, args.meshes, space, 1000):
            print(f"| {space} | {row(r)} |")
    print()
    print("| coefficient | DoFs | abs(K_I) / p sqrt(pi a) | K_II error | "
          "Newton steps | closed | contact pressure | L2 error |")
    print("|---|---|---|---|---|---|---|---|")
    for c in (1e1, 1e2, 1e3, 1e4, 1e5, 1e6):
        r = run(work, args.sweep_mesh + 1, "cells", c)[-1]
        print(f"| {c:.0e} | {row(r)} | {float(r['L2_error']):.3e} |")


if __name__ == "__main__":
    main()
