"""The five shading modes of one mesh with shadinglab.render, under pvpython.

    pvpython examples/python/render_modes.py datasets/torus_48x24.vtp out/modes.png

No display needed: the CPU renderer draws, as `shadinglab render --backend
cpu` does (the same picture for the same settings). The panels are written
side by side, titled with their mode and render time (with matplotlib;
without it, untitled, in the order flat, gouraud, phong, fast-phong,
cook-torrance).
"""

import sys

import numpy
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

import shadinglab

MODES = [("flat", {}), ("gouraud", {}), ("phong", {}), ("fast-phong", {}),
         ("phong", {"model": "cook-torrance", "m": 0.3})]


def write_png(strip, out):
    """An H x W x 3 uint8 array (row 0 the top) as a PNG, through VTK."""
    picture = vtkImageData()
    picture.SetDimensions(strip.shape[1], strip.shape[0], 1)
    picture.GetPointData().SetScalars(numpy_to_vtk(numpy.ascontiguousarray(strip[::-1]).reshape(-1, 3)))
    writer = vtkPNGWriter()
    writer.SetFileName(out)
    writer.SetInputData(picture)
    writer.Write()


def main(path, out):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    panels, titles = [], []
    for mode, extra in MODES:
        image, stats = shadinglab.render(reader.GetOutput(), mode=mode, size=(400, 300), **extra)
        name = "cook-torrance" if extra else mode
        print(f"{name:14s} {stats['milliseconds']:7.1f} ms  {stats['pixels_covered']} pixels")
        panels.append(image)
        titles.append(f"{name} ({stats['milliseconds']:.1f} ms)")
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        plt = None
    if plt is not None:
        figure, axes = plt.subplots(1, len(panels), figsize=(3.2 * len(panels), 2.9), dpi=110)
        for ax, image, title in zip(axes, panels, titles):
            ax.imshow(image)
            ax.set_title(title, fontsize=10)
            ax.axis("off")
        figure.suptitle(f"ShadingLab: {path.split('/')[-1]} in each mode (CPU renderer, "
                        "shadinglab.render)", fontsize=11)
        figure.tight_layout()
        figure.savefig(out)
    else:
        write_png(numpy.concatenate(panels, axis=1), out)
    print("wrote", out)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "datasets/torus_48x24.vtp",
         sys.argv[2] if len(sys.argv) > 2 else "modes.png")
