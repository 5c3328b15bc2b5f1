# ShadingLab in client/server mode, as on a cluster: `mpiexec -n 2 pvserver`
# and a pvpython client connected to it, the plugin loaded on both sides;
# the ShadingLab Surface of ShadingLab Normals must render on the server
# and come back to the client.
#
#   pvpython ClientServerTest.py PLUGIN MESH OUTDIR
import os
import socket
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pngs import read_png  # noqa: E402
from mpirun import clean_environment  # noqa: E402

plugin, mesh, outdir = sys.argv[1:4]
os.makedirs(outdir, exist_ok=True)

# A free port (bound then released: a small race, fine on a test machine).
with socket.socket() as s:
    s.bind(('localhost', 0))
    port = s.getsockname()[1]
env = clean_environment()
server = subprocess.Popen(['mpiexec', '--allow-run-as-root', '--oversubscribe', '-n', '2', 'pvserver',
                           '--force-offscreen-rendering', '--server-port=%d' % port],
                          env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                          start_new_session=True)
failures = []
try:
    for _ in range(120):  # wait up to 60 s for the server to listen
        with socket.socket() as probe:
            if probe.connect_ex(('localhost', port)) == 0:
                break
        time.sleep(0.5)
    from paraview.simple import (Connect, LoadPlugin, OpenDataFile, CreateView, Show, Render,
                                 SaveScreenshot)
    from paraview import servermanager
    Connect('localhost', port)
    LoadPlugin(plugin, remote=False, ns=globals())
    LoadPlugin(plugin, remote=True, ns=globals())
    partitions = servermanager.ActiveConnection.GetNumberOfDataPartitions()
    normals = ShadingLabNormals(Input=OpenDataFile(mesh))  # noqa: F821 (from the plugin)
    view = CreateView('RenderView')
    view.ViewSize = [320, 240]
    view.OrientationAxesVisibility = 0
    rep = Show(normals, view)
    rep.Representation = 'ShadingLab Surface'
    rep.ShadingMode = 'Gouraud'
    Render(view)
    shot = os.path.join(outdir, 'client_server.png')
    SaveScreenshot(shot, view, ImageResolution=[320, 240])
    pixels = read_png(shot).reshape(-1, 3)
    background = pixels[0]
    drawn = (abs(pixels - background).sum(axis=1) > 30).sum()
    print('server ranks: %d; pixels drawn: %d' % (partitions, drawn))
    if partitions != 2:
        failures.append('expected 2 server ranks')
    if drawn < 5000:
        failures.append('the surface did not come back to the client')
    from paraview.simple import Disconnect
    Disconnect()  # pvserver exits when its client leaves
finally:
    try:
        server.wait(timeout=20)
    except subprocess.TimeoutExpired:
        os.killpg(server.pid, 15)  # mpiexec and its pvserver ranks
        server.wait(timeout=20)
print('%d failure(s)' % len(failures))
sys.exit(1 if failures else 0)
