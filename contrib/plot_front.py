#!/usr/bin/python3
"""K_I, K_II, K_III and G of a run's fronts: a table and a figure.

    contrib/plot_front.py output/sif_inclined_2d          the last solve
    contrib/plot_front.py output/sif_penny_3d --all       every solve

Along a 3D front the abscissa s is the horizontal axis (the last solve, or
with --all every solve overlaid). At the tips of a 2D crack K is drawn
against the solve: the step of a growth run (its last mesh), or the mesh
of a static run solved on several; one line per tip and mode. Points whose
K the run flagged as unreliable (the `unreliable` and `reason` columns of
the front files) get open red markers and their reason in the table. The
figure is written next to the CSV files as front.png. K is in the scene's
stress unit times the square root of its length unit (--length-unit and
--stress-unit only label the axes).

Runs with the system Python (/usr/bin/python3, whose matplotlib
contrib/install_dependencies.sh installs).
"""
import argparse
import os
import re

from xcrack_runs import number, read_csv as read, run_files


def key_of(path):
    """(step, mesh) of front_<step>[.<mesh>].csv."""
    match = re.match(r"front_(\d+)(?:\.(\d+))?\.csv$", os.path.basename(path))
    return int(match.group(1)), int(match.group(2) or 0)


def print_table(path, rows):
    print(f"\n{os.path.basename(path)}\n")
    columns = ["index", "s", "x", "y", "z", "K_I", "K_II", "K_III", "G",
               "G_Irwin"]
    print("| " + " | ".join(columns) + " | unreliable |")
    print("|" + "---|" * (len(columns) + 1))
    for r in rows:
        print("| " + " | ".join(r.get(c, "") for c in columns) + " | "
              + (r.get("reason", "") if r.get("unreliable") == "1" else "")
              + " |")


def plot_3d(plt, files, units):
    fig, axes = plt.subplots(2, 1, figsize=(6.5, 6), sharex=True)
    for path in files:
        rows = read(path)
        label = os.path.splitext(os.path.basename(path))[0]
        for front in sorted({r["front"] for r in rows}):
            line = [r for r in rows if r["front"] == front]
            s = [number(r["s"]) for r in line]
            for mode in ("K_I", "K_II", "K_III"):
                axes[0].plot(s, [number(r[mode]) for r in line], "-",
                             label=f"{mode} ({label})" if front == "1" else None)
            axes[1].plot(s, [number(r["G"]) for r in line], "-",
                         label=f"G, G-theta ({label})" if front == "1" else None)
            axes[1].plot(s, [number(r["G_Irwin"]) for r in line], ":",
                         label=f"G from the K's ({label})"
                         if front == "1" else None)
            bad = [r for r in line if r.get("unreliable") == "1"]
            if bad:
                axes[0].plot([number(r["s"]) for r in bad],
                             [number(r["K_I"]) for r in bad], "o", mfc="none",
                             mec="red", ms=8, label="K unreliable")
    axes[1].set_xlabel(f"s along the front [{units.length}]")
    return fig, axes


def plot_2d(plt, files, units):
    """K per tip against the solve: one file per step (its last mesh), or
    per mesh of a static run."""
    by_key = {key_of(p): p for p in files}
    steps = sorted({k[0] for k in by_key})
    growth = len(steps) > 1
    if growth:
        chosen = [(s, by_key[max(k for k in by_key if k[0] == s)])
                  for s in steps]
        xlabel = "step"
    else:
        chosen = [(k[1], by_key[k]) for k in sorted(by_key)]
        xlabel = "mesh"
    series = {}
    for x, path in chosen:
        for r in read(path):
            series.setdefault(r["front"], []).append((x, r))
    fig, axes = plt.subplots(2, 1, figsize=(6.5, 6), sharex=True)
    for tip, points in sorted(series.items()):
        x = [p[0] for p in points]
        for mode in ("K_I", "K_II"):
            axes[0].plot(x, [number(p[1][mode]) for p in points], "o-", ms=3,
                         label=f"{mode}, tip {tip}")
        axes[1].plot(x, [number(p[1]["G"]) for p in points], "o-", ms=3,
                     label=f"G, G-theta, tip {tip}")
        axes[1].plot(x, [number(p[1]["G_Irwin"]) for p in points], "x",
                     label=f"G from the K's, tip {tip}")
        bad = [p for p in points if p[1].get("unreliable") == "1"]
        if bad:
            axes[0].plot([p[0] for p in bad],
                         [number(p[1]["K_I"]) for p in bad], "o", mfc="none",
                         mec="red", ms=9, mew=1.5,
                         label="K unreliable" if tip == "1" else None)
    axes[1].set_xlabel(xlabel)
    return fig, axes


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directory", help="the run's output directory")
    parser.add_argument("--all", action="store_true",
                        help="3D: overlay every solve, not only the last; "
                        "(2D tips are always drawn over every solve)")
    parser.add_argument("--length-unit", default="length",
                        help="the name of the scene's length unit, e.g. m")
    parser.add_argument("--stress-unit", default="stress",
                        help="the name of the scene's stress unit, e.g. MPa")
    args = parser.parse_args()
    files = sorted(run_files(args.directory, r"front_.*\.csv"), key=key_of)
    if not files:
        raise SystemExit(f"no front_*.csv in {args.directory}: was "
                         "'Fracture parameters/Compute' on and is there a crack?")
    last = read(files[-1])
    three_d = len(last) > 1 and any(number(r["s"], 0) > 0 for r in last)
    shown = files if (args.all or not three_d) else files[-1:]
    for path in (shown if args.all else files[-1:]):
        print_table(path, read(path))

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("(matplotlib missing: no figure; /usr/bin/python3 has it)")
        return
    units = argparse.Namespace(length=args.length_unit,
                               stress=args.stress_unit)
    fig, axes = (plot_3d if three_d else plot_2d)(plt, shown, units)
    axes[0].set_ylabel(f"K [{units.stress} {units.length}^1/2]")
    axes[1].set_ylabel(f"G [{units.stress} {units.length}]")
    for ax in axes:
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7)
        ax.grid(True, lw=0.3)
    fig.tight_layout()
    out = os.path.join(args.directory, "front.png")
    fig.savefig(out, dpi=110)
    print(f"\nwrote {out}")


if __name__ == "__main__":
    main()
