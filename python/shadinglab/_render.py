"""shadinglab.render: the CPU renderer's picture as a NumPy array."""

import json
from typing import Any, Dict, Optional, Tuple

from .shadinglabCPUVTK import vtkSoftwareShadingRenderer
from ._table import apply, help_text
from .shadinglabRenderVTK import vtkShadingLabSettings


def _polydata(mesh: Any):
    """A vtkPolyData for any VTK data set (a PyVista mesh is one): its surface."""
    from vtkmodules.vtkCommonDataModel import vtkDataSet, vtkPolyData

    if isinstance(mesh, vtkPolyData):
        return mesh
    if isinstance(mesh, vtkDataSet):
        from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter

        surface = vtkGeometryFilter()
        surface.SetInputData(mesh)
        surface.Update()
        return surface.GetOutput()
    raise TypeError(f"mesh must be a vtkPolyData or another VTK data set (a PyVista mesh), not {type(mesh).__name__}")


def render(
    mesh: Any,
    mode: Optional[str] = None,
    material: Optional[str] = None,
    size: Tuple[int, int] = (640, 480),
    camera: Any = None,
    output: str = "display",
    **settings: Any,
) -> Tuple["numpy.ndarray", Dict[str, Any]]:  # noqa: F821
    """Renders ``mesh`` with the CPU renderer; returns (image, stats).

    mesh      a vtkPolyData, or any VTK data set or PyVista mesh (its surface)
    mode      flat, gouraud, phong, fast-phong or auto (Cook-Torrance is the
              material's model: model="cook-torrance")
    material  a preset (gold, copper, plastic, ...), as --material
    size      (width, height) in pixels
    camera    a vtkCamera; None fits the view to the mesh, as the command line
    output    "display": H x W x 3 uint8, the display image (the command
              line's PNG); "linear": H x W x 3 float32, linear intensities
    settings  any key of the settings table (below), ``-`` spelt ``_``

    The image's row 0 is the top of the picture. It is a view of the
    renderer's output array (no copy after the one the renderer makes);
    the stats are the command line's ``render --stats`` keys. Without
    normals, a smooth mode draws weighted normals split at the feature
    angle, as the command line, so the picture is the command line's for
    the same settings. Raises ValueError (the settings table's one-line
    message) for a refused setting or request (fast-phong with a
    Cook-Torrance material, no such array to colour by) and RuntimeError
    when the render fails.

    Settings (the settings table):
    """
    import numpy
    from vtkmodules.util.numpy_support import vtk_to_numpy

    if output not in ("display", "linear"):
        raise ValueError(f"output must be display or linear (got '{output}')")
    width, height = (int(v) for v in size)
    made = vtkShadingLabSettings()
    apply(made, mode=mode, material=material, **settings)
    renderer = vtkSoftwareShadingRenderer()
    renderer.SetInputData(_polydata(mesh))
    renderer.SetSize(width, height)
    renderer.SetSettings(made)
    if camera is not None:
        renderer.SetCamera(camera)
    renderer.Update()
    error = renderer.GetLastError()
    if error:
        raise (ValueError if renderer.GetLastErrorIsRequest() else RuntimeError)(error)
    image = renderer.GetOutput()
    array = image.GetPointData().GetArray("RGB" if output == "display" else "LinearRGB")
    # A view of the VTK array (it keeps the array alive), rows turned over:
    # VTK's row 0 is the bottom, an image's the top.
    pixels = vtk_to_numpy(array).reshape(height, width, 3)[::-1]
    stats = json.loads(renderer.GetLastStatsJson())
    stats.update(width=width, height=height)
    return pixels, stats


render.__doc__ = (render.__doc__ or "") + "\n" + help_text() + "\n"
