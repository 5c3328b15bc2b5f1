"""shadinglab.accuracy: the time-against-error study as a NumPy record array."""

import os
import shutil
import subprocess
import tempfile
from typing import Optional


def _executable() -> str:
    """The shadinglab command: $SHADINGLAB_EXE, the build tree's, or PATH's."""
    given = os.environ.get("SHADINGLAB_EXE")
    if given:
        return given
    here = os.path.dirname(os.path.abspath(__file__))
    # build/lib/python3/dist-packages/shadinglab -> build/bin/shadinglab
    built = os.path.normpath(os.path.join(here, "..", "..", "..", "..", "bin", "shadinglab"))
    if os.access(built, os.X_OK):
        return built
    found = shutil.which("shadinglab")
    if not found:
        raise RuntimeError("the shadinglab command was not found (set SHADINGLAB_EXE or PATH)")
    return found


def accuracy(quick: bool = True, backend: str = "cpu", size: Optional[str] = None,
             frames: Optional[int] = None, threads: Optional[int] = None):
    """Runs the time-against-error study (``shadinglab accuracy``).

    Every shape, level, mode and model against the exact surfaces, as
    docs/accuracy.md measures it; ``quick`` runs the command's small
    version. Returns its rows as a NumPy record array, one field a column
    of its accuracy.csv (shape, level, triangles, backend, mode, model,
    normals, ..., frame_ms, mean_255, rmse_255, p99_255, max_255, ...:
    docs/accuracy.md). Raises ValueError with the command's one-line
    message for a refused argument.
    """
    import numpy

    with tempfile.TemporaryDirectory() as out:
        command = [_executable(), "accuracy", "--backend", backend, "--out", out]
        if quick:
            command.append("--quick")
        for flag, value in (("--size", size), ("--frames", frames), ("--threads", threads)):
            if value is not None:
                command += [flag, str(value)]
        done = subprocess.run(command, capture_output=True, text=True)
        if done.returncode == 2:
            raise ValueError(done.stderr.strip().splitlines()[-1] if done.stderr.strip() else "refused")
        if done.returncode != 0:
            raise RuntimeError(f"shadinglab accuracy failed ({done.returncode}): {done.stderr.strip()}")
        table = os.path.join(out, "accuracy.csv")
        if not os.path.exists(table):
            raise RuntimeError("shadinglab accuracy wrote no accuracy.csv")
        return numpy.genfromtxt(table, delimiter=",", names=True, dtype=None,
                                encoding="utf-8").view(numpy.recarray)
