#!/usr/bin/env python3
"""Newman and Raju's stress intensity factors of a semi-elliptical surface
crack in a finite plate (Newman and Raju 1981, Eng. Fract. Mech. 15;
NASA TM-83200 1981 for tension and bending), the handbook values the
surface-crack benchmarks compare against. Their stated accuracy is about
5 % for 0 < a/c <= 1, a/t <= 0.8, c/b < 0.5, 0 <= phi <= pi/2.

a: depth, c: half-length on the face, t: thickness, b: half-width of the
plate; phi the parametric angle of the ellipse (x = c cos phi, y = a sin
phi; phi = 0 where the front meets the face, pi/2 at the deepest point).

  contrib/newman_raju.py --a 0.6 --c 1 --t 2 --b 4            # a table
  contrib/newman_raju.py --a 0.6 --c 1 --t 2 --b 4 --expression
      # 'Reference K' of a prm: K_I as an expression of the front point's
      # x (along the face) and y (depth), centre at the origin.
  contrib/newman_raju.py --corner --a 0.6 --c 1 --t 2 --b 16 [--expression]

A quarter-elliptical corner crack under tension (--corner; Newman and
Raju 1986, "Stress-intensity factor equations for cracks in
three-dimensional finite bodies subjected to tension and bending loads",
in Atluri (ed.), Computational Methods in the Mechanics of Fracture,
a/c <= 1): the crack at the edge where the face y = 0 meets the face
x = 0, depth a along y into the thickness t, c along x on the face y = 0;
b the plate's whole width from that edge. phi = 0 on the face y = 0,
pi/2 on the face x = 0; both are free-surface points.
"""
import argparse
import math


def shape_factor(a_c):
    """Q, the square of the complete elliptic integral of the second kind,
    by the approximation Newman and Raju use (a/c <= 1)."""
    return 1 + 1.464 * a_c ** 1.65


def boundary_correction(a, c, t, b, phi):
    """F(phi) of tension: K = S sqrt(pi a / Q) F (a/c <= 1)."""
    a_c, a_t = a / c, a / t
    m1 = 1.13 - 0.09 * a_c
    m2 = -0.54 + 0.89 / (0.2 + a_c)
    m3 = 0.5 - 1 / (0.65 + a_c) + 14 * (1 - a_c) ** 24
    g = 1 + (0.1 + 0.35 * a_t ** 2) * (1 - math.sin(phi)) ** 2
    f_phi = (a_c ** 2 * math.cos(phi) ** 2 + math.sin(phi) ** 2) ** 0.25
    f_w = (1 / math.cos(math.pi * c / (2 * b) * math.sqrt(a_t))) ** 0.5
    return (m1 + m2 * a_t ** 2 + m3 * a_t ** 4) * g * f_phi * f_w


def bending_correction(a, c, t, phi):
    """H(phi): K under an outer-fibre bending stress S_b is
    S_b sqrt(pi a / Q) H F (a/c <= 1)."""
    a_c, a_t = a / c, a / t
    p = 0.2 + a_c + 0.6 * a_t
    h1 = 1 - 0.34 * a_t - 0.11 * a_c * a_t
    g1 = -1.22 - 0.12 * a_c
    g2 = 0.55 - 1.05 * a_c ** 0.75 + 0.47 * a_c ** 1.5
    h2 = 1 + g1 * a_t + g2 * a_t ** 2
    return h1 + (h2 - h1) * math.sin(phi) ** p


def corner_terms(a, c, t, b):
    """The parts of a corner crack's F_c that do not depend on phi: the
    M polynomial times the width correction, and the coefficients of g1
    and g2 (a/c <= 1; b the whole width)."""
    a_c, a_t = a / c, a / t
    m = ((1.08 - 0.03 * a_c) + (-0.44 + 1.06 / (0.3 + a_c)) * a_t ** 2 +
         (-0.5 + 0.25 * a_c + 14.8 * (1 - a_c) ** 15) * a_t ** 4)
    # The width correction has not been checked against a second source
    # (the rest has); sif_corner_3d.prm keeps c/b at 1/16, where it is
    # 1.003.
    lam = c / b * math.sqrt(a_t)
    f_w = 1 - 0.2 * lam + 9.4 * lam ** 2 - 19.4 * lam ** 3 + 27.1 * lam ** 4
    return m * f_w, 0.08 + 0.4 * a_t ** 2, 0.08 + 0.15 * a_t ** 2


def corner_correction(a, c, t, b, phi):
    """F_c(phi) of a corner crack under tension: K = S sqrt(pi a / Q) F_c.
    g1 raises K towards the face y = 0 (phi = 0), g2 towards the face
    x = 0 (phi = pi/2)."""
    m_f_w, g1c, g2c = corner_terms(a, c, t, b)
    g1 = 1 + g1c * (1 - math.sin(phi)) ** 3
    g2 = 1 + g2c * (1 - math.cos(phi)) ** 3
    f_phi = ((a / c) ** 2 * math.cos(phi) ** 2 + math.sin(phi) ** 2) ** 0.25
    return m_f_w * g1 * g2 * f_phi


def k_corner(a, c, t, b, phi, stress=1.0):
    return (stress * math.sqrt(math.pi * a / shape_factor(a / c)) *
            corner_correction(a, c, t, b, phi))


def corner_expression(a, c, t, b):
    """K_I of a corner crack under a tension of 1 at the front point
    (x, y), the corner at the origin, as a muparser expression."""
    m_f_w, g1c, g2c = corner_terms(a, c, t, b)
    scale = math.sqrt(math.pi * a / shape_factor(a / c)) * m_f_w
    s = f"sin(atan2(abs(y) / {a!r}, abs(x) / {c!r}))"
    co = f"cos(atan2(abs(y) / {a!r}, abs(x) / {c!r}))"
    factor = (f"(1 + {g1c!r} * (1 - {s})^3) * "
              f"(1 + {g2c!r} * (1 - {co})^3) * "
              f"({(a / c) ** 2!r} * {co}^2 + {s}^2)^0.25")
    return f"{scale!r} * {factor}; 0; 0"


def k_tension(a, c, t, b, phi, stress=1.0):
    return (stress * math.sqrt(math.pi * a / shape_factor(a / c)) *
            boundary_correction(a, c, t, b, phi))


def k_bending(a, c, t, b, phi, stress=1.0):
    return (stress * math.sqrt(math.pi * a / shape_factor(a / c)) *
            bending_correction(a, c, t, phi) *
            boundary_correction(a, c, t, b, phi))


def expression(a, c, t, b, tension=1.0, bending=0.0):
    """K_I at the front point (x, y) as a muparser expression (phi from
    the point's position on the ellipse), for 'Reference K'."""
    a_c, a_t = a / c, a / t
    m = ((1.13 - 0.09 * a_c) + (-0.54 + 0.89 / (0.2 + a_c)) * a_t ** 2 +
         (0.5 - 1 / (0.65 + a_c) + 14 * (1 - a_c) ** 24) * a_t ** 4)
    f_w = (1 / math.cos(math.pi * c / (2 * b) * math.sqrt(a_t))) ** 0.5
    scale = math.sqrt(math.pi * a / shape_factor(a_c)) * m * f_w
    gc = 0.1 + 0.35 * a_t ** 2
    s = f"sin(atan2(abs(y) / {a!r}, abs(x) / {c!r}))"
    factor = f"(1 + {gc!r} * (1 - {s})^2) * ({a_c ** 2!r} * (1 - {s}^2) + {s}^2)^0.25"
    load = f"{tension!r}"
    if bending:
        p = 0.2 + a_c + 0.6 * a_t
        h1 = 1 - 0.34 * a_t - 0.11 * a_c * a_t
        h2 = (1 + (-1.22 - 0.12 * a_c) * a_t +
              (0.55 - 1.05 * a_c ** 0.75 + 0.47 * a_c ** 1.5) * a_t ** 2)
        load = (f"({tension!r} + {bending!r} * ({h1!r} + {h2 - h1!r} * "
                f"{s}^{p!r}))")
    return f"{scale!r} * {load} * {factor}; 0; 0"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--a", type=float, required=True, help="depth")
    parser.add_argument("--c", type=float, required=True,
                        help="half-length on the face")
    parser.add_argument("--t", type=float, required=True, help="thickness")
    parser.add_argument("--b", type=float, required=True,
                        help="half-width of the plate (--corner: the whole "
                        "width from the cracked edge)")
    parser.add_argument("--corner", action="store_true",
                        help="a corner crack under tension")
    parser.add_argument("--tension", type=float, default=1.0)
    parser.add_argument("--bending", type=float, default=0.0,
                        help="outer-fibre bending stress")
    parser.add_argument("--expression", action="store_true",
                        help="print the Reference K expression")
    args = parser.parse_args()
    if args.corner:
        if args.expression:
            print(corner_expression(args.a, args.c, args.t, args.b))
            return
        print("phi_deg  K_tension")
        for deg in (0, 10, 22.5, 30, 45, 60, 67.5, 80, 90):
            k = k_corner(args.a, args.c, args.t, args.b, math.radians(deg))
            print(f"{deg:7.1f}  {args.tension * k:9.5f}")
        return
    if args.expression:
        print(expression(args.a, args.c, args.t, args.b, args.tension,
                         args.bending))
        return
    print("phi_deg  K_tension  K_bending  K")
    for deg in (0, 10, 22.5, 30, 45, 60, 67.5, 80, 90):
        phi = math.radians(deg)
        kt = k_tension(args.a, args.c, args.t, args.b, phi)
        kb = k_bending(args.a, args.c, args.t, args.b, phi)
        print(f"{deg:7.1f}  {kt:9.5f}  {kb:9.5f}  "
              f"{args.tension * kt + args.bending * kb:9.5f}")


if __name__ == "__main__":
    main()
