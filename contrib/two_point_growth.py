#!/usr/bin/env python3
"""The engineering procedure's growth of a semi-elliptical surface crack
(BS 7910, API 579): the crack stays a semi-ellipse with two degrees of
freedom, the depth a and the half-length c, each grown by the Paris law
with Newman and Raju's K at its point (da/dN = C dK(90 deg)^m, dc/dN =
C dK(0)^m), integrated in N by classical Runge-Kutta. Compared with a
surface-crack run of xcrack (free front shape) at the run's steps
(issue 44 §2): a and c at equal N; c and N at equal depth; N at equal
depth once more with the procedure's K's scaled by the run's own ratios to
Newman and Raju (what then remains is not the level of K); how far the
front departs from its ellipse and its K against Newman and Raju's. The
figure draws a(N), c(N) and a/c against a/t.

  /usr/bin/python3 contrib/two_point_growth.py output/surface_crack_3d \\
      --t 2 --b 4 --C 1e-3 --m 3 [--stress 1] [--depth 1.6] \\
      [--figure a_c.png]

The run's depth is its front's y halfway between its ends (a quadratic
through the three front points nearest); its half-length half the
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


def run_history(directory, depth_limit=None):
    """(N, a, c, rows) of each step of a growth run, up to the depth
    @p depth_limit if given; rows are the step's front points."""
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
        depth = at_middle(rows, "y")
        half = 0.5 * abs(float(rows[-1]["x"]) - float(rows[0]["x"]))
        if depth_limit is not None and depth > depth_limit + 1e-9:
            break
        history.append((cycles[step], depth, half, rows))
    return history


def at_middle(rows, column):
    """A column of the front file at the middle of the front, where x lies
    halfway between its ends: the quadratic in x through the three front
    points nearest it (a chord between two points would cut below a
    front that bends, by up to 2 % of the depth here, and the sampling of
    the points would then move the depth from step to step)."""
    x0 = 0.5 * (float(rows[0]["x"]) + float(rows[-1]["x"]))
    near = sorted(rows, key=lambda r: abs(float(r["x"]) - x0))[:3]
    xs = [float(r["x"]) for r in near]
    value = 0.0
    for i, r in enumerate(near):
        weight = 1.0
        for j in range(3):
            if j != i:
                weight *= (x0 - xs[j]) / (xs[i] - xs[j])
        value += weight * float(r[column])
    return value


def front_against_ellipse(rows, a, c, t, b):
    """How far a front departs from the semi-ellipse through its depth a
    and its ends (half-length c): the largest abs(r / r_ellipse - 1) over
    its points, and K_I against Newman and Raju's for that ellipse at the
    deepest point and at the two ends (relative differences)."""
    x0 = 0.5 * (float(rows[0]["x"]) + float(rows[-1]["x"]))
    shape = 0.0
    for r in rows:
        x, y = float(r["x"]) - x0, float(r["y"])
        shape = max(shape, abs(math.hypot(x / c, y / a) - 1))
    k_deep = at_middle(rows, "K_I") / newman_raju.k_tension(
        a, c, t, b, math.pi / 2) - 1
    k_face = [float(r["K_I"]) / newman_raju.k_tension(a, c, t, b, 0.0) - 1
              for r in (rows[0], rows[-1])]
    return shape, k_deep, k_face


def rates(a, c, t, b, C, m, stress, scale=None):
    """(da/dN, dc/dN) of the two-point procedure (tension). @p scale, if
    given, maps a to the factors (deepest, face) that multiply Newman and
    Raju's K's."""
    k_a = newman_raju.k_tension(a, c, t, b, math.pi / 2, stress)
    k_c = newman_raju.k_tension(a, c, t, b, 0.0, stress)
    if scale:
        f_a, f_c = scale(a)
        k_a, k_c = k_a * f_a, k_c * f_c
    return C * k_a ** m, C * k_c ** m


def integrate(a, c, n_end, t, b, C, m, stress, steps=20000, scale=None):
    """The procedure's (N, a, c) from 0 to n_end (RK4)."""
    h = n_end / steps
    path = [(0.0, a, c)]

    def f(a, c):
        return rates(a, c, t, b, C, m, stress, scale)
    for i in range(steps):
        k1 = f(a, c)
        k2 = f(a + 0.5 * h * k1[0], c + 0.5 * h * k1[1])
        k3 = f(a + 0.5 * h * k2[0], c + 0.5 * h * k2[1])
        k4 = f(a + h * k3[0], c + h * k3[1])
        a += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        c += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
        if a >= 0.95 * t or c >= 0.95 * b:
            break  # beyond the equations' range
        path.append(((i + 1) * h, a, c))
    return path


def at(path, n):
    """(a, c) of the procedure at N = n (linear between its steps)."""
    for (n0, a0, c0), (n1, a1, c1) in zip(path, path[1:]):
        if n0 <= n <= n1:
            w = (n - n0) / (n1 - n0) if n1 > n0 else 0
            return a0 + w * (a1 - a0), c0 + w * (c1 - c0)
    return None  # beyond the procedure's range (a = 0.95 t)


def at_depth(path, a):
    """(N, c) of the procedure where its depth is @p a."""
    for (n0, a0, c0), (n1, a1, c1) in zip(path, path[1:]):
        if a0 <= a <= a1:
            w = (a - a0) / (a1 - a0) if a1 > a0 else 0
            return n0 + w * (n1 - n0), c0 + w * (c1 - c0)
    return path[-1][0], path[-1][2]


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
    parser.add_argument("--depth", type=float,
                        help="compare up to this depth (a/t = 0.8: 0.8 t)")
    parser.add_argument("--figure", help="draw a(N), c(N) into this file")
    args = parser.parse_args()
    history = run_history(args.run, args.depth)
    n0, a0, c0, _ = history[0]
    # Twice the run's cycles, so that the procedure reaches the run's
    # depths even where it grows more slowly.
    path = integrate(a0, c0, 2 * history[-1][0], args.t, args.b, args.C,
                     args.m, args.stress)
    # The procedure with Newman and Raju's K's scaled by the run's own
    # ratios to them (at its deepest point and face points, linear in a
    # between the run's steps): what is left between it and the run is
    # not the level of K but the front's shape and the integration.
    checks = [front_against_ellipse(rows, a, c, args.t, args.b)
              for n, a, c, rows in history]
    ratios = [(a, 1 + k_deep, 1 + sum(k_face) / len(k_face))
              for (n, a, c, rows), (_, k_deep, k_face) in zip(history, checks)]

    def scale(a):
        if a <= ratios[0][0]:
            return ratios[0][1:]
        for (a0, d0, f0), (a1, d1, f1) in zip(ratios, ratios[1:]):
            if a0 <= a <= a1 and a1 > a0:
                w = (a - a0) / (a1 - a0)
                return d0 + w * (d1 - d0), f0 + w * (f1 - f0)
        return ratios[-1][1:]
    scaled = integrate(a0, c0, 2 * history[-1][0], args.t, args.b, args.C,
                       args.m, args.stress, scale=scale)
    # Per step: a and c against the procedure's at the same N, and c and
    # N at the same depth a (the shape's path, which a bias of K along the
    # whole front does not move); the front against the ellipse through
    # its a and c (shape), and its K_I at the deepest point and the face
    # points against Newman and Raju's for that ellipse, which say why the
    # two part where they do.
    print("| step | N | a/t | a/c | a vs procedure, equal N | "
          "c vs procedure, equal N | c vs procedure, equal a | "
          "N vs procedure, equal a | N vs procedure with the run's K, "
          "equal a | off the ellipse | K_I deepest vs N-R | "
          "K_I face vs N-R |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for step, ((n, a, c, rows), (shape, k_deep, k_face)) in enumerate(
            zip(history, checks)):
        procedure = at(path, n)
        n_a, c_a = at_depth(path, a)
        faces = ", ".join(f"{100 * k:+.1f} %" for k in k_face)
        n_diff = f"{100 * (n / n_a - 1):+.1f} %" if n_a > 0 else ""
        n_s, _ = at_depth(scaled, a)
        n_scaled = f"{100 * (n / n_s - 1):+.1f} %" if n_s > 0 else ""
        print(f"| {step} | {n:.2f} | {a / args.t:.3f} | {a / c:.3f} | "
              + (f"{100 * (a / procedure[0] - 1):+.1f} % | "
                 f"{100 * (c / procedure[1] - 1):+.1f} % " if procedure
                 else "past 0.95 t | past 0.95 t ") +
              f"| {100 * (c / c_a - 1):+.1f} % | {n_diff} | {n_scaled} | "
              f"{100 * shape:.1f} % | {100 * k_deep:+.1f} % | {faces} |")
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
        n_last = history[-1][0]
        shown = [p for p in path if p[0] <= 1.05 * n_last]
        fig, (ax, shape) = plt.subplots(1, 2, figsize=(10, 4))
        ax.plot([p[0] for p in shown], [p[1] for p in shown], "C0-",
                label="a, two-point procedure")
        ax.plot([p[0] for p in shown], [p[2] for p in shown], "C1-",
                label="c, two-point procedure")
        ax.plot([h[0] for h in history], [h[1] for h in history], "C0o",
                label="a, xcrack")
        ax.plot([h[0] for h in history], [h[2] for h in history], "C1s",
                label="c, xcrack")
        ax.set_title(f"a/c = {a0 / c0:.2f}, a/t = {a0 / args.t:.2f} at N = 0")
        ax.set_xlabel("N")
        ax.set_ylabel("length")
        ax.legend()
        # The shape's path: a/c against a/t.
        a_end = history[-1][1]
        shape.plot([p[1] / args.t for p in path if p[1] <= 1.02 * a_end],
                   [p[1] / p[2] for p in path if p[1] <= 1.02 * a_end],
                   "k-", label="two-point procedure")
        shape.plot([h[1] / args.t for h in history],
                   [h[1] / h[2] for h in history], "ko", label="xcrack")
        shape.set_xlabel("a/t")
        shape.set_ylabel("a/c")
        shape.legend()
        fig.tight_layout()
        fig.savefig(args.figure, dpi=120)


if __name__ == "__main__":
    main()
