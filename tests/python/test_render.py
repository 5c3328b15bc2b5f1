"""shadinglab.render and the settings table from Python (no display needed)."""

import json
import os

import numpy
import pytest

import shadinglab
from conftest import cli, dataset, read_png, read_polydata


@pytest.mark.parametrize(
    "mode,material",
    [("flat", "plastic"), ("gouraud", "gold"), ("phong", "copper"), ("fast-phong", None)],
)
def test_render_is_the_command_lines_picture(workdir, mode, material):
    # The torus has no normals: both make them (split at 30 degrees).
    path = dataset("torus_24x12.vtp")
    png = os.path.join(workdir, "cli.png")
    chosen = ["--material", material] if material else []
    status, _, err = cli("render", path, "--backend", "cpu", "--mode", mode, *chosen,
                         "--size", "320x240", "--out", png)
    assert status == 0, err
    image, stats = shadinglab.render(read_polydata(path), mode=mode, material=material, size=(320, 240))
    assert image.shape == (240, 320, 3) and image.dtype == numpy.uint8
    difference = numpy.abs(image.astype(int) - read_png(png).astype(int))
    assert difference.mean() <= 1.0, (mode, material, difference.mean())
    assert stats["mode"] == mode and stats["pixels_covered"] > 10000
    assert stats["normals_computed"] is (mode != "flat")  # flat takes face normals


def test_colour_by_data_is_the_command_lines_picture(workdir):
    path = dataset("terrain.vtp")
    png = os.path.join(workdir, "cli.png")
    status, _, err = cli("render", path, "--backend", "cpu", "--color-by", "Elevation",
                         "--colormap", "Viridis", "--size", "320x240", "--out", png)
    assert status == 0, err
    image, _ = shadinglab.render(read_polydata(path), color_by="Elevation", colormap="Viridis",
                                 size=(320, 240))
    # The command line's PNG carries a legend at its right edge: compared
    # left of it.
    left = slice(0, 240)
    difference = numpy.abs(image[:, left].astype(int) - read_png(png)[:, left].astype(int))
    assert difference.mean() <= 1.0, difference.mean()
    # The colours are the data's: not grey.
    covered = image[:, left].reshape(-1, 3)
    assert numpy.ptp(covered.astype(int), axis=1).max() > 60


def test_bad_keyword_arguments_raise_the_tables_message():
    mesh = read_polydata(dataset("torus_24x12.vtp"))
    for flag, value, kwargs in [("--ks", "2", {"ks": 2}), ("--mode", "wobbly", {"mode": "wobbly"}),
                                ("--light-intensity", "-1", {"light_intensity": -1})]:
        status, _, err = cli("render", dataset("torus_24x12.vtp"), "--backend", "cpu", flag, value,
                             "--out", os.devnull)
        assert status == 2
        # "shadinglab render: error: --ks must be in [0, 1] (got 2)"
        expected = err.strip().split("error: ", 1)[1].replace("--", "", 1)
        with pytest.raises(ValueError) as raised:
            shadinglab.render(mesh, size=(32, 24), **kwargs)
        assert str(raised.value) == expected
    with pytest.raises(ValueError, match="unknown setting 'frobnicate'"):
        shadinglab.render(mesh, frobnicate=1)
    # Requests the table cannot refuse alone: the renderer's one line.
    with pytest.raises(ValueError, match="fast-phong evaluates"):
        shadinglab.render(mesh, mode="fast-phong", model="cook-torrance", size=(32, 24))
    with pytest.raises(ValueError, match="color-by"):
        shadinglab.render(mesh, color_by="NoSuchArray", size=(32, 24))


def test_the_image_is_a_view_of_the_renderers_array():
    # One copy of the frame: the renderer's image into the output vtkImageData.
    # The array returned owns no data; its buffer is that VTK array's.
    image, _ = shadinglab.render(read_polydata(dataset("torus_24x12.vtp")), size=(64, 48))
    assert not image.flags["OWNDATA"]
    base = image
    while isinstance(base.base, numpy.ndarray):
        base = base.base
    assert isinstance(base.base, memoryview)
    assert base.base.obj.GetClassName() == "vtkUnsignedCharArray"
    assert base.base.obj.GetName() == "RGB"


def test_linear_output_and_a_pyvista_free_data_set():
    from vtkmodules.vtkFiltersSources import vtkSphereSource

    sphere = vtkSphereSource()
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(24)
    sphere.Update()
    linear, _ = shadinglab.render(sphere.GetOutput(), output="linear", size=(96, 72))
    assert linear.dtype == numpy.float32 and numpy.isfinite(linear).all()
    # Linear intensities: never negative, above 1 in highlights (the display
    # transform maps them); the background is the command line's.
    assert linear.min() >= 0.0 and linear.max() > 1.0
    with pytest.raises(TypeError):
        shadinglab.render("not a mesh")


def test_settings_are_the_tables():
    rows = shadinglab.settings()
    status, out, _ = cli("settings", "--markdown")
    assert status == 0
    for row in rows:
        assert f"`{row.key}`" in out
    names = {row.name for row in rows}
    assert {"mode", "light_intensity", "color_by", "max_error"} <= names
    # help(shadinglab.render) lists them, as --help lists the flags.
    for row in rows:
        assert row.name in shadinglab.render.__doc__


def test_settings_object_drives_the_mapper_and_the_filters():
    made = shadinglab.make_settings(mode="gouraud", material="gold", ks=0.5)
    assert made.Get("mode") == "gouraud" and made.Get("ks") == "0.5"
    mapper = shadinglab.vtkShadingLabPolyDataMapper()
    mapper.SetSettingsFrom(made)
    assert isinstance(mapper, shadinglab.vtkShadingLabOpenGLPolyDataMapper)
    assert mapper.SetSetting("mode", "phong") and not mapper.SetSetting("mode", "wobbly")
    normals = shadinglab.vtkWeightedPolyDataNormals()
    mesh = read_polydata(dataset("torus_24x12.vtp"))
    normals.SetInputData(mesh)
    normals.SetFeatureAngle(30)
    normals.Update()
    assert normals.GetOutput().GetPointData().GetNormals() is not None
    assert mesh.GetPointData().GetNormals() is None  # the input is not modified


def test_accuracy_returns_a_record_array():
    rows = shadinglab.accuracy(quick=True, backend="cpu")
    assert isinstance(rows, numpy.recarray) and len(rows) > 10
    assert {"shape", "mode", "model", "triangles"} <= set(rows.dtype.names)
    assert set(numpy.unique(rows.backend)) == {"cpu"}
    with pytest.raises(ValueError, match="backend"):
        shadinglab.accuracy(backend="tpu")
