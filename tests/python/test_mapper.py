"""The mapper under a VTK actor, and in PyVista (needs an X display)."""

import os

import numpy
import pytest

import shadinglab
from conftest import dataset, read_polydata


def grab(window):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

    grabber = vtkWindowToImageFilter()
    grabber.SetInput(window)
    grabber.ReadFrontBufferOff()
    grabber.Update()
    image = grabber.GetOutput()
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[::-1, :, :3].copy()


def plain_vtk_picture(mesh, settings, camera, size, lookup=None, array=None):
    """Our mapper in a plain VTK pipeline: one renderer, its headlight."""
    from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderWindow, vtkRenderer
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factory)

    mapper = shadinglab.vtkShadingLabPolyDataMapper()
    mapper.SetSettingsFrom(settings)
    mapper.SetInputData(mesh)
    mapper.ScalarVisibilityOff()
    if lookup is not None:
        mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectColorArray(array)
        mapper.ScalarVisibilityOn()
        mapper.SetLookupTable(lookup)
        mapper.SetUseLookupTableScalarRange(True)
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0, 0, 0)
    if camera is not None:
        renderer.GetActiveCamera().DeepCopy(camera)
    else:
        renderer.ResetCamera()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    window.Render()
    return grab(window), mapper


@pytest.mark.skipif(not os.environ.get("DISPLAY"), reason="needs an X display (ctest runs it under Xvfb)")
def test_mapper_under_an_actor_draws_the_settings():
    mesh = read_polydata(dataset("torus_24x12.vtp"))
    settings = shadinglab.make_settings(mode="gouraud", material="gold")
    picture, mapper = plain_vtk_picture(mesh, settings, None, (320, 240))
    assert mapper.GetDrawnMode() == shadinglab.vtkShadingLabPolyDataMapper.GOURAUD
    assert mapper.GetBackendChoice() == "gpu"
    covered = picture.sum(axis=2) > 0
    assert covered.mean() > 0.1
    # Gold: red above green above blue where lit.
    lit = picture[covered].astype(int)
    assert lit[:, 0].mean() > lit[:, 1].mean() > lit[:, 2].mean()


@pytest.mark.parametrize("mode", ["flat", "gouraud", "phong", "fast-phong"])
def test_pyvista_add_mesh_is_the_mappers_vtk_picture(mode):
    if not os.environ.get("DISPLAY"):
        pytest.skip("needs an X display (ctest runs it under Xvfb)")
    if os.environ.get("SHADINGLAB_REQUIRE_PYVISTA") == "1":
        import pyvista
    else:
        pyvista = pytest.importorskip("pyvista")
    import shadinglab.pyvista
    mesh = pyvista.read(dataset("terrain.vtp"))
    plotter = pyvista.Plotter(off_screen=True, window_size=(320, 240), lighting="none")
    plotter.add_light(pyvista.Light(light_type="headlight"))
    plotter.set_background("black")
    plotter.ren_win.SetMultiSamples(0)
    plotter.disable_anti_aliasing()
    actor = shadinglab.pyvista.add_mesh(plotter, mesh, mode=mode, material="plastic",
                                        scalars="Elevation", cmap="viridis", show_scalar_bar=False)
    assert isinstance(actor.GetMapper(), shadinglab.vtkShadingLabPolyDataMapper)
    plotter.reset_camera()
    shot = plotter.screenshot(return_img=True)[:, :, :3]
    camera = plotter.renderer.GetActiveCamera()
    settings = shadinglab.make_settings(mode=mode, material="plastic")
    lookup = pyvista.LookupTable(cmap="viridis")
    lookup.scalar_range = (float(mesh["Elevation"].min()), float(mesh["Elevation"].max()))
    reference, _ = plain_vtk_picture(mesh, settings, camera, (320, 240), lookup, "Elevation")
    plotter.close()
    assert shot.shape == reference.shape
    difference = numpy.abs(shot.astype(int) - reference.astype(int))
    assert difference.mean() <= 1.0, (mode, difference.mean())
    # Both drew the surface (PyVista's Flat-interpolated property once drew
    # the smooth modes blank: no normals uploaded).
    assert (reference.sum(axis=2) > 0).mean() > 0.1
    assert (shot.sum(axis=2) > 0).mean() > 0.1
    with pytest.raises(ValueError, match="ks must be in"):
        shadinglab.pyvista.add_mesh(pyvista.Plotter(off_screen=True), mesh, ks=3)
