#!/usr/bin/python3
# Colour by data, measured on three coloured meshes (issue: highlights that
# read as data, faces left black by one light):
#  - the colour-fidelity fraction (docs/model.md eq. 9.3: covered pixels
#    whose colour is not shade x map(value)), from `shadinglab render
#    --stats`, for the default picture and for the previous default (its
#    material with highlights and grey ambient, one key light: reproduced
#    with --highlights on and --light at the old key light's direction);
#  - the mean luminance of the CLI's picture against ParaView's Surface of
#    the same data and camera (pvpython, its default light kit and Cool to
#    Warm), over the pixels both cover, the CLI's legend excluded.
#
#   bench/color_fidelity.py BUILD_DIR OUT_DIR
#
# The meshes: the README's engine head scan coloured by Elevation (when
# scripts/real-mesh-picture has written out/head_elevation.vtp), the
# shipped terrain, the metaballs isosurface coloured by its normal's z, and
# ParaView's Wavelet contoured at 157 coloured by Elevation (written here).
#
# Prints a Markdown table; writes the PNGs to OUT_DIR.
import json
import math
import os
import subprocess
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

SIZE = (800, 600)
AZIMUTH, ELEVATION = 30.0, -50.0


def wavelet_isosurface(path):
    """ParaView's Wavelet source, contoured at 157, coloured by Elevation."""
    src = vtk.vtkRTAnalyticSource()
    src.SetWholeExtent(-20, 20, -20, 20, -20, 20)
    contour = vtk.vtkContourFilter()
    contour.SetInputConnection(src.GetOutputPort())
    contour.SetValue(0, 157.0)
    contour.ComputeScalarsOff()
    elevation = vtk.vtkElevationFilter()
    elevation.SetInputConnection(contour.GetOutputPort())
    elevation.SetLowPoint(0, 0, -20)
    elevation.SetHighPoint(0, 0, 20)
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetInputConnection(elevation.GetOutputPort())
    writer.SetFileName(path)
    writer.Write()


def fit_camera(bounds):
    """render::FitCamera (plugin/render/src/Scene.cpp) for SIZE's aspect."""
    b = np.array(bounds).reshape(3, 2)
    center = b.mean(axis=1)
    radius = 0.5 * np.linalg.norm(b[:, 1] - b[:, 0])
    half = math.radians(15.0)
    distance = radius / math.sin(half)
    az, el = math.radians(AZIMUTH), math.radians(ELEVATION)
    d = np.array([math.sin(az) * math.cos(el), math.sin(el), math.cos(az) * math.cos(el)])
    right = np.cross([0, 1, 0], d)
    right /= np.linalg.norm(right)
    up = np.cross(d, right)
    return center, center + d * distance, up / np.linalg.norm(up), d


def old_key_light(bounds):
    """render::KeyLight of the previous default: toEye + up/2 - 0.4 right."""
    _, _, up, d = fit_camera(bounds)
    forward = -d
    right = np.cross(forward, up)
    right /= np.linalg.norm(right)
    up_b = np.cross(right, forward)
    key = d + 0.5 * up_b - 0.4 * right
    return key / np.linalg.norm(key)


def bounds_of(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput().GetBounds()


def cli(build, path, array, out, extra):
    cmd = [os.path.join(build, 'bin', 'shadinglab'), 'render', path, '--color-by', array,
           '--azimuth', str(AZIMUTH), '--elevation', str(ELEVATION),
           '--size', '%dx%d' % SIZE, '--backend', 'cpu', '--stats', '--out', out] + extra
    done = subprocess.run(cmd, check=True, capture_output=True, text=True)
    return json.loads(done.stdout)['color_fidelity']['fraction']


PARAVIEW = r'''
import sys
from paraview.simple import *
path, array, component, out = sys.argv[1:5]
cam = [float(v) for v in sys.argv[5:14]]
reader = XMLPolyDataReader(FileName=[path])
view = CreateView('RenderView')
view.ViewSize = [%d, %d]
view.OrientationAxesVisibility = 0
view.Background = [0.0, 0.0, 0.0]
if hasattr(view, 'UseColorPaletteForBackground'):
    view.UseColorPaletteForBackground = 0
display = Show(reader, view)
ColorBy(display, ('POINTS', array) if component == '-1' else ('POINTS', array, 'Z'))
display.RescaleTransferFunctionToDataRange(True)
view.CameraPosition = cam[0:3]
view.CameraFocalPoint = cam[3:6]
view.CameraViewUp = cam[6:9]
view.CameraViewAngle = 30.0
Render(view)  # the render view fits the clipping range to the data itself
SaveScreenshot(out, view, ImageResolution=[%d, %d])
''' % (SIZE + SIZE)


def read_png(path):
    reader = vtk.vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    rgb = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3]
    return rgb[::-1].astype(np.float64) / 255.0  # row 0 at the top


def luminance(rgb):
    """Rec. 709 luma of the 8-bit values as written (what a viewer shows)."""
    return rgb @ np.array([0.2126, 0.7152, 0.0722])


def main():
    build, out = sys.argv[1:3]
    os.makedirs(out, exist_ok=True)
    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    wavelet = os.path.join(out, 'wavelet_isosurface.vtp')
    wavelet_isosurface(wavelet)
    meshes = []
    head = os.path.join(here, 'out', 'head_elevation.vtp')  # scripts/real-mesh-picture writes it
    if os.path.exists(head):
        meshes.append(('engine head scan (OCCT head.stl, 117,694 triangles)', head, 'Elevation', -1))
    meshes += [('terrain.vtp', os.path.join(here, 'datasets', 'terrain.vtp'), 'Elevation', -1),
              ('metaballs_isosurface.vtp', os.path.join(here, 'datasets', 'metaballs_isosurface.vtp'),
               'ExactNormal', 2),
              ('Wavelet isosurface', wavelet, 'Elevation', -1)]
    script = os.path.join(out, 'paraview_surface.py')
    with open(script, 'w') as f:
        f.write(PARAVIEW)
    import platform
    commit = subprocess.run(['git', '-C', here, 'rev-parse', '--short', 'HEAD'],
                            capture_output=True, text=True).stdout.strip()
    dirty = subprocess.run(['git', '-C', here, 'status', '--porcelain', '--untracked-files=no'],
                           capture_output=True, text=True).stdout.strip()
    cpu = next((l.split(':', 1)[1].strip() for l in open('/proc/cpuinfo') if l.startswith('model name')), '?')
    print('Written by `bench/color_fidelity.py`; do not edit. Measured on %s, %d cores, %s; '
          'date %s, commit %s%s.\n' % (cpu, os.cpu_count(), platform.platform(),
                                        subprocess.run(['date', '+%Y-%m-%d'], capture_output=True,
                                                       text=True).stdout.strip(),
                                        commit, ' with uncommitted changes' if dirty else ''))
    print('| mesh, colour by | fidelity before | fidelity after | mean luminance: ParaView | '
          'CLI before | CLI after |')
    print('|---|---|---|---|---|---|')
    for name, path, array, component in meshes:
        spelled = array if component < 0 else '%s:%d' % (array, component)
        bounds = bounds_of(path)
        key = old_key_light(bounds)
        stem = os.path.join(out, os.path.splitext(os.path.basename(path))[0])
        after = cli(build, path, spelled, stem + '-after.png', [])
        before = cli(build, path, spelled, stem + '-before.png',
                     ['--highlights', 'on', '--light', 'dir:%.9g,%.9g,%.9g' % tuple(key)])
        focal, position, up, _ = fit_camera(bounds)
        subprocess.run(['pvpython', script, path, array, str(component), stem + '-paraview.png'] +
                       ['%.12g' % v for v in list(position) + list(focal) + list(up)],
                       check=True, capture_output=True)
        pv = read_png(stem + '-paraview.png')
        mask = pv.sum(axis=2) > 0  # ParaView's background is black
        mask[:, int(0.75 * SIZE[0]):] = False  # the CLI's legend
        lum = {k: luminance(read_png(stem + '-%s.png' % k))[mask].mean()
               for k in ('before', 'after')}
        lum_pv = luminance(pv)[mask].mean()
        print('| %s, %s | %.1f %% | %.2f %% | %.3f | %.3f (%+.0f %%) | %.3f (%+.0f %%) |' % (
            name, spelled, 100 * before, 100 * after, lum_pv,
            lum['before'], 100 * (lum['before'] / lum_pv - 1),
            lum['after'], 100 * (lum['after'] / lum_pv - 1)))


if __name__ == '__main__':
    main()
