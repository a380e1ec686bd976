"""Run the release xcrack on a parameter text and read its statistics.csv:
the one helper the study and benchmark scripts in contrib/ share."""
import csv
import os
import subprocess

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
xcrack = os.path.join(top, "build", "release", "xcrack")


def run_xcrack(prm_text, work, ranks=1):
    """Write prm_text (its output directory must be work/out) to work/run.prm,
    run xcrack on `ranks` MPI ranks and return the rows of statistics.csv."""
    prm = os.path.join(work, "run.prm")
    with open(prm, "w") as f:
        f.write(prm_text)
    # Root in containers; one BLAS thread per rank so ranks and threads do
    # not compete for the cores.
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OPENBLAS_NUM_THREADS="1")
    command = [xcrack, prm]
    if ranks > 1:
        command = ["mpirun", "-np", str(ranks)] + command
    subprocess.run(command, check=True, env=env, stdout=subprocess.DEVNULL)
    with open(os.path.join(work, "out", "statistics.csv")) as f:
        return list(csv.DictReader(f))


def front_file(row, n_meshes):
    """The name of the front file of a statistics row: front_<step>.csv, or
    front_<step>.<mesh>.csv for a step solved on n_meshes > 1 meshes."""
    key = f"{int(row['step']):03d}"
    if n_meshes > 1:
        key += f".{int(row['mesh']):02d}"
    return f"front_{key}.csv"
