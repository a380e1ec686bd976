#!/usr/bin/python3
"""Figures of fatigue growth runs, and the table of their steps.

    contrib/plot_growth.py output/demo                   one run
    contrib/plot_growth.py out/a out/b --output-dir cmp  runs compared

For one run directory it writes, next to the run's files:

- growth_cycles.png: the crack size a against the load cycles N, with the
  reason the run stopped;
- growth_path.png: 2D, the crack path on the body's outline (holes
  included), the initial crack thick; 3D, the successive fronts seen along
  the crack plane's normal;
- growth_rate.png: Delta K against a, and da/dN against Delta K (log-log:
  a Paris law is a straight line of slope m);
- growth_k.png (3D): K_I, K_II, K_III along each front, step by step.

Steps whose K the run flagged as unreliable (a crown that reaches the
boundary, see the `unreliable` and `reason` columns) are drawn with open
red markers, and the cycles that rest on them are named. With several
directories the same figures overlay the runs (one colour each) in
--output-dir. Lengths are in the unit of the scene's mesh, K in the
scene's stress unit times the square root of its length unit
(--length-unit and --stress-unit only label the axes).

Reads statistics.csv, front_<step>.csv, run.json and the crack and
solution VTU files; runs with the system Python (/usr/bin/python3, whose
matplotlib contrib/install_dependencies.sh installs).
"""
import argparse
import os
import re

from xcrack_runs import (body_outline, number, read_csv as read, read_vtu,
                         run_files, run_record)


def steps(directory):
    """The last statistics row of each step, in order."""
    rows = read(os.path.join(directory, "statistics.csv"))
    last = {}
    for r in rows:
        last[int(r["step"])] = r
    return [last[s] for s in sorted(last)]


def fronts(directory):
    """{step: rows of front_<step>.csv}: the file of a step solved on one
    mesh, or of the last mesh of a step solved on several."""
    result = {}
    for path in run_files(directory, r"front_.*\.csv"):
        match = re.match(r"front_(\d+)(\.\d+)?\.csv$", os.path.basename(path))
        if match:
            result[int(match.group(1))] = read(path)
    return result


def crack_lips(directory, step):
    """The lips of every crack at `step` (its last mesh): 2D segments or 3D
    polygons as lists of (x, y, z)."""
    # Per crack (crack-, crack1-, crack2-, ...) the last file of the step:
    # its last mesh (the names sort by mesh).
    files = {}
    for path in run_files(directory, r"crack[0-9]*-.*\.vtu"):
        match = re.match(r"(crack[0-9]*)-(\d+)(\.\d+)?\.vtu$",
                         os.path.basename(path))
        if match and int(match.group(2)) == step:
            files[match.group(1)] = path
    lips = []
    for path in files.values():
        data = read_vtu(path, ("Points", "connectivity", "offsets", "types"))
        xyz = data["Points"]
        start = 0
        for end, kind in zip(data["offsets"], data["types"]):
            if int(kind) in (3, 7):
                lips.append([tuple(xyz[3 * int(i):3 * int(i) + 3])
                             for i in data["connectivity"][start:int(end)]])
            start = int(end)
    return lips


class Run:
    """What the figures need of one run directory."""

    def __init__(self, directory):
        self.directory = directory
        self.name = os.path.basename(os.path.normpath(directory))
        self.record = run_record(directory) or {}
        self.table = steps(directory)
        if not self.table or "crack_size" not in self.table[0]:
            raise SystemExit(f"{directory}/statistics.csv has no crack_size: "
                             "was it a run with a crack?")
        self.fronts = fronts(directory)
        self.three_d = any(number(r["z"], 0) != 0
                           for rows in self.fronts.values() for r in rows)
        self.flagged = {int(r["step"]) for r in self.table
                        if number(r.get("unreliable_points"), 0) > 0}

    def stop_reason(self):
        reason = self.record.get("reason", "")
        return reason if reason else "(no run record)"

    def cycles(self):
        return [number(r.get("cycles"), 0) for r in self.table]

    def sizes(self):
        return [number(r["crack_size"]) for r in self.table]


def print_table(run):
    print(f"\n{run.directory}: {run.stop_reason()}\n")
    print("| step | cycles | crack size | K_max | delta_K | advance | "
          "unreliable |")
    print("|---|---|---|---|---|---|---|")
    for r in run.table:
        step = int(r["step"])
        print(f"| {step} | {number(r.get('cycles'), 0):.6g} | "
              f"{number(r['crack_size']):.6g} | {r.get('K_max', '')} | "
              f"{r.get('delta_K', '')} | {r.get('advance', '')} | "
              f"{r.get('reason', '') if step in run.flagged else ''} |")
    unreliable = run.record.get("unreliable", {})
    if unreliable.get("cycles"):
        total = run.record.get("cycles", 0) or 1
        print(f"\n{unreliable['cycles']:.6g} of the {total:.6g} cycles "
              f"({100 * unreliable['cycles'] / total:.2g} %) rest on K "
              "flagged as unreliable.")


def mark_flagged(ax, run, x, y, color):
    """Open red markers on the flagged steps of `run` at (x, y)."""
    points = [(a, b) for a, b, r in zip(x, y, run.table)
              if int(r["step"]) in run.flagged]
    if points:
        ax.plot([p[0] for p in points], [p[1] for p in points], "o",
                mfc="none", mec="red", ms=9, mew=1.5,
                label=f"{run.name}: K unreliable" if color else "K unreliable")


def figure_cycles(plt, runs, units, path):
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for k, run in enumerate(runs):
        color = f"C{k}" if len(runs) > 1 else None
        ax.plot(run.cycles(), run.sizes(), "o-", ms=3, color=color,
                label=run.name if len(runs) > 1 else None)
        mark_flagged(ax, run, run.cycles(), run.sizes(), color)
    ax.set_xlabel("load cycles N")
    ax.set_ylabel(("crack length a" if not runs[0].three_d else
                   "crack area A") + f" [{units.length}"
                  + ("" if not runs[0].three_d else "^2") + "]")
    title = "\n".join(f"{run.name}: {wrap(run.stop_reason())}"
                      for run in runs)
    ax.set_title(title, fontsize=7, loc="left")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=7)
    save(fig, path)


def wrap(text, width=90):
    words, lines, line = text.split(), [], ""
    for word in words:
        if len(line) + len(word) > width:
            lines.append(line)
            line = ""
        line += (" " if line else "") + word
    return "\n".join(lines + [line])


def figure_path_2d(plt, runs, units, path):
    fig, ax = plt.subplots(figsize=(6, 5.5))
    outline = body_outline(runs[0].directory)
    if outline:
        for (a, b) in outline:
            ax.plot([a[0], b[0]], [a[1], b[1]], "-", color="0.5", lw=0.8)
    for k, run in enumerate(runs):
        color = f"C{k}"
        steps_known = sorted(run.fronts)
        if steps_known:
            for n, lip in enumerate(crack_lips(run.directory, steps_known[0])):
                ax.plot([p[0] for p in lip], [p[1] for p in lip], "-",
                        color="black", lw=2.5,
                        label="initial crack" if n == 0 and k == 0 else None)
        tips = {}
        for step in steps_known:
            for r in run.fronts[step]:
                tips.setdefault(r["front"], []).append(
                    (number(r["x"]), number(r["y"]), step))
        for t, (name, points) in enumerate(tips.items()):
            ax.plot([p[0] for p in points], [p[1] for p in points], "o-",
                    ms=2.5, color=color,
                    label=(f"{run.name}" if len(runs) > 1 else "tips")
                    if t == 0 else None)
            bad = [p for p in points if p[2] in run.flagged]
            if bad:
                ax.plot([p[0] for p in bad], [p[1] for p in bad], "o",
                        mfc="none", mec="red", ms=8, mew=1.5,
                        label="K unreliable" if t == 0 and k == 0 else None)
    ax.set_xlabel(f"x [{units.length}]")
    ax.set_ylabel(f"y [{units.length}]")
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=7)
    ax.set_title("crack path" + ("" if outline else
                                 " (no solution files: no outline)"))
    save(fig, path)


def view_axes(runs, view):
    points = [(number(r["x"]), number(r["y"]), number(r["z"]))
              for run in runs for rows in run.fronts.values() for r in rows]
    spans = [max(p[d] for p in points) - min(p[d] for p in points)
             for d in range(3)]
    a, b = sorted(range(3), key=lambda d: -spans[d])[:2]
    if view:
        if len(view) != 2 or any(c not in "xyz" for c in view):
            raise SystemExit(f"--view {view}: two of x, y, z")
        a, b = "xyz".index(view[0]), "xyz".index(view[1])
    return a, b


def figure_path_3d(plt, runs, units, view, path):
    a, b = view_axes(runs, view)
    fig, ax = plt.subplots(figsize=(6, 5.5))
    for k, run in enumerate(runs):
        last = max(run.fronts) or 1
        for step in sorted(run.fronts):
            rows = run.fronts[step]
            for front in sorted({r["front"] for r in rows}):
                line = [r for r in rows if r["front"] == front]
                color = (plt.cm.viridis(step / last) if len(runs) == 1
                         else f"C{k}")
                ax.plot([number(r["xyz"[a]]) for r in line],
                        [number(r["xyz"[b]]) for r in line],
                        "--" if step in run.flagged else "-", lw=0.8,
                        color=color,
                        label=run.name if len(runs) > 1 and step == 0 else None)
    ax.set_xlabel(f"{'xyz'[a]} [{units.length}]")
    ax.set_ylabel(f"{'xyz'[b]} [{units.length}]")
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, lw=0.3)
    ax.set_title("fronts, step by step" +
                 (f" (0 to {max(runs[0].fronts)}, dark to light)"
                  if len(runs) == 1 else "") +
                 "; dashed: K unreliable", fontsize=9)
    if len(runs) > 1:
        ax.legend(fontsize=7)
    save(fig, path)


def figure_rate(plt, runs, units, path):
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
    for k, run in enumerate(runs):
        color = f"C{k}"
        rows = [r for r in run.table if number(r.get("delta_K")) > 0]
        a = [number(r["crack_size"]) for r in rows]
        dk = [number(r["delta_K"]) for r in rows]
        axes[0].plot(a, dk, "o-", ms=3, color=color,
                     label=run.name if len(runs) > 1 else None)
        # da/dN of the fastest point between steps: its advance over the
        # cycles that advance took (the next row's delta_cycles).
        rate, dk_rate, bad = [], [], []
        for r, s in zip(run.table, run.table[1:]):
            cycles = number(s.get("delta_cycles"), 0)
            if cycles > 0 and number(r.get("delta_K"), 0) > 0:
                rate.append(number(r["advance"]) / cycles)
                dk_rate.append(number(r["delta_K"]))
                bad.append(int(r["step"]) in run.flagged
                           or int(s["step"]) in run.flagged)
        axes[1].loglog(dk_rate, rate, "o", ms=3, color=color,
                       label=run.name if len(runs) > 1 else None)
        flagged = [(x, y) for x, y, f in zip(dk_rate, rate, bad) if f]
        if flagged:
            axes[1].loglog([p[0] for p in flagged], [p[1] for p in flagged],
                           "o", mfc="none", mec="red", ms=9, mew=1.5,
                           label="K unreliable" if k == 0 else None)
        flagged = [(x, y) for x, y, r in zip(a, dk, rows)
                   if int(r["step"]) in run.flagged]
        if flagged:
            axes[0].plot([p[0] for p in flagged], [p[1] for p in flagged],
                         "o", mfc="none", mec="red", ms=9, mew=1.5,
                         label="K unreliable" if k == 0 else None)
    k_unit = f"{units.stress} {units.length}^1/2"
    axes[0].set_xlabel(("crack length a" if not runs[0].three_d else
                        "crack area A") + f" [{units.length}"
                       + ("" if not runs[0].three_d else "^2") + "]")
    axes[0].set_ylabel(f"Delta K, largest on the fronts [{k_unit}]")
    axes[1].set_xlabel(f"Delta K [{k_unit}]")
    axes[1].set_ylabel(f"da/dN of the fastest point [{units.length}/cycle]")
    for ax in axes:
        ax.grid(True, lw=0.3, which="both")
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7)
    save(fig, path)


def figure_k_3d(plt, run, units, path):
    fig, axes = plt.subplots(3, 1, figsize=(6.5, 8), sharex=True)
    last = max(run.fronts) or 1
    for step in sorted(run.fronts):
        rows = run.fronts[step]
        for front in sorted({r["front"] for r in rows}):
            line = [r for r in rows if r["front"] == front]
            s = [number(r["s"]) for r in line]
            for ax, mode in zip(axes, ("K_I", "K_II", "K_III")):
                ax.plot(s, [number(r[mode]) for r in line],
                        "--" if step in run.flagged else "-", lw=0.8,
                        color=plt.cm.viridis(step / last))
    k_unit = f"{units.stress} {units.length}^1/2"
    for ax, mode in zip(axes, ("K_I", "K_II", "K_III")):
        ax.set_ylabel(f"{mode} [{k_unit}]")
        ax.grid(True, lw=0.3)
    axes[-1].set_xlabel(f"s along the front [{units.length}]")
    axes[0].set_title(f"K along the fronts, steps 0 to {max(run.fronts)} "
                      "(dark to light; dashed: K unreliable)", fontsize=9)
    save(fig, path)


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    print(f"wrote {path}")


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directories", nargs="+", metavar="DIRECTORY",
                        help="a growth run's output directory")
    parser.add_argument("--output-dir", default="",
                        help="where the figures go (default: the run's "
                        "directory for one run, the working directory for "
                        "several)")
    parser.add_argument("--view", default="",
                        help="3D: the two axes of the fronts' figure, e.g. "
                        "xz (default: the two of largest extent)")
    parser.add_argument("--length-unit", default="length",
                        help="the name of the scene's length unit, e.g. m")
    parser.add_argument("--stress-unit", default="stress",
                        help="the name of the scene's stress unit, e.g. MPa")
    parser.add_argument("--path-figure", default="",
                        help="where to write the figure of the path or "
                        "fronts (default: OUTPUT_DIR/growth_path.png)")
    args = parser.parse_args()
    runs = [Run(d) for d in args.directories]
    for run in runs:
        print_table(run)
    if len({run.three_d for run in runs}) > 1:
        raise SystemExit("the runs mix 2D and 3D scenes")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("(matplotlib missing: no figures; /usr/bin/python3 has it)")
        return

    units = argparse.Namespace(length=args.length_unit,
                               stress=args.stress_unit)
    out = args.output_dir or (runs[0].directory if len(runs) == 1 else ".")
    os.makedirs(out, exist_ok=True)
    figure_cycles(plt, runs, units, os.path.join(out, "growth_cycles.png"))
    path = args.path_figure or os.path.join(out, "growth_path.png")
    if any(run.fronts for run in runs):
        if runs[0].three_d:
            figure_path_3d(plt, runs, units, args.view, path)
            if len(runs) == 1:
                figure_k_3d(plt, runs[0], units,
                            os.path.join(out, "growth_k.png"))
        else:
            figure_path_2d(plt, runs, units, path)
    figure_rate(plt, runs, units, os.path.join(out, "growth_rate.png"))


if __name__ == "__main__":
    main()
