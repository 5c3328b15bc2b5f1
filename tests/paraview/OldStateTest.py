# A ParaView state saved with ShadingLab 0.1.0 (before the settings table
# generated the representation's XML; tests/paraview/data/state-0.1.0.pvsm,
# made by pvbatch with that build's plugin) loads: every ShadingLab property
# comes back with its value, and the picture equals the one made by setting
# the same properties by hand on a fresh representation.
#
#   pvbatch --force-offscreen-rendering OldStateTest.py PLUGIN STATE OUTDIR
import os
import sys

from paraview.simple import *
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pngs import read_png  # noqa: E402

plugin, state, outdir = sys.argv[1:4]
os.makedirs(outdir, exist_ok=True)
LoadPlugin(plugin, remote=False, ns=globals())
failures = []


def check(condition, message):
    print(('ok   ' if condition else 'FAIL ') + message)
    if not condition:
        failures.append(message)


LoadState(state)
view = GetActiveViewOrCreate('RenderView')
source = FindSource('Sphere1')
rep = GetDisplayProperties(source, view)
expected = {
    'Representation': 'ShadingLab Surface', 'ShadingMode': 'Gouraud',
    'ReflectanceModel': 'Cook-Torrance', 'MaxError': 2.0, 'Kd': 0.4, 'Ks': 0.6,
    'BeckmannRoughness': [0.2, 0.6, 0, 0], 'BeckmannWeights': [0.4, 0.6, 0, 0],
    'Eta': [0.2, 0.4, 1.4], 'Extinction': [3.5, 2.4, 1.8], 'SpecularVariant': 'Walter 2007',
    'InterpolationSpace': 'Screen-space', 'FastPhongMaxSpread': 20.0, 'NormalWeighting': 'Angle',
    'FeatureAngle': 40.0, 'RecomputeNormals': 1, 'AmbientReflectance': 0.1,
    'SpecularTint': [0.9, 0.8, 0.7], 'Shininess': 50.0}
for name, value in expected.items():
    got = rep.GetPropertyValue(name)
    got = list(got) if hasattr(got, '__len__') and not isinstance(got, str) else got
    if isinstance(got, list) and len(got) == 1:
        got = got[0]
    check(got == value, '%s loads as %r (got %r)' % (name, value, got))

W, H = 240, 180
view.ViewSize = [W, H]
view.OrientationAxesVisibility = 0
ResetCamera(view)
loaded_png = os.path.join(outdir, 'loaded.png')
Render(view)
SaveScreenshot(loaded_png, view, ImageResolution=[W, H])

# The same settings by hand on a fresh source and representation.
Hide(source, view)
fresh = Sphere(ThetaResolution=24, PhiResolution=12)
fresh_rep = Show(fresh, view)
fresh_rep.Representation = 'ShadingLab Surface'
for name, value in expected.items():
    if name != 'Representation':
        fresh_rep.SetPropertyWithName(name, value)
by_hand_png = os.path.join(outdir, 'by_hand.png')
Render(view)
SaveScreenshot(by_hand_png, view, ImageResolution=[W, H])
loaded, by_hand = read_png(loaded_png), read_png(by_hand_png)
covered = (loaded.sum(axis=2) > 0).sum()
check(covered > 2000, 'the loaded state draws the sphere (%d pixels)' % covered)
check(abs(loaded - by_hand).max() == 0,
      'the loaded state draws what the same settings by hand draw (max diff %d)'
      % abs(loaded - by_hand).max())

# The loaded view is destroyed here, while the X connection is alive: left
# to the interpreter's exit, ParaView 5.11 frees the state's FXAA textures
# after the display has gone and crashes in XGetErrorText (seen with the
# 0.1.0 plugin as well as this one).
Delete(view)
del view

print('%d failure(s)' % len(failures))
sys.exit(1 if failures else 0)
