# Smooth shading on 2 MPI ranks equals 1 rank for irregular meshes without
# normals, shown directly as ShadingLab Surface (no Normals filter): the
# representation must make normals that see every face around a partition
# boundary vertex. Meshes are generated here (none has normals): a
# decimated noisy sphere (non-uniform triangles), a marching-cubes
# isosurface (slivers) and a scan-like height field with sliver triangles
# (open, random diagonals), and the sphere and the scan again with a third of
# their triangles reversed at random (inconsistent orientation: one rank
# turns them back as the whole mesh would be, DistributedOrientation.h; on
# one rank they must draw as the intact mesh does, mean <= 1/255 and p99 <=
# 2/255, and the same on 2 ranks). Each is split by RedistributeDataSet and drawn
# coloured by Elevation in Gouraud, Phong and fast Phong (Blinn-Phong) and
# Phong/Cook-Torrance, with the default normals (split at 30 degrees), on
# both backends (Backend GPU and CPU: the CPU's colour and depth go through
# IceT's compositing like the GL path's); 2 ranks against 1 rank: mean <=
# 1/255 and p99 <= 2/255 of the covered pixels' channels; CPU against GPU
# on 1 rank within the parity thresholds (mean <= 1/255, p99 <= 4/255).
# Pipelines with ghost cells (a GhostCellsGenerator after RedistributeDataSet,
# as ParaView users add one) go the same way: the sphere shown directly
# (ParaView's geometry filter hands the representation no ghost cells: it
# borrows faces) and through the ShadingLab Normals filter, which sees the
# ghost faces and uses them; the reversed scan through
# the filter, which drops them (their orientation would need their owners)
# and borrows its neighbours' faces instead (vtkShadingLabNormals.cxx). On 2
# ranks their surfaces must carry ghost cells, or the branch went untested.
#
#   pvpython MpiSeamTest.py PLUGIN OUTDIR       (the driver; runs mpiexec)
#   pvbatch MpiSeamTest.py --worker PLUGIN DIR  (one run, on rank 0)
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pngs import read_png  # noqa: E402
from mpirun import pvbatch_on_ranks  # noqa: E402

W, H = 400, 300
MESHES = ('noisy_sphere', 'isosurface', 'scan', 'noisy_sphere_reversed', 'scan_reversed',
          'noisy_sphere_ghosts', 'noisy_sphere_ghosts_filter', 'scan_reversed_ghosts_filter')
GHOSTS = '_ghosts'
FILTER = '_filter'


def source_of(name):
    """The mesh file a test mesh reads: its name without the pipeline's suffixes."""
    return name.replace(FILTER, '').replace(GHOSTS, '')
MODES = (('Gouraud', 'Blinn-Phong'), ('Phong', 'Blinn-Phong'), ('Fast Phong', 'Blinn-Phong'),
         ('Phong', 'Cook-Torrance'))
BACKENDS = ('GPU', 'CPU')


def png_name(name, mode, model, backend):
    return '%s_%s_%s_%s.png' % (name, mode.replace(' ', ''), model, backend)


def make_meshes(outdir):
    """Writes the three meshes (no normals) into outdir."""
    import random
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkFiltersCore import vtkDecimatePro, vtkTriangleFilter, vtkFlyingEdges3D
    from vtkmodules.vtkImagingHybrid import vtkSampleFunction
    from vtkmodules.vtkCommonDataModel import vtkQuadric, vtkPolyData, vtkCellArray
    from vtkmodules.vtkCommonCore import vtkPoints, vtkIdList
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

    def write(poly, name):
        poly.GetPointData().SetNormals(None)
        writer = vtkXMLPolyDataWriter()
        writer.SetFileName(os.path.join(outdir, name + '.vtp'))
        writer.SetInputData(poly)
        writer.Write()

    def write_reversed(poly, name):
        """`poly` with a third of its triangles (never the first) reversed."""
        flips = random.Random(11)
        cells = vtkCellArray()
        polys = poly.GetPolys()
        for c in range(poly.GetNumberOfPolys()):
            ids = vtkIdList()
            polys.GetCellAtId(c, ids)
            corners = [ids.GetId(k) for k in range(ids.GetNumberOfIds())]
            if c > 0 and flips.random() < 1.0 / 3.0:
                corners.reverse()
            cells.InsertNextCell(len(corners), corners)
        reversed_poly = vtkPolyData()
        reversed_poly.ShallowCopy(poly)
        reversed_poly.SetPolys(cells)
        write(reversed_poly, name)

    rng = random.Random(7)
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(120)
    sphere.SetPhiResolution(60)
    sphere.Update()
    noisy = vtkPolyData()
    noisy.DeepCopy(sphere.GetOutput())
    points = noisy.GetPoints()
    for i in range(points.GetNumberOfPoints()):
        p = points.GetPoint(i)
        s = 1.0 + rng.uniform(-0.01, 0.01)
        points.SetPoint(i, p[0] * s, p[1] * s, p[2] * s)
    decimate = vtkDecimatePro()
    decimate.SetInputData(noisy)
    decimate.SetTargetReduction(0.7)
    decimate.PreserveTopologyOn()
    decimate.Update()
    write(decimate.GetOutput(), 'noisy_sphere')
    write_reversed(decimate.GetOutput(), 'noisy_sphere_reversed')

    quadric = vtkQuadric()
    quadric.SetCoefficients(1, 2, 0.5, 0.3, 0, 0.2, 0, 0, 0, 0)
    sample = vtkSampleFunction()
    sample.SetImplicitFunction(quadric)
    sample.SetSampleDimensions(40, 40, 40)
    sample.SetModelBounds(-1, 1, -1, 1, -1, 1)
    contour = vtkFlyingEdges3D()
    contour.SetInputConnection(sample.GetOutputPort())
    contour.SetValue(0, 0.5)
    contour.ComputeNormalsOff()
    contour.ComputeGradientsOff()
    contour.Update()
    write(contour.GetOutput(), 'isosurface')

    import math
    n = 48
    scan_points, cells = vtkPoints(), vtkCellArray()
    for j in range(n):
        for i in range(n):
            # Columns bunched together (slivers) and a bumpy height.
            x = (i / (n - 1)) ** 1.7 * 2 - 1 + rng.uniform(-0.002, 0.002)
            y = j / (n - 1) * 2 - 1
            z = 0.25 * math.sin(3 * x) * math.cos(2 * y) + rng.uniform(-0.004, 0.004)
            scan_points.InsertNextPoint(x, y, z)
    for j in range(n - 1):
        for i in range(n - 1):
            a, b, c, d = j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i
            if rng.random() < 0.5:
                cells.InsertNextCell(3, (a, b, c))
                cells.InsertNextCell(3, (a, c, d))
            else:
                cells.InsertNextCell(3, (a, b, d))
                cells.InsertNextCell(3, (b, c, d))
    scan = vtkPolyData()
    scan.SetPoints(scan_points)
    scan.SetPolys(cells)
    write(scan, 'scan')
    write_reversed(scan, 'scan_reversed')


def worker(plugin, directory):
    import paraview.simple
    from paraview.simple import (LoadPlugin, OpenDataFile, RedistributeDataSet, ExtractSurface,
                                 Elevation, CreateView, Show, Hide, Render, ResetCamera,
                                 SaveScreenshot, ColorBy)
    # ParaView 5.13 renamed GhostCellsGenerator to GhostCells.
    ghost_cells = getattr(paraview.simple, 'GhostCells', None) or paraview.simple.GhostCellsGenerator
    LoadPlugin(plugin, remote=False, ns=globals())
    view = CreateView('RenderView')
    view.ViewSize = [W, H]
    view.OrientationAxesVisibility = 0
    for name in MESHES:
        reader = OpenDataFile(os.path.join(directory, source_of(name) + '.vtp'))
        reader.UpdatePipeline()
        b = reader.GetDataInformation().GetBounds()
        parts = RedistributeDataSet(Input=reader)
        if GHOSTS in name:
            parts = ghost_cells(Input=parts)
        surface = ExtractSurface(Input=parts)
        if GHOSTS in name:
            # Cells with the ghosts, over all ranks: more than the mesh has
            # on several ranks (the driver compares with 1 rank's count).
            surface.UpdatePipeline()
            with open(os.path.join(directory, name + '_cells.txt'), 'w') as f:
                f.write('%d\n' % surface.GetDataInformation().GetNumberOfCells())
        if FILTER in name:
            surface = ShadingLabNormals(Input=surface)  # noqa: F821 (from the plugin)
        elevation = Elevation(Input=surface, LowPoint=[b[0], b[2], b[4]], HighPoint=[b[1], b[3], b[5]])
        rep = Show(elevation, view)
        rep.Representation = 'ShadingLab Surface'
        ColorBy(rep, ('POINTS', 'Elevation'))
        # The same view of every mesh (ResetCamera keeps the direction).
        view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = [0, 0, 1], [0, 0, 0], [0, 1, 0]
        ResetCamera(view)
        camera = view.GetActiveCamera()
        camera.Azimuth(30)
        camera.Elevation(25)
        for backend in BACKENDS:
            rep.Backend = backend
            for mode, model in MODES:
                rep.ShadingMode = mode
                rep.ReflectanceModel = model
                Render(view)
                out = os.path.join(directory, png_name(name, mode, model, backend))
                SaveScreenshot(out, view, ImageResolution=[W, H])
        Hide(elevation, view)


def driver(plugin, outdir):
    import numpy
    failures = []
    dirs = {}
    for ranks in (1, 2):
        d = os.path.join(outdir, 'ranks%d' % ranks)
        os.makedirs(d, exist_ok=True)
        make_meshes(d)
        pvbatch_on_ranks(ranks, __file__, plugin, d)
        dirs[ranks] = d

    def compare(path_a, path_b, p99_limit, what):
        a, b = read_png(path_a), read_png(path_b)
        background = a[0, 0]
        covered = numpy.any(a != background, axis=2) | numpy.any(b != background, axis=2)
        diff = numpy.abs(a - b)[covered]
        mean, p99, worst = diff.mean(), numpy.percentile(diff, 99), diff.max()
        ok = mean <= 1.0 and p99 <= p99_limit and covered.sum() > 5000
        print('%s: mean %.3f p99 %.1f max %.0f /255 over %d pixels %s'
              % (what, mean, p99, worst, covered.sum(), 'ok' if ok else 'FAIL'))
        if not ok:
            failures.append(what)

    for name in MESHES:
        for mode, model in MODES:
            for backend in BACKENDS:
                png = png_name(name, mode, model, backend)
                compare(os.path.join(dirs[1], png), os.path.join(dirs[2], png), 2.0,
                        '%-13s %-11s %-14s %s, 2 ranks vs 1' % (name, mode, model, backend))
            compare(os.path.join(dirs[1], png_name(name, mode, model, 'GPU')),
                    os.path.join(dirs[1], png_name(name, mode, model, 'CPU')), 4.0,
                    '%-13s %-11s %-14s 1 rank, CPU vs GPU' % (name, mode, model))
            if source_of(name).endswith('_reversed'):
                intact = source_of(name)[:-len('_reversed')]
                for backend in BACKENDS:
                    for ranks in (1, 2):
                        compare(os.path.join(dirs[1], png_name(intact, mode, model, backend)),
                                os.path.join(dirs[ranks], png_name(name, mode, model, backend)), 2.0,
                                '%-13s %-11s %-14s %s, %d rank(s) vs intact' % (name, mode, model, backend, ranks))
    for name in MESHES:
        if GHOSTS in name:
            cells = [int(open(os.path.join(dirs[r], name + '_cells.txt')).read()) for r in (1, 2)]
            ok = cells[1] > cells[0]
            print('%s: %d cells on 1 rank, %d with ghost cells on 2 %s'
                  % (name, cells[0], cells[1], 'ok' if ok else 'FAIL'))
            if not ok:
                failures.append(name + ' has no ghost cells')
    print('%d failure(s)' % len(failures))
    return 1 if failures else 0


if __name__ == '__main__':
    if sys.argv[1] == '--worker':
        worker(*sys.argv[2:4])
    else:
        sys.exit(driver(*sys.argv[1:3]))
