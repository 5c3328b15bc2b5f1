"""ShadingLab from Python.

The VTK classes, wrapped by VTK's own wrapping (the VTK modules of
plugin/ and mesh/):

- ``vtkShadingLabPolyDataMapper`` (and its composite) under any vtkActor;
- ``vtkSoftwareShadingRenderer``, the CPU renderer as a VTK image algorithm;
- ``vtkWeightedPolyDataNormals``, ``vtkMeshRepair``, ``vtkOpenSubdivRefine``;
- ``vtkShadingLabSettings``, every setting by the settings table's keys.

and a thin layer on top:

- ``render(mesh, mode=..., material=..., size=(w, h), **settings)``: the CPU
  renderer's picture as a NumPy array, and its statistics;
- ``settings()``: the settings table; keyword arguments are checked by it;
- ``accuracy(...)``: the time-against-error study as a NumPy record array;
- ``shadinglab.pyvista.add_mesh(plotter, mesh, ...)``: a PyVista actor drawn
  by the ShadingLab mapper.

It imports in the Python of the VTK it was built against: pvpython and
pvbatch on Debian 12, python3 (with python3-vtk9, PyVista) and pvpython on
Debian 13 and unstable. See docs/python.md.
"""

from .shadinglabRenderVTK import vtkShadingLabSettings
from .shadinglabMesh import vtkMeshRepair, vtkOpenSubdivRefine, vtkWeightedPolyDataNormals
from .shadinglabCPUVTK import vtkSoftwareShadingRenderer
from .shadinglabGL import vtkShadingLabOpenGLPolyDataMapper
from .shadinglabVTK import vtkShadingLabCompositePolyDataMapper, vtkShadingLabPolyDataMapper

from ._table import Setting, make_settings, settings
from ._render import render
from ._study import accuracy

__all__ = [
    "vtkShadingLabSettings",
    "vtkMeshRepair",
    "vtkOpenSubdivRefine",
    "vtkWeightedPolyDataNormals",
    "vtkSoftwareShadingRenderer",
    "vtkShadingLabOpenGLPolyDataMapper",
    "vtkShadingLabPolyDataMapper",
    "vtkShadingLabCompositePolyDataMapper",
    "Setting",
    "make_settings",
    "settings",
    "render",
    "accuracy",
]
