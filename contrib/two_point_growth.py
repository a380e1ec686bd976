#!/usr/bin/env python3
"""The engineering procedure's growth of a semi-elliptical surface crack
(BS 7910, API 579): the crack stays a semi-ellipse with two degrees of
freedom, the depth a and the half-length c, each grown by the Paris law
with Newman and Raju's K at its point (da/dN = C dK(90 deg)^m, dc/dN =
C dK(0)^m), integrated in N by classical Runge-Kutta. Compared with a
surface-crack run of xcrack (free front shape): a(N) and c(N) side by side
at the run's steps (issue 44 §2).

  /usr/bin/python3 contrib/two_point_growth.py output/surface_crack_3d \\
      --t 2 --b 4 --C 1e-3 --m 3 [--stress 1] [--figure a_c.png]

The run's depth is its front's deepest point; its half-length half the
distance between the front's ends on the face y = 0; its cycles those of
statistics.csv. The procedure starts from the run's a and c at step 0.
"""
import argparse
import csv
import glob
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import newman_raju  # noqa: E402


def run_history(directory):
    """(N, a, c) of each step of a growth run."""
    cycles = {}
    with open(os.path.join(directory, "statistics.csv")) as f:
        for row in csv.DictReader(f):
            cycles[int(row["step"])] = float(row["cycles"])
    history = []
    for step in sorted(cycles):
        files = sorted(glob.glob(os.path.join(directory,
                                              f"front_{step:03d}*.csv")))
        if not files:
            continue
        rows = list(csv.DictReader(open(files[-1])))
        if len(set(r["front"] for r in rows)) != 1:
            break  # broken through: no longer a semi-ellipse
        depth = max(float(r["y"]) for r in rows)
        half = 0.5 * abs(float(rows[-1]["x"]) - float(rows[0]["x"]))
        history.append((cycles[step], depth, half))
    return history


def rates(a, c, t, b, C, m, stress):
    """(da/dN, dc/dN) of the two-point procedure (tension)."""
    k_a = newman_raju.k_tension(a, c, t, b, math.pi / 2, stress)
    k_c = newman_raju.k_tension(a, c, t, b, 0.0, stress)
    return C * k_a ** m, C * k_c ** m


def integrate(a, c, n_end, t, b, C, m, stress, steps=20000):
    """The procedure's (N, a, c) from 0 to n_end (RK4)."""
    h = n_end / steps
    path = [(0.0, a, c)]
    for i in range(steps):
        k1 = rates(a, c, t, b, C, m, stress)
        k2 = rates(a + 0.5 * h * k1[0], c + 0.5 * h * k1[1], t, b, C, m,
                   stress)
        k3 = rates(a + 0.5 * h * k2[0], c + 0.5 * h * k2[1], t, b, C, m,
                   stress)
        k4 = rates(a + h * k3[0], c + h * k3[1], t, b, C, m, stress)
        a += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        c += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
        path.append(((i + 1) * h, a, c))
    return path


def at(path, n):
    """(a, c) of the procedure at N = n (linear between its steps)."""
    for (n0, a0, c0), (n1, a1, c1) in zip(path, path[1:]):
        if n0 <= n <= n1:
            w = (n - n0) / (n1 - n0) if n1 > n0 else 0
            return a0 + w * (a1 - a0), c0 + w * (c1 - c0)
    return path[-1][1], path[-1][2]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run", help="the output directory of a growth run")
    parser.add_argument("--t", type=float, required=True, help="thickness")
    parser.add_argument("--b", type=float, required=True,
                        help="half-width of the plate")
    parser.add_argument("--C", type=float, required=True)
    parser.add_argument("--m", type=float, required=True)
    parser.add_argument("--stress", type=float, default=1.0,
                        help="stress range (tension)")
    parser.add_argument("--figure", help="draw a(N), c(N) into this file")
    args = parser.parse_args()
    history = run_history(args.run)
    n0, a0, c0 = history[0]
    path = integrate(a0, c0, history[-1][0], args.t, args.b, args.C, args.m,
                     args.stress)
    print("| step | N | a (xcrack) | a (procedure) | a diff | c (xcrack) | "
          "c (procedure) | c diff |")
    print("|---|---|---|---|---|---|---|---|")
    for step, (n, a, c) in enumerate(history):
        a_p, c_p = at(path, n)
        print(f"| {step} | {n:.2f} | {a:.4f} | {a_p:.4f} | "
              f"{100 * (a / a_p - 1):+.1f} % | {c:.4f} | {c_p:.4f} | "
              f"{100 * (c / c_p - 1):+.1f} % |")
    # Cycles to the run's last depth by the procedure.
    a_last = history[-1][1]
    n_reach = next((n for n, a, c in path if a >= a_last), None)
    if n_reach is not None:
        print(f"\nThe procedure reaches the run's last depth {a_last:.4f} "
              f"at N = {n_reach:.2f} (the run: {history[-1][0]:.2f}).")
    if args.figure:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4))
        ax.plot([p[0] for p in path], [p[1] for p in path], "C0-",
                label="a, two-point procedure")
        ax.plot([p[0] for p in path], [p[2] for p in path], "C1-",
                label="c, two-point procedure")
        ax.plot([h[0] for h in history], [h[1] for h in history], "C0o",
                label="a, xcrack")
        ax.plot([h[0] for h in history], [h[2] for h in history], "C1s",
                label="c, xcrack")
        ax.set_xlabel("N")
        ax.set_ylabel("length")
        ax.legend()
        fig.tight_layout()
        fig.savefig(args.figure, dpi=120)


if __name__ == "__main__":
    main()
