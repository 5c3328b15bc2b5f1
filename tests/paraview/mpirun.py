# SPDX-License-Identifier: BSD-3-Clause
"""Running a pvbatch worker on N MPI ranks from a pvpython driver."""
import os
import subprocess


def clean_environment():
    """os.environ without Open MPI's variables: pvpython initialized MPI as a
    singleton, and its variables must not reach an mpiexec it starts."""
    return {k: v for k, v in os.environ.items() if not k.startswith(('OMPI_', 'PMIX_', 'OPAL_'))}


def pvbatch_on_ranks(ranks, script, *args):
    """Runs `pvbatch script --worker args...` on `ranks` MPI ranks (offscreen);
    raises CalledProcessError on failure."""
    subprocess.run(['mpiexec', '--allow-run-as-root', '--oversubscribe', '-n', str(ranks),
                    'pvbatch', '--force-offscreen-rendering', os.path.abspath(script),
                    '--worker'] + [str(a) for a in args], check=True, timeout=600,
                   env=clean_environment())
