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
