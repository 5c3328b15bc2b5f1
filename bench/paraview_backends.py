# pvbatch frame times of ParaView's own Surface against ShadingLab Surface
# on each backend: a sphere of ~1,000,000 triangles coloured by Elevation,
# 1920x1080, the camera turning 2 degrees a frame; per configuration the
# median of FRAMES frames after one warm-up frame, all configurations
# interleaved in one process and the whole set repeated RUNS times.
#
#   pvbatch --force-offscreen-rendering bench/paraview_backends.py PLUGIN [FRAMES] [RUNS] [THETA] [FXAA]
#
# THETA (default 1000) sets the sphere's resolution: THETA x THETA/2 x 2
# triangles (316: ~100,000, where Auto's threshold sits). FXAA (default 1,
# ParaView's default) is the view's UseFXAA: on llvmpipe its full-screen
# pass costs tens of milliseconds a 1080p frame, whoever drew the pixels.
#
# Every ShadingLab configuration is timed right after ParaView's Surface,
# and its ratio taken to that Surface: pairs, as farm-bench pairs, because
# these machines drift by tens of percent within a minute, and one Surface
# figure per run made the ratios swing with it (the same code read 0.42x
# and 0.62x in two runs). Prints one line per configuration with every
# run's median (ms; for Surface, the median of its paired measurements in
# that run) and the median of its paired ratios. A benchmark, not a test:
# on a machine without a GPU the GL numbers are Mesa llvmpipe's.
import statistics
import sys
import time

from paraview.simple import *

plugin = sys.argv[1]
FRAMES = int(sys.argv[2]) if len(sys.argv) > 2 else 7
RUNS = int(sys.argv[3]) if len(sys.argv) > 3 else 2
THETA = int(sys.argv[4]) if len(sys.argv) > 4 else 1000
FXAA = int(sys.argv[5]) if len(sys.argv) > 5 else 1
LoadPlugin(plugin, remote=False, ns=globals())

# ThetaResolution x PhiResolution x 2 triangles (1000: about 1.0M).
sphere = Sphere(ThetaResolution=THETA, PhiResolution=THETA // 2)
elevation = Elevation(Input=sphere, LowPoint=[0, 0, -0.5], HighPoint=[0, 0, 0.5])
view = CreateView('RenderView')
view.ViewSize = [1920, 1080]
view.OrientationAxesVisibility = 0
view.UseFXAA = FXAA
rep = Show(elevation, view)
ColorBy(rep, ('POINTS', 'Elevation'))
ResetCamera(view)
camera = view.GetActiveCamera()
elevation.UpdatePipeline()
triangles = elevation.GetDataInformation().GetNumberOfCells()

CONFIGS = [('ParaView Surface', None, None, None)]
for backend in ('GPU', 'CPU'):
    for mode, model in (('Flat', 'Blinn-Phong'), ('Gouraud', 'Blinn-Phong'),
                        ('Phong', 'Blinn-Phong'), ('Phong', 'Cook-Torrance')):
        CONFIGS.append(('ShadingLab %s %s/%s' % (backend, mode, model), backend, mode, model))


def frame_times(backend, mode, model):
    if backend is None:
        rep.Representation = 'Surface'
    else:
        rep.Representation = 'ShadingLab Surface'
        rep.Backend = backend
        rep.ShadingMode = mode
        rep.ReflectanceModel = model
    Render(view)  # warm-up: shaders, buffers, the mesh's conversion
    times = []
    for _ in range(FRAMES):
        camera.Azimuth(2)
        start = time.perf_counter()
        Render(view)
        times.append(1000 * (time.perf_counter() - start))
    return statistics.median(times)


medians = {label: [] for label, *_ in CONFIGS}
ratios = {label: [] for label, *_ in CONFIGS}
for run in range(RUNS):
    surfaces = []
    for label, backend, mode, model in CONFIGS[1:]:
        surface = frame_times(None, None, None)
        t = frame_times(backend, mode, model)
        surfaces.append(surface)
        medians[label].append(t)
        ratios[label].append(t / surface)
    medians['ParaView Surface'].append(statistics.median(surfaces))
    ratios['ParaView Surface'].append(1.0)
print('%d triangles, 1920x1080, FXAA %s, median of %d frames, %d runs'
      % (triangles, 'on' if FXAA else 'off', FRAMES, RUNS))
for label, *_ in CONFIGS:
    print('%-42s %s ms  (x%.2f of ParaView Surface)'
          % (label, ' '.join('%7.1f' % t for t in medians[label]),
             statistics.median(ratios[label])))
