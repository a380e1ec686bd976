#!/usr/bin/python3
"""Rerun the tables of doc/ that take minutes and report the numbers that
no longer match the code.

    contrib/build.sh release
    contrib/check_doc_tables.py                   every registered table
    contrib/check_doc_tables.py paris_ellipse_3d  one of them
    contrib/check_doc_tables.py --list            what is registered
    contrib/check_doc_tables.py --print NAME      the table the code gives now

A registered table carries, on the line under it in its page, the words
"contrib/check_doc_tables.py NAME" with the command and the commit that
made it. The script runs the shipped scene with the release build in a
temporary directory, makes the table's rows again and compares them with
the page's, number by number: a number that moved by more than one unit of
its last printed digit is reported with its row and column. Exit status 1
if any did. Wall times are never compared.
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from xcrack_runs import top, xcrack  # noqa: E402


def run_scene(prm, work):
    """Run prm/benchmarks/<prm>.prm into work/out; return work/out."""
    out = os.path.join(work, "out")
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    subprocess.run([xcrack, "-s", f"Output directory={out}",
                    "-s", "Output/Timing summary=false",
                    os.path.join(top, "prm", "benchmarks", prm + ".prm")],
                   check=True, env=env, stdout=subprocess.DEVNULL)
    return out


def last_rows(out):
    """The last statistics row of each step."""
    with open(os.path.join(out, "statistics.csv")) as f:
        rows = {int(r["step"]): r for r in csv.DictReader(f)}
    return [rows[s] for s in sorted(rows)]


def ellipse_table(work):
    """doc/verification/growth.md, the ellipse growing towards a circle:
    contrib/plot_ellipse_growth.py's table."""
    out = run_scene("paris_ellipse_3d", work)
    text = subprocess.run(
        [sys.executable, os.path.join(top, "contrib", "plot_ellipse_growth.py"),
         out, "--figure", os.path.join(work, "ellipse.png")],
        check=True, capture_output=True, text=True).stdout
    return [line for line in text.splitlines() if line.startswith("| ")][1:]


def penny_table(work):
    """doc/verification/growth.md, the penny: a = sqrt(area / pi), the
    cycles against the closed form from a0 = 1 and (in brackets) from the
    a0 of the fields."""
    rows = last_rows(run_scene("paris_penny_3d", work))
    factor = 1e-3 * (2 / math.sqrt(math.pi)) ** 3
    radius = [math.sqrt(float(r["crack_size"]) / math.pi) for r in rows]

    def closed(a0, a):
        return 2 * (a0 ** -0.5 - a ** -0.5) / factor

    table = []
    for step, (r, a) in enumerate(zip(rows, radius)):
        if step == 0:
            continue
        n = float(r["cycles"])
        exact, fields = closed(1.0, a), closed(radius[0], a)
        table.append(f"| {step} | {a:.4f} | {n:.2f} | {exact:.2f} | "
                     f"{100 * (n / exact - 1):+.2f} % "
                     f"({100 * (n / fields - 1):+.2f} %) |")
    return table


def closure_table(work):
    """doc/verification/contact.md, fatigue with closure: the cycles of the
    shipped R = -1 run with contact against the closed form of R = 0."""
    rows = last_rows(run_scene("closure_center_2d", work))
    n = float(rows[-1]["cycles"])
    return [f"| R = -1, penalty (`closure_center_2d.prm`) | {n:,.2f} | "
            f"{100 * (n / 776634.444 - 1):+.3f} % |"]


TABLES = {
    "paris_ellipse_3d": ("doc/verification/growth.md", ellipse_table,
                         "about 3 min"),
    "paris_penny_3d": ("doc/verification/growth.md", penny_table,
                       "about 15 min"),
    "closure_center_2d": ("doc/verification/contact.md", closure_table,
                          "about 20 s"),
}


def page_table(name, page):
    """The rows of the table above the line that names `name` in `page`,
    and that line's number."""
    lines = open(os.path.join(top, page)).read().splitlines()
    marker = f"contrib/check_doc_tables.py {name}"
    for i, line in enumerate(lines):
        if marker in line:
            j = i - 1
            while j >= 0 and not lines[j].startswith("|"):
                j -= 1
            end = j + 1
            while j >= 0 and lines[j].startswith("|"):
                j -= 1
            rows = [l for l in lines[j + 1:end] if not re.match(r"\|[-| ]+\|$", l)]
            return rows[1:], i + 1
    raise SystemExit(f"{page} has no table marked '{marker}'")


NUMBER = re.compile(r"[-+]?\d[\d,]*\.?\d*(?:e[-+]?\d+)?")


def numbers(cell):
    return [n for n in NUMBER.findall(cell.replace("**", ""))]


def compare(name, page_rows, new_rows):
    """Differences as text, matching rows by their first cell."""
    found = []
    new_by_key = {r.split("|")[1].strip(): r for r in new_rows}
    for row in page_rows:
        key = row.split("|")[1].strip()
        if key not in new_by_key:
            continue
        old_cells = [c.strip() for c in row.strip("|").split("|")]
        new_cells = [c.strip() for c in new_by_key[key].strip("|").split("|")]
        for column, (old, new) in enumerate(zip(old_cells, new_cells)):
            for a, b in zip(numbers(old), numbers(new)):
                digits = len(a.split(".")[1]) if "." in a and "e" not in a else 0
                unit = 10.0 ** -digits
                x, y = float(a.replace(",", "")), float(b.replace(",", ""))
                if abs(x - y) > unit * (1 + 1e-9) + 1e-12 * abs(x):
                    found.append(f"{name}: row '{key}', column {column + 1}: "
                                 f"the page says {a}, the code gives {b}")
    missing = [r.split("|")[1].strip() for r in page_rows
               if r.split("|")[1].strip() not in new_by_key]
    if missing:
        found.append(f"{name}: the code gives no row for {', '.join(missing)}")
    return found


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("names", nargs="*", help="registered tables "
                        "(default: all)")
    parser.add_argument("--list", action="store_true",
                        help="list the registered tables and stop")
    parser.add_argument("--print", action="store_true",
                        help="print the tables the code gives now")
    args = parser.parse_args()
    if args.list:
        for name, (page, _, cost) in TABLES.items():
            print(f"{name}: {page} ({cost})")
        return
    names = args.names or list(TABLES)
    unknown = [n for n in names if n not in TABLES]
    if unknown:
        raise SystemExit(f"not registered: {', '.join(unknown)} "
                         f"(--list shows {', '.join(TABLES)})")
    if not os.path.exists(xcrack):
        raise SystemExit(f"{xcrack} is missing: contrib/build.sh release")
    found = []
    for name in names:
        page, make, cost = TABLES[name]
        page_rows, line = page_table(name, page)
        print(f"{name} ({page}, line {line}; {cost}) ...", flush=True)
        with tempfile.TemporaryDirectory() as work:
            new_rows = make(work)
        if args.print:
            print("\n".join(new_rows))
        differences = compare(name, page_rows, new_rows)
        found += differences
        print("  " + ("\n  ".join(differences) if differences else "matches"))
    sys.exit(1 if found else 0)


if __name__ == "__main__":
    main()
