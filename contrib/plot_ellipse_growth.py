#!/usr/bin/python3
"""The embedded elliptical crack of prm/benchmarks/paris_ellipse_3d.prm
growing towards a circle, against the two-point model.

    build/release/xcrack prm/benchmarks/paris_ellipse_3d.prm
    /usr/bin/python3 contrib/plot_ellipse_growth.py output/paris_ellipse_3d

Each step's front (front_<step>.csv, the crack in the plane z = 0, axes
along x and y) gives its semi-axes at the ends of the axes (a parabola
through the three points nearest to each end) and its misfit to the
ellipse with those axes. The two-point model keeps the crack an
ellipse and grows each semi-axis at the Paris rate of Irwin's K at its
end, K = s sqrt(pi b) / E(k) (sin^2 phi + (b/a)^2 cos^2 phi)^(1/4), from
the same initial axes. Prints the table of the steps and writes
doc/figures/ellipse_growth.png (or --figure): b/a against a, and a and b
against the cycles N.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_growth import fronts, steps  # noqa: E402
from xcrack_runs import top  # noqa: E402


def fit(rows):
    """Semi-axes (a, b) of the front, measured at the ends of the axes, and
    the largest relative misfit of the points to the centred ellipse with
    those axes. Each end: a parabola x = a + k y^2 (y = b + k x^2) through
    the three points nearest to that end, least squares; a and b are the
    means over the two ends."""
    points = [(float(r["x"]), float(r["y"])) for r in rows]

    def end(u, v):
        """The end along +u of the points (u, v): u at v = 0."""
        near = sorted(points, key=lambda p: -u(p))[:3]
        n = len(near)
        s1 = sum(v(p) ** 2 for p in near)
        s2 = sum(v(p) ** 4 for p in near)
        t0 = sum(u(p) for p in near)
        t1 = sum(u(p) * v(p) ** 2 for p in near)
        return (t0 * s2 - t1 * s1) / (n * s2 - s1 * s1)

    a = (end(lambda p: p[0], lambda p: p[1]) +
         end(lambda p: -p[0], lambda p: p[1])) / 2
    b = (end(lambda p: p[1], lambda p: p[0]) +
         end(lambda p: -p[1], lambda p: p[0])) / 2
    misfit = max(abs(math.hypot(x / a, y / b) - 1) for x, y in points)
    return a, b, misfit


def ellipe(m):
    """Complete elliptic integral of the second kind E(m), m = k^2, by the
    arithmetic-geometric mean: E = K (1 - sum 2^(n-1) c_n^2)."""
    a, g = 1.0, math.sqrt(1 - m)
    total, power = m / 2, 0.5  # n = 0: c_0^2 = m
    while abs(a - g) > 1e-15 * a:
        c = (a - g) / 2
        a, g = (a + g) / 2, math.sqrt(a * g)
        power *= 2
        total += power * c * c
    return math.pi / (2 * a) * (1 - total)


def two_point(a, b, c, m, n_end, stress=1.0, db=1e-4):
    """(N, a, b) of the two-point model up to N = n_end (b/a <= 1)."""
    n, path = 0.0, [(0.0, a, b)]
    while n < n_end:
        small, large = min(a, b), max(a, b)
        factor = stress * math.sqrt(math.pi * small) / ellipe(
            1 - (small / large) ** 2)
        k_minor = factor  # at the ends of the minor axis
        k_major = factor * math.sqrt(small / large)
        k_b, k_a = (k_minor, k_major) if b <= a else (k_major, k_minor)
        dn = db / (c * max(k_a, k_b) ** m)
        a += c * k_a ** m * dn
        b += c * k_b ** m * dn
        n += dn
        path.append((n, a, b))
    return path


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directory", help="the run's output directory")
    parser.add_argument("--C", type=float, default=1e-3)
    parser.add_argument("--m", type=float, default=3)
    parser.add_argument("--figure", default=os.path.join(
        top, "doc", "figures", "ellipse_growth.png"))
    args = parser.parse_args()

    table = {int(r["step"]): r for r in steps(args.directory)}
    rows = []
    for step, front in sorted(fronts(args.directory).items()):
        a, b, misfit = fit(front)
        rows.append((step, float(table[step]["cycles"] or 0), a, b, misfit))
    a0, b0 = rows[0][2], rows[0][3]
    model = two_point(a0, b0, args.C, args.m, rows[-1][1] * 1.02)

    def model_at(n):
        for (n0, x0, y0), (n1, x1, y1) in zip(model, model[1:]):
            if n0 <= n <= n1:
                w = (n - n0) / (n1 - n0) if n1 > n0 else 0
                return x0 + w * (x1 - x0), y0 + w * (y1 - y0)
        return model[-1][1], model[-1][2]

    print("| step | cycles | a | b | b/a | model at N: a, b, b/a | "
          "misfit to the ellipse |")
    print("|---|---|---|---|---|---|---|")
    for step, n, a, b, misfit in rows:
        ma, mb = model_at(n)
        print(f"| {step} | {n:.1f} | {a:.4f} | {b:.4f} | {b / a:.3f} | "
              f"{ma:.4f}, {mb:.4f}, {mb / ma:.3f} | {100 * misfit:.1f} % |")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib missing: no figure", file=sys.stderr)
        return
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    left.plot([p[1] for p in model], [p[2] / p[1] for p in model], "k-",
              label="two-point model (Irwin's K)")
    left.plot([r[2] for r in rows], [r[3] / r[2] for r in rows], "o",
              label="xcrack, ends of the axes")
    left.set_xlabel("semi-axis a")
    left.set_ylabel("aspect ratio b/a")
    left.legend()
    right.plot([p[0] for p in model], [p[1] for p in model], "k-",
               label="model a")
    right.plot([p[0] for p in model], [p[2] for p in model], "k--",
               label="model b")
    right.plot([r[1] for r in rows], [r[2] for r in rows], "o",
               label="xcrack a")
    right.plot([r[1] for r in rows], [r[3] for r in rows], "s",
               label="xcrack b")
    right.set_xlabel("load cycles N")
    right.set_ylabel("semi-axis")
    right.legend()
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(args.figure)), exist_ok=True)
    fig.savefig(args.figure, dpi=100)
    print(f"wrote {args.figure}")


if __name__ == "__main__":
    main()
