#!/usr/bin/env python3
"""Plot K_I, K_II, K_III and G along the crack front from the
front_<step>.csv files of a run (one figure per file, or the files of
several steps or meshes overlaid), and print them as a table.

    /usr/bin/python3 contrib/plot_front.py output/sif_inclined_2d            # the last one
    /usr/bin/python3 contrib/plot_front.py output/sif_inclined_2d --all      # every one

Along a 3D front the abscissa s is the horizontal axis; at the tips of a 2D
crack (one row per tip) the tip index is. The figure is written next to the
CSV files as front.png.
"""
import argparse
import csv
import os

from xcrack_runs import run_files


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("directory", help="the run's output directory")
    parser.add_argument("--all", action="store_true",
                        help="overlay every file, not only the last")
    args = parser.parse_args()
    files = run_files(args.directory, r"front_.*\.csv")
    if not files:
        raise SystemExit(f"no front_*.csv in {args.directory}: was "
                         "'Fracture parameters/Compute' on and is there a crack?")
    if not args.all:
        files = files[-1:]

    for path in files:
        rows = read(path)
        print(f"\n{os.path.basename(path)}\n")
        print("| index | s | x | y | z | K_I | K_II | K_III | G | G_Irwin |")
        print("|---|---|---|---|---|---|---|---|---|---|")
        for r in rows:
            print("| " + " | ".join(r[c] for c in ["index", "s", "x", "y", "z",
                                                    "K_I", "K_II", "K_III",
                                                    "G", "G_Irwin"]) + " |")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("(matplotlib missing: no figure; /usr/bin/python3 has it)")
        return
    fig, axes = plt.subplots(2, 1, figsize=(6, 6), sharex=True)
    for path in files:
        rows = read(path)
        three_d = len(rows) > 1 and any(float(r["s"]) > 0 for r in rows)
        x = [float(r["s"]) if three_d else int(r["index"]) for r in rows]
        label = os.path.splitext(os.path.basename(path))[0]
        style = "-" if three_d else "o"
        for column in ["K_I", "K_II", "K_III"]:
            axes[0].plot(x, [float(r[column]) for r in rows], style,
                         label=f"{column} ({label})")
        axes[1].plot(x, [float(r["G"]) for r in rows], style,
                     label=f"G, J integral ({label})")
        axes[1].plot(x, [float(r["G_Irwin"]) for r in rows], "x",
                     label=f"G from the K's ({label})")
        axes[1].set_xlabel("s" if three_d else "tip index")
    axes[0].set_ylabel("K")
    axes[1].set_ylabel("G")
    for ax in axes:
        ax.legend(fontsize=7)
        ax.grid(True, lw=0.3)
    fig.tight_layout()
    out = os.path.join(args.directory, "front.png")
    fig.savefig(out, dpi=110)
    print(f"\nwrote {out}")


if __name__ == "__main__":
    main()
