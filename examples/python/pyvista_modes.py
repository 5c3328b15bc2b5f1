"""PyVista: the five shading modes side by side on a real mesh, coloured by
an array, drawn by the ShadingLab mapper (python3 with PyVista).

    python3 examples/python/pyvista_modes.py datasets/metaballs_isosurface.vtp Elevation out/pyvista.png

Without an output file it opens a window; with one it draws offscreen. An
array the mesh lacks is made as PyVista makes it (Elevation:
``mesh.elevation()``). On the isosurface's 4,000 triangles flat shows the
facets, Gouraud loses and smears the highlights, fast Phong follows Phong
where the normals vary little, Cook-Torrance's lobe is broader.
"""

import sys

import pyvista

import shadinglab
import shadinglab.pyvista

MODES = [("Flat", {"mode": "flat"}), ("Gouraud", {"mode": "gouraud"}), ("Phong", {"mode": "phong"}),
         ("Fast Phong (Bishop & Weimer)", {"mode": "fast-phong"}),
         ("Cook-Torrance", {"mode": "phong", "model": "cook-torrance", "m": 0.3})]


def main(path, array, out=None):
    mesh = pyvista.read(path)
    if array == "Elevation" and array not in mesh.point_data:
        mesh = mesh.elevation()
    plotter = pyvista.Plotter(shape=(1, len(MODES)), window_size=(1800, 420), off_screen=out is not None)
    for column, (title, settings) in enumerate(MODES):
        plotter.subplot(0, column)
        shadinglab.pyvista.add_mesh(plotter, mesh, material=None, ks=0.3, shininess=40, scalars=array,
                                    cmap="viridis", show_scalar_bar=column == len(MODES) - 1,
                                    scalar_bar_args={"n_labels": 3, "fmt": "%.2f"},
                                    **settings)
        plotter.add_text(title, font_size=11)
        plotter.view_isometric()
    plotter.link_views()
    if out:
        plotter.screenshot(out)
        print("wrote", out)
    else:
        plotter.show()


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "datasets/metaballs_isosurface.vtp",
         sys.argv[2] if len(sys.argv) > 2 else "Elevation",
         sys.argv[3] if len(sys.argv) > 3 else None)
