# ParaView reading a big mesh: the plugin's reader (FastMeshReader) against
# ParaView's own (PLY Reader / STL Reader), in one pvpython, interleaved.
#
#   pvpython bench/paraview_read.py PLUGIN FILE [RUNS]
#
# Prints one line per run and the medians: the seconds from creating the
# reader to its data on the client side's server (UpdatePipeline), page
# cache warm (one untimed read of each first).
import os
import statistics
import sys
import time

from paraview.simple import *

plugin, path = sys.argv[1:3]
runs = int(sys.argv[3]) if len(sys.argv) > 3 else 5
LoadPlugin(plugin, remote=False, ns=globals())
own = {'.ply': PLYReader, '.stl': STLReader}[os.path.splitext(path)[1].lower()]


def timed(make):
    start = time.perf_counter()
    reader = make()
    reader.UpdatePipeline()
    seconds = time.perf_counter() - start
    cells = reader.GetDataInformation().GetNumberOfCells()
    Delete(reader)
    return seconds, cells


makers = {'ShadingLab': lambda: ShadingLabMeshReader(FileName=path),
          'ParaView': lambda: own(FileNames=[path])}
for make in makers.values():
    timed(make)  # warm
times = {name: [] for name in makers}
for r in range(runs):
    for name, make in makers.items():
        seconds, cells = timed(make)
        times[name].append(seconds)
        print('run %d  %-10s %.3f s  %d cells' % (r + 1, name, seconds, cells), flush=True)
a, b = statistics.median(times['ShadingLab']), statistics.median(times['ParaView'])
print('median of %d: ShadingLab %.3f s, ParaView %.3f s, ratio %.3f' % (runs, a, b, a / b))
