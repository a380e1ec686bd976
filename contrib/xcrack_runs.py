"""Run the release xcrack on a parameter text and read its statistics.csv:
the one helper the study and benchmark scripts in contrib/ share."""
import csv
import json
import os
import subprocess
import sys

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
xcrack = os.path.join(top, "build", "release", "xcrack")


def benchmark_prm(benchmark, work, entries=""):
    """The parameter text of a study's run: prm/benchmarks/<benchmark>.prm
    writing to work/out without a timing table, then `entries`."""
    return (f"include {top}/prm/benchmarks/{benchmark}.prm\n"
            f"set Output directory = {work}/out\n"
            "subsection Output\n  set Timing summary = false\nend\n"
            + entries)


def run_xcrack(prm_text, work, ranks=1, binary=None):
    """Write prm_text (its output directory must be work/out) to work/run.prm,
    run xcrack on `ranks` MPI ranks and return the rows of statistics.csv.
    `binary` (or the environment's XCRACK_BINARY, for any study): another
    build's xcrack, its libxcrack_core.so beside it, for before/after
    comparisons."""
    prm = os.path.join(work, "run.prm")
    with open(prm, "w") as f:
        f.write(prm_text)
    # Root in containers; one BLAS thread per rank so ranks and threads do
    # not compete for the cores.
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OPENBLAS_NUM_THREADS="1")
    binary = binary or os.environ.get("XCRACK_BINARY")
    if binary:
        env["LD_LIBRARY_PATH"] = os.path.dirname(os.path.abspath(binary))
    command = [binary or xcrack, prm]
    if ranks > 1:
        command = ["mpirun", "-np", str(ranks)] + command
    subprocess.run(command, check=True, env=env, stdout=subprocess.DEVNULL)
    with open(os.path.join(work, "out", "statistics.csv")) as f:
        return list(csv.DictReader(f))


def read_csv(path):
    """The rows of a CSV file of a run (statistics.csv, front_*.csv) as
    dictionaries by column."""
    with open(path) as f:
        return list(csv.DictReader(f))


def number(text, default=float("nan")):
    """A cell as a number; `default` for an empty cell or a text (a
    reason)."""
    try:
        return float(text)
    except (TypeError, ValueError):
        return default


def k_errors(row, digits=3):
    """The K errors of a 3D statistics row against its reference, as text:
    what the timing studies print to show that a faster run solved the same
    problem."""
    return ", ".join(f"{mode} error {float(row[mode + '_error']):.{digits}e}"
                     for mode in ("K_I", "K_II", "K_III"))


def front_file(row, n_meshes):
    """The name of the front file of a statistics row: front_<step>.csv, or
    front_<step>.<mesh>.csv for a step solved on n_meshes > 1 meshes."""
    key = f"{int(row['step']):03d}"
    if n_meshes > 1:
        key += f".{int(row['mesh']):02d}"
    return f"front_{key}.csv"


def run_record(directory):
    """The run record (run.json) of an output directory. Warns on stderr when
    the run did not complete (killed, failed or still running): its files may
    stop short. Returns None for a directory written before run records."""
    path = os.path.join(directory, "run.json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        record = json.load(f)
    if record["status"] != "completed":
        print(f"warning: the run in {directory} is {record['status']}"
              + (f" ({record['reason']})" if record.get("reason") else "")
              + ": its results stop where it stopped.", file=sys.stderr)
    return record


def run_files(directory, regex):
    """The files of the run in `directory` whose names match `regex`, sorted:
    those its run record lists (never a stale file of an earlier run), or
    every matching file for a directory without a record."""
    import re
    record = run_record(directory)
    names = record["files"] if record else os.listdir(directory)
    return sorted(os.path.join(directory, n) for n in names
                  if re.fullmatch(regex, n)
                  and os.path.exists(os.path.join(directory, n)))


def read_vtu(path, arrays=("Points", "connectivity", "offsets")):
    """The named data arrays of a VTU file (XML UnstructuredGrid) as lists
    of numbers: "Points" (the coordinates, x y z after each other),
    "connectivity" and "offsets" of the cells, or a field by its Name.
    Reads the ASCII arrays xcrack's crack files hold and the zlib-compressed
    binary ones deal.II's DataOut writes; nothing beyond Python's standard
    library."""
    import base64
    import re
    import struct
    import zlib
    with open(path) as f:
        text = f.read()
    compressed = 'compressor="vtkZLibDataCompressor"' in text
    sizes = {"Float32": ("f", 4), "Float64": ("d", 8), "Int32": ("i", 4),
             "Int64": ("q", 8), "UInt8": ("B", 1), "UInt32": ("I", 4),
             "UInt64": ("Q", 8)}
    result = {}
    points = re.search(r"<Points>\s*<DataArray([^>]*)>(.*?)</DataArray>",
                       text, re.S)
    found = [("Points",) + points.groups()] if points else []
    for attributes, body in re.findall(r"<DataArray([^>]*)>(.*?)</DataArray>",
                                       text, re.S):
        name = re.search(r'Name="([^"]*)"', attributes)
        if name:
            found.append((name.group(1), attributes, body))
    for name, attributes, body in found:
        if name not in arrays or name in result:
            continue
        kind = re.search(r'type="([^"]*)"', attributes).group(1)
        if 'format="ascii"' in attributes:
            values = [float(v) for v in body.split()]
        else:
            code, size = sizes[kind]
            body = body.strip()
            if compressed:
                # A header of UInt32: blocks, block size, last block size,
                # then each block's compressed size, base64 on its own;
                # then the blocks, base64 together.
                first = base64.b64decode(body[:24])
                n_blocks = struct.unpack("<I", first[:4])[0]
                header_length = 4 * (3 + n_blocks)
                encoded = 4 * ((header_length + 2) // 3)
                header = struct.unpack(f"<{3 + n_blocks}I",
                                       base64.b64decode(body[:encoded]))
                data = base64.b64decode(body[encoded:])
                raw, at = b"", 0
                for block in header[3:]:
                    raw += zlib.decompress(data[at:at + block])
                    at += block
            else:
                raw = base64.b64decode(body)[4:]
            values = list(struct.unpack(f"<{len(raw) // size}{code}", raw))
        result[name] = values
    return result


def body_outline(directory):
    """The boundary of a 2D body as segments ((x0, y0), (x1, y1)), from the
    first solution file of the run (every piece of its .pvtu): the edges of
    its cells that no other cell shares. None without solution files (Output/
    Write vtu = false) or in 3D."""
    import re
    pieces = run_files(directory, r"solution-.*\.vtu")
    if not pieces:
        return None
    first = re.match(r"solution-([0-9.]+)\.[0-9]+\.vtu$",
                     os.path.basename(pieces[0])).group(1)
    count = {}
    for path in pieces:
        if f"solution-{first}." not in os.path.basename(path):
            continue
        data = read_vtu(path)
        xyz = data["Points"]
        if any(abs(z) > 0 for z in xyz[2::3]):
            return None
        point = [(round(xyz[3 * i], 12), round(xyz[3 * i + 1], 12))
                 for i in range(len(xyz) // 3)]
        start = 0
        for end in data["offsets"]:
            cell = [point[int(i)] for i in data["connectivity"][start:int(end)]]
            start = int(end)
            # deal.II's quadrilaterals list their corners in VTK's order,
            # around the cell.
            for a, b in zip(cell, cell[1:] + cell[:1]):
                edge = (min(a, b), max(a, b))
                count[edge] = count.get(edge, 0) + 1
    return [edge for edge, n in count.items() if n == 1]
