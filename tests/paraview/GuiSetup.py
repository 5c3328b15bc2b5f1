# Opened by the GUI test before the XML playback (paraview --script): a
# torus coloured by elevation, at a fixed camera.
import os
from paraview.simple import *
mesh = os.path.join(os.environ['SHADINGLAB_DATASETS'], 'torus_48x24.vtp')
reader = XMLPolyDataReader(registrationName='torus', FileName=[mesh])
elevation = Elevation(registrationName='elevation', Input=reader)
view = GetActiveViewOrCreate('RenderView')
view.OrientationAxesVisibility = 0
display = Show(elevation, view)
ColorBy(display, ('POINTS', 'Elevation'))
display.SetScalarBarVisibility(view, False)
SetActiveSource(elevation)
Hide3DWidgets(proxy=elevation)
view.CameraPosition = [2.2, -3.0, 3.2]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 30
Render(view)
