# Opened by the GUI test before the XML playback (paraview --script): a
# torus coloured by elevation, at a fixed camera.
import os
from paraview.simple import *
mesh = os.path.join(os.environ['SHADINGLAB_DATASETS'], 'torus_48x24.vtp')
reader = XMLPolyDataReader(registrationName='torus', FileName=[mesh])
# The points ParaView 5.11 chose for this torus, named: ParaView 6 leaves
# both at 0 until the reader has run (a zero vector, VTK then uses z).
elevation = Elevation(registrationName='elevation', Input=reader,
                      LowPoint=[1, 1, 1], HighPoint=[-1, -1, -1])
view = GetActiveViewOrCreate('RenderView')
view.OrientationAxesVisibility = 0
# ParaView 5.11's default background, named: ParaView 6's palette is grey.
view.UseColorPaletteForBackground = 0
view.Background = [0.32, 0.34, 0.43]
display = Show(elevation, view)
ColorBy(display, ('POINTS', 'Elevation'))
# ParaView 6.0 changed the default colour map (Cool to Warm became Fast):
# name it, so the baseline holds on every ParaView.
GetColorTransferFunction('Elevation').ApplyPreset('Cool to Warm', True)
display.SetScalarBarVisibility(view, False)
SetActiveSource(elevation)
# Hide3DWidgets became HideInteractiveWidgets in ParaView 6.0.
globals().get('HideInteractiveWidgets', globals().get('Hide3DWidgets'))(proxy=elevation)
view.CameraPosition = [2.2, -3.0, 3.2]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 30
Render(view)
