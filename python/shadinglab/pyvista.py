"""ShadingLab in PyVista: add_mesh draws a mesh with the ShadingLab mapper.

What of PyVista's own ``Plotter.add_mesh`` carries over: ``scalars`` (a
point or cell array's name, or an array of values), ``cmap`` (a Matplotlib
or PyVista colour map name), ``clim``, ``show_scalar_bar``, ``scalar_bar_args``, ``opacity``,
``color`` (the albedo without scalars), ``name``, ``reset_camera``. What
does not: ``style`` (the surface is drawn; no wireframe or points), the
lighting keywords (``ambient``, ``diffuse``, ``specular``, ``smooth_shading``,
``pbr``: the material and mode settings replace them; the property is
interpolated Gouraud so that VTK uploads the normals), ``show_edges``,
``texture``. Anything else is a ShadingLab setting (the settings table).
"""

from typing import Any, Optional

from ._table import apply, help_text
from .shadinglabRenderVTK import vtkShadingLabSettings
from .shadinglabVTK import vtkShadingLabPolyDataMapper


def add_mesh(plotter: Any, mesh: Any, mode: str = "gouraud", material: Optional[str] = "gold",
             scalars: Any = None, cmap: Any = None, clim: Any = None, color: Any = None,
             opacity: float = 1.0, show_scalar_bar: Optional[bool] = None,
             scalar_bar_args: Optional[dict] = None, name: Optional[str] = None,
             reset_camera: Optional[bool] = None, **settings: Any):
    """Adds ``mesh`` to ``plotter``, drawn by vtkShadingLabPolyDataMapper.

    Returns the actor (a pyvista.Actor). ``mode``, ``material`` and the
    other keyword arguments are settings of the table (below); ``scalars``,
    ``cmap``, ``clim`` colour the surface by data as PyVista does, the
    colour scaled by the shading. Raises ValueError for a refused setting.

    Settings (the settings table):
    """
    import numpy
    import pyvista

    surface = pyvista.wrap(mesh)
    if not isinstance(surface, pyvista.PolyData):
        surface = surface.extract_surface()
    made = vtkShadingLabSettings()
    apply(made, mode=mode, material=material, **settings)
    mapper = vtkShadingLabPolyDataMapper()
    mapper.SetSettingsFrom(made)
    mapper.SetInputData(surface)
    mapper.ScalarVisibilityOff()
    title = None
    if scalars is not None:
        if isinstance(scalars, str):
            title = scalars
        else:
            title = "Data"
            values = numpy.asarray(scalars)
            if values.shape[0] == surface.n_points:
                surface.point_data[title] = values
            elif values.shape[0] == surface.n_cells:
                surface.cell_data[title] = values
            else:
                raise ValueError("scalars: one value per point or per cell")
        if title in surface.point_data:
            mapper.SetScalarModeToUsePointFieldData()
            data = surface.point_data[title]
        elif title in surface.cell_data:
            mapper.SetScalarModeToUseCellFieldData()
            data = surface.cell_data[title]
        else:
            raise ValueError(f"scalars: no point or cell array '{title}' (there are "
                             f"{', '.join(list(surface.point_data) + list(surface.cell_data)) or 'none'})")
        mapper.SelectColorArray(title)
        mapper.ScalarVisibilityOn()
        low, high = (numpy.nanmin(data), numpy.nanmax(data)) if clim is None else clim
        table = pyvista.LookupTable(cmap=cmap or pyvista.global_theme.cmap)
        table.scalar_range = (float(low), float(high))
        mapper.SetLookupTable(table)
        mapper.SetUseLookupTableScalarRange(True)
    actor = pyvista.Actor(mapper=mapper)
    # PyVista's properties are interpolated Flat unless smooth_shading; VTK
    # then uploads no point normals, which every ShadingLab mode but flat
    # needs (the mode, not the property, decides the shading).
    actor.prop.interpolation = "gouraud"
    if color is not None:
        actor.prop.color = color
    actor.prop.opacity = opacity
    plotter.add_actor(actor, name=name, reset_camera=reset_camera)
    if title is not None and (show_scalar_bar is None or show_scalar_bar):
        plotter.add_scalar_bar(**dict({"title": title, "mapper": mapper}, **(scalar_bar_args or {})))
    return actor


add_mesh.__doc__ = (add_mesh.__doc__ or "") + "\n" + help_text() + "\n"
