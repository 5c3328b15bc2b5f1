# The plugin's mesh reader in pvpython: OpenDataFile picks it for .ply,
# .stl, .off and .obj; it gives VTK's readers' points and cells; a malformed
# file gives one error line and an empty output, no crash.
#
#   pvpython ReaderTest.py PLUGIN DATADIR OUTDIR PVPYTHON
import os
import subprocess
import sys

from paraview.simple import *
from paraview import servermanager
from vtkmodules.util.numpy_support import vtk_to_numpy

if sys.argv[1] == '--read':  # the child of the bad-file case below
    LoadPlugin(sys.argv[2], remote=False, ns=globals())
    reader = ShadingLabMeshReader(FileName=sys.argv[3])
    reader.UpdatePipeline()
    print('points: %d' % servermanager.Fetch(reader).GetNumberOfPoints())
    sys.exit(0)

plugin, data, outdir, pvpython = sys.argv[1:5]
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


def same(a, b):
    pa = vtk_to_numpy(a.GetPoints().GetData())
    pb = vtk_to_numpy(b.GetPoints().GetData())
    ca = vtk_to_numpy(a.GetPolys().GetConnectivityArray())
    cb = vtk_to_numpy(b.GetPolys().GetConnectivityArray())
    oa = vtk_to_numpy(a.GetPolys().GetOffsetsArray())
    ob = vtk_to_numpy(b.GetPolys().GetOffsetsArray())
    return (pa.dtype == pb.dtype and pa.shape == pb.shape and (pa.view('u1') == pb.view('u1')).all()
            and ca.shape == cb.shape and (ca == cb).all() and (oa == ob).all())


for name, vtk_reader in (('sphere_lowpoly.ply', lambda f: PLYReader(FileNames=[f])),
                         ('cylinder_8.stl', lambda f: STLReader(FileNames=[f])),
                         ('corrugated_plane.obj', lambda f: WavefrontOBJReader(FileName=f))):
    path = os.path.join(data, name)
    ours = OpenDataFile(path)
    check(ours.GetXMLName() == 'FastMeshReader',
          'OpenDataFile reads %s with the ShadingLab reader (got %s)' % (name, ours.GetXMLName()))
    a = fetch(ours)
    b = fetch(vtk_reader(path))
    check(a.GetNumberOfPolys() > 0 and same(a, b),
          "%s: the same %d points and %d polygons as VTK's reader" % (
              name, a.GetNumberOfPoints(), a.GetNumberOfPolys()))

off = OpenDataFile(os.path.join(data, 't_junctions.off'))
mesh = fetch(off)
check(off.GetXMLName() == 'FastMeshReader' and mesh.GetNumberOfPolys() > 0,
      'ParaView opens .off through the plugin (%d polygons)' % mesh.GetNumberOfPolys())

bad = os.path.join(outdir, 'bad_index.ply')
with open(bad, 'w') as f:
    f.write('ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n'
            'property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n'
            '0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n')
child = subprocess.run([pvpython, __file__, '--read', plugin, bad], capture_output=True, text=True)
named = [line for line in child.stderr.splitlines() if 'vertex index 7 outside 0..2' in line]
check(len(named) == 1 and 'malformed PLY' in named[0],
      'a malformed file gives one error line naming the problem: %s' % (named[0] if named else child.stderr[-300:]))
check(child.returncode == 0 and 'points: 0' in child.stdout,
      'and an empty output, no crash (exit %d)' % child.returncode)

print('%d failure(s)' % len(failures))
sys.exit(1 if failures else 0)
