# The ShadingLab filters in pvbatch (what they report, inputs unmodified)
# and a .pvsm state round trip of the filters and the representation.
#
#   pvbatch --force-offscreen-rendering FiltersStateTest.py PLUGIN DATADIR OUTDIR
import os
import sys

from paraview.simple import *
from paraview import servermanager

plugin, data, outdir = sys.argv[1:4]
os.makedirs(outdir, exist_ok=True)
LoadPlugin(plugin, remote=False, ns=globals())
failures = []


def check(condition, message):
    print(('ok   ' if condition else 'FAIL ') + message)
    if not condition:
        failures.append(message)


def fetch(proxy):
    proxy.UpdatePipeline()
    return servermanager.Fetch(proxy)


# Normals: creases split on the 8-sided cylinder; the input keeps no normals.
cylinder = OpenDataFile(os.path.join(data, 'cylinder_8.vtp'))
normals = ShadingLabNormals(Input=cylinder)
normals.Weighting = 'Angle'
normals.FeatureAngle = 30
out = fetch(normals)
before = fetch(cylinder)
check(out.GetPointData().GetNormals() is not None, 'normals filter writes Normals')
check(out.GetNumberOfPoints() > before.GetNumberOfPoints(),
      'creases split points: %d -> %d' % (before.GetNumberOfPoints(), out.GetNumberOfPoints()))
check(before.GetPointData().GetNormals() is None, 'the input is not given normals')

# Repair: a T-junction (the small quads' shared vertex lies on the big
# quad's edge) gets its edge split.
from vtkmodules.vtkCommonDataModel import vtkPolyData, vtkCellArray
from vtkmodules.vtkCommonCore import vtkPoints
tpoints = vtkPoints()
for p in [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (2, 0, 0), (2, 0.5, 0), (1, 0.5, 0), (2, 1, 0)]:
    tpoints.InsertNextPoint(p)
tcells = vtkCellArray()
for quad in [(0, 1, 2, 3), (1, 4, 5, 6), (6, 5, 7, 2)]:
    tcells.InsertNextCell(4, quad)
tmesh = vtkPolyData()
tmesh.SetPoints(tpoints)
tmesh.SetPolys(tcells)
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
writer = vtkXMLPolyDataWriter()
writer.SetFileName(os.path.join(outdir, 't_junction.vtp'))
writer.SetInputData(tmesh)
writer.Write()
junctions = OpenDataFile(os.path.join(outdir, 't_junction.vtp'))
repair = ShadingLabMeshRepair(Input=junctions)
repair.FixTJunctions = 1
fixed = fetch(repair)
raw = fetch(junctions)
# The big quad's edge is split at the junction: it becomes a pentagon.
corners = lambda mesh: mesh.GetPolys().GetNumberOfConnectivityIds()
check(corners(fixed) == corners(raw) + 1,
      'T-junction split: %d -> %d polygon corners' % (corners(raw), corners(fixed)))

# Subdivision: Loop, 2 levels, 16 faces per face, limit normals.
sphere = OpenDataFile(os.path.join(data, 'icosphere_1.vtp'))
refine = ShadingLabSubdivision(Input=sphere)
refine.Levels = 2
refined = fetch(refine)
check(refined.GetNumberOfPolys() == 80 * 16, 'Loop x2: %d faces' % refined.GetNumberOfPolys())
check(refined.GetPointData().GetNormals() is not None, 'limit normals')

# State round trip: every ShadingLab property survives Save/Load State.
view = CreateView('RenderView')
rep = Show(refine, view)
rep.Representation = 'ShadingLab Surface'
settings = {'ShadingMode': 'Auto', 'MaxError': 2.5, 'ReflectanceModel': 'Cook-Torrance', 'MaterialPreset': 'copper',
            'Kd': 0.25, 'Ks': 0.5, 'Shininess': 77.0, 'AmbientReflectance': 0.1,
            'BeckmannRoughness': [0.2, 0.5, 0.0, 0.0], 'BeckmannWeights': [0.3, 0.7, 0.0, 0.0],
            'Eta': [0.2, 0.9, 1.1], 'Extinction': [3.0, 2.5, 2.2], 'SpecularVariant': 'Walter 2007',
            'InterpolationSpace': 'Screen-space', 'FastPhongMaxSpread': 12.5,
            'NormalWeighting': 'Angle', 'FeatureAngle': 40.0, 'RecomputeNormals': 1}
for name, value in settings.items():
    setattr(rep, name, value)
Render(view)
state = os.path.join(outdir, 'shadinglab.pvsm')
SaveState(state)
ResetSession()
LoadState(state)
loaded = GetRepresentation(FindSource('ShadingLabSubdivision1'), GetActiveView())
check(loaded.Representation == 'ShadingLab Surface', 'representation restored')
for name, value in settings.items():
    got = loaded.GetPropertyValue(name)
    if isinstance(value, list):
        got = list(got)
    same = got == value if not isinstance(value, float) else abs(got - value) < 1e-12
    check(same, '%s restored: %s' % (name, got))
levels = FindSource('ShadingLabSubdivision1').Levels
check(levels == 2, 'filter property restored: Levels %s' % levels)
print('%d failure(s)' % len(failures))
sys.exit(1 if failures else 0)
