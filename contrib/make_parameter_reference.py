#!/usr/bin/python3
"""Write doc/parameters.md, the reference of every entry of a parameter
file, from the code: `xcrack --print-parameters json` gives each entry's
default, pattern and documentation as declared next to the class that
uses it.

    contrib/make_parameter_reference.py build/release/xcrack doc/parameters.md
    cmake --build build/release --target parameter_reference   (the same)
    contrib/make_parameter_reference.py XCRACK --check doc/parameters.md

With --check nothing is written: the exit status is 1, with the command
that updates it, if the file differs from what the code declares (the
test cli/parameter_reference runs this).
"""
import argparse
import json
import os
import re
import subprocess
import sys

HEADER = """# Parameter reference

Every entry of an xcrack parameter file, generated from the code by
`contrib/make_parameter_reference.py` (`cmake --build build/release
--target parameter_reference`); do not edit by hand, a test fails when this
file is stale. `xcrack --print-parameters` prints the same as a parameter
file. Subsections are headings; an entry's value must match the pattern
in "allowed".

Units are the scene's: xcrack has none of its own. Give lengths,
stresses and moduli in one consistent set (say m for lengths, MPa for
stresses and moduli); K is then in MPa m^1/2, G in MPa m, and a rate
da/dN in m per cycle (user-guide.md, "Units").
"""


def pattern(text):
    """A pattern description made short: [Double 0...MAX_DOUBLE
    (inclusive)] -> a number >= 0."""
    text = text.strip()
    match = re.fullmatch(r"\[Selection (.*) \]", text)
    if match:
        return "one of: " + ", ".join(f"`{c}`" for c in match.group(1).split("|"))
    match = re.fullmatch(r"\[MultipleSelection (.*) \]", text)
    if match:
        return "a list of: " + ", ".join(f"`{c}`" for c in match.group(1).split("|"))
    if text == "[Bool]":
        return "`true` or `false`"
    if text == "[Anything]":
        return "text"
    if text.startswith("[FileName"):
        return "a file name (relative: to the parameter file)"
    if text.startswith("[DirectoryName"):
        return "a directory name"
    match = re.fullmatch(r"\[(Integer|Double) (?:range )?(\S+)\.\.\.(\S+) "
                         r"\(inclusive\)\]", text)
    if match:
        kind = "an integer" if match.group(1) == "Integer" else "a number"
        low, high = match.group(2), match.group(3)
        bounded = lambda v: v not in ("MAX_INT", "MAX_DOUBLE", "-MAX_INT",
                                      "-MAX_DOUBLE", "-2147483648",
                                      "2147483647")
        if bounded(low) and bounded(high):
            return f"{kind} in [{low}, {high}]"
        if bounded(low):
            return f"{kind} >= {low}"
        if bounded(high):
            return f"{kind} <= {high}"
        return kind
    match = re.fullmatch(r"\[(Integer|Double)\]", text)
    if match:
        return "an integer" if match.group(1) == "Integer" else "a number"
    return text.replace("|", "\\|")


def cell(text):
    return " ".join(str(text).split()).replace("|", "\\|")


def is_entry(node):
    return isinstance(node, dict) and "pattern_description" in node


def write_section(out, node, path, level):
    entries = [(k, v) for k, v in node.items() if is_entry(v)]
    sections = [(k, v) for k, v in node.items()
                if isinstance(v, dict) and not is_entry(v)]
    if path:
        out.append("")
        out.append("#" * min(level, 6) + " " + " / ".join(path))
    if path and path[-1] == "Crack 1":
        out.append("")
        out.append("`Crack 2`, `Crack 3`, ... take the same entries, one "
                   "subsection per crack up to `Number of cracks`.")
    if entries:
        out.append("")
        out.append("| entry | default | allowed | meaning |")
        out.append("|---|---|---|---|")
        for name, entry in sorted(entries):
            default = entry.get("default_value", "")
            out.append(f"| `{cell(name)}` | "
                       + (f"`{cell(default)}`" if default != "" else "(empty)")
                       + f" | {cell(pattern(entry['pattern_description']))} | "
                       f"{cell(entry.get('documentation', ''))} |")
    for name, child in sorted(sections):
        # One crack subsection stands for all of them.
        if re.fullmatch(r"Crack ([2-9]|[1-9][0-9]+)", name):
            continue
        write_section(out, child, path + [name], level + 1)


def reference(xcrack):
    text = subprocess.run([xcrack, "--print-parameters", "json"], check=True,
                          capture_output=True, text=True).stdout
    tree = json.loads(text)
    out = [HEADER.rstrip()]
    out.append("")
    out.append("## Top level")
    top = {k: v for k, v in tree.items() if is_entry(v)}
    write_section(out, top, [], 2)
    for name, child in sorted(tree.items()):
        if not is_entry(child):
            write_section(out, child, [name], 2)
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("xcrack", help="the xcrack executable")
    parser.add_argument("target", help="the Markdown file (doc/parameters.md)")
    parser.add_argument("--check", action="store_true",
                        help="compare instead of writing")
    args = parser.parse_args()
    text = reference(args.xcrack)
    if args.check:
        old = open(args.target).read() if os.path.exists(args.target) else ""
        if old != text:
            print(f"{args.target} is stale: the code declares other entries. "
                  "Update it with: cmake --build build/release --target "
                  "parameter_reference", file=sys.stderr)
            sys.exit(1)
        print(f"{args.target} is current")
        return
    with open(args.target, "w") as f:
        f.write(text)
    print(f"wrote {args.target}")


if __name__ == "__main__":
    main()
