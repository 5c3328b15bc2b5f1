"""Helpers of the Python package's tests: the command line, the datasets, PNGs.

Run by ctest (tests/CMakeLists.txt) under pvpython and, where the VTK has
PyVista beside it (Debian unstable), under python3, with PYTHONPATH at the
build tree's package, SHADINGLAB_EXE the command line and
SHADINGLAB_SOURCE_DIR the source tree.
"""

import os
import subprocess

import numpy
import pytest

SOURCE = os.environ.get("SHADINGLAB_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
EXE = os.environ.get("SHADINGLAB_EXE", "shadinglab")


def dataset(name):
    return os.path.join(SOURCE, "datasets", name)


def read_polydata(path):
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def read_png(path):
    """H x W x 3 uint8, row 0 the top."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader

    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)
    return numpy.ascontiguousarray(pixels[::-1, :, :3])


def cli(*args, env=None):
    """Runs the command line; returns (status, stdout, stderr)."""
    done = subprocess.run([EXE, *args], capture_output=True, text=True, env=env)
    return done.returncode, done.stdout, done.stderr


@pytest.fixture
def workdir(tmp_path):
    return str(tmp_path)
