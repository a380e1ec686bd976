#!/usr/bin/python3
"""The foot of a point on a 3D front polyline, nearest point against the
normal-plane foot (doc/performance.md, "What blocks the larger steps").

The interaction integral's auxiliary fields live in the frame of the foot.
The nearest point of a polyline jumps across the bisector planes of its
vertices on the concave side; the normal-plane foot, the abscissa s with
(x - p(s)) . e3(s) = 0 and e3 the chord over [s - step, s + step] as in
FrontCurve::frame_at, is continuous there. This walks points along arcs
near a unit circle of 64 segments and prints the largest change of s
between neighbouring points (the typical change is 2e-4) for both feet, and
the Newton iterations the normal-plane foot took from the nearest point.

    /usr/bin/python3 contrib/study_continuous_foot.py
"""
import argparse
import numpy as np

N_POINTS = 65
STEP = 0.25  # half the outer crown radius, as FrontCurve's step
angles = np.linspace(0, 2 * np.pi, N_POINTS)
P = np.c_[np.cos(angles), np.sin(angles), 0 * angles]
P[-1] = P[0]
S = np.r_[0, np.cumsum(np.linalg.norm(np.diff(P, axis=0), axis=1))]
LENGTH = S[-1]


def position(s):
    s = s % LENGTH
    i = min(np.searchsorted(S, s, side="right") - 1, N_POINTS - 2)
    t = (s - S[i]) / (S[i + 1] - S[i])
    return P[i] + t * (P[i + 1] - P[i])


def tangent(s):
    v = position(s + STEP) - position(s - STEP)
    return v / np.linalg.norm(v)


def nearest(x):
    best, best_s = np.inf, 0.
    for i in range(N_POINTS - 1):
        ab = P[i + 1] - P[i]
        t = np.clip((x - P[i]) @ ab / (ab @ ab), 0, 1)
        d = np.linalg.norm(x - P[i] - t * ab)
        if d < best:
            best, best_s = d, S[i] + t * (S[i + 1] - S[i])
    return best_s


def normal_plane_foot(x):
    """Newton on g(s) = (x - p(s)) . e3(s) from the nearest point."""
    s = nearest(x)
    for iteration in range(1, 31):
        g = (x - position(s)) @ tangent(s)
        h = 1e-7
        dg = ((x - position(s + h)) @ tangent(s + h)
              - (x - position(s - h)) @ tangent(s - h)) / (2 * h)
        s -= g / dg
        if abs(g / dg) < 1e-13:
            break
    return s, iteration


def main():
    argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    print("| arc radius | height | largest step of s, nearest | largest step, "
          "normal plane | Newton iterations |")
    print("|---|---|---|---|---|")
    for rho, z in [(0.8, 0.0), (0.9, 0.05), (1.2, 0.1)]:
        s_near, s_plane, iterations = [], [], []
        for phi in np.linspace(0.3, 0.9, 3001):
            x = np.array([rho * np.cos(phi), rho * np.sin(phi), z])
            s_near.append(nearest(x))
            s, k = normal_plane_foot(x)
            s_plane.append(s)
            iterations.append(k)
        print(f"| {rho} | {z} | {np.max(np.abs(np.diff(s_near))):.1e} | "
              f"{np.max(np.abs(np.diff(s_plane))):.1e} | {max(iterations)} |")


if __name__ == "__main__":
    main()
