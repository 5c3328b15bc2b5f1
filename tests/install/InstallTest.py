#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The project as a user installs it, used from where it is installed.

1. `cmake --install` into a fresh prefix: the CLI runs from there, pvbatch
   loads the plugin from there, and a small external CMake project finds
   the package (find_package(ShadingLab)), builds and runs.
2. `cpack -G DEB`: the two packages install into a scratch dpkg root
   (dpkg --root) with their files, and remove cleanly.
3. As root on a machine without ShadingLab installed (CI): `dpkg -i` for
   real, LoadDistributedPlugin('ShadingLab') in pvpython finds the plugin
   without PV_PLUGIN_PATH, then `dpkg -r` removes every file.

usage: InstallTest.py SOURCE_DIR BUILD_DIR WORK_DIR
Prints ok/FAIL lines and "N failure(s)".
"""
import glob
import os
import re
import shutil
import subprocess
import sys

source, build, work = sys.argv[1:4]
failures = 0


def check(condition, what):
    global failures
    print(('ok   ' if condition else 'FAIL ') + what, flush=True)
    failures += 0 if condition else 1


def run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        print('  $ ' + ' '.join(cmd) + '\n' + r.stdout[-2000:] + r.stderr[-2000:])
    return r


shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
env = dict(os.environ)
env.pop('PV_PLUGIN_PATH', None)
version = re.search(r'project\(ShadingLab VERSION ([0-9.]+)',
                    open(os.path.join(source, 'CMakeLists.txt')).read()).group(1)

# 1. cmake --install into a fresh prefix.
prefix = os.path.join(work, 'prefix')
r = run(['cmake', '--install', build, '--prefix', prefix])
check(r.returncode == 0, 'cmake --install into a fresh prefix')
cli = os.path.join(prefix, 'bin', 'shadinglab')
r = run([cli, '--version'])
check(r.returncode == 0 and r.stdout.strip() == 'shadinglab ' + version,
      'installed shadinglab --version says %s (%r)' % (version, r.stdout.strip()))
png = os.path.join(work, 'installed.png')
r = run([cli, 'render', os.path.join(source, 'datasets', 'torus_24x12.vtp'), '--backend', 'cpu',
         '--size', '96x64', '--out', png])
check(r.returncode == 0 and os.path.getsize(png) > 100, 'the installed CLI renders a PNG')
plugins = glob.glob(os.path.join(prefix, 'lib*', '**', 'paraview-*', 'plugins', 'ShadingLab',
                                 'ShadingLab.so'), recursive=True)
check(len(plugins) == 1, 'the plugin is installed as lib/paraview-X.Y/plugins/ShadingLab/ShadingLab.so')
script = os.path.join(work, 'load.py')
with open(script, 'w') as f:
    f.write('''import sys
from paraview.simple import *
LoadPlugin(sys.argv[1], remote=False, ns=globals())
sphere = Sphere(ThetaResolution=24, PhiResolution=12)
rep = Show(sphere)
rep.SetRepresentationType('ShadingLab Surface')
rep.ShadingMode = 'Gouraud'
Render()
print('representation', rep.Representation)
''')
if plugins:
    r = run(['pvbatch', '--force-offscreen-rendering', script, plugins[0]], env=env)
    check(r.returncode == 0 and 'ShadingLab Surface' in r.stdout,
          'pvbatch loads the installed plugin and draws a ShadingLab Surface')
# The Python package, where `cmake --install` put it (lib/python3/dist-packages,
# Debian's folder for every Python 3), imported by pvpython: it renders.
site = os.path.join(prefix, 'lib', 'python3', 'dist-packages')
check(os.path.exists(os.path.join(site, 'shadinglab', '__init__.py')),
      'the Python package is installed in lib/python3/dist-packages/shadinglab')
r = run(['pvpython', '-c', 'import shadinglab\n'
         'from vtkmodules.vtkFiltersSources import vtkSphereSource\n'
         's = vtkSphereSource(); s.Update()\n'
         'image, stats = shadinglab.render(s.GetOutput(), mode="gouraud", size=(64, 48))\n'
         'print("rendered", image.shape, stats["mode"])'],
        env=dict(env, PYTHONPATH=site))
check(r.returncode == 0 and 'rendered (48, 64, 3) gouraud' in r.stdout,
      'pvpython imports the installed package and renders (%s)' % (r.stdout + r.stderr).strip()[-200:])
# A plain C++ project (no C) per package component: CPU needs neither VTK
# nor ParaView; VTK brings the VTK ShadingLab was built against; IO (C
# enabled: HDF5's lookup in ParaView 5.11's VTK compiles C) reads a mesh.
for component, links in [('CPU', 'ShadingLab::CPU'), ('VTK', 'ShadingLab::CPU and ShadingLab::GL'),
                         ('IO', 'ShadingLab::MeshIO')]:
    consumer_build = os.path.join(work, 'consumer-build-' + component.lower())
    shutil.rmtree(consumer_build, ignore_errors=True)
    r = run(['cmake', '-S', os.path.join(source, 'tests', 'install', 'consumer'), '-B', consumer_build,
             '-DCMAKE_PREFIX_PATH=' + prefix, '-DCMAKE_BUILD_TYPE=Release',
             '-DSHADINGLAB_COMPONENT=' + component])
    check(r.returncode == 0, 'a %s project finds the installed package '
          '(find_package(ShadingLab COMPONENTS %s))' % ('C/C++' if component == 'IO' else 'CXX-only',
                                                       component))
    r = run(['cmake', '--build', consumer_build, '-j2'])
    check(r.returncode == 0, 'it builds against ' + links)
    exe = os.path.join(consumer_build, 'consumer')
    args = [os.path.join(source, 'datasets', 'torus_48x24.vtp')] if component == 'IO' else []
    r = run([exe] + args) if os.path.exists(exe) else None
    expected = 'shadinglab read ' if component == 'IO' else 'shadinglab %s covered' % version
    check(r is not None and r.returncode == 0 and expected in r.stdout
          and (component != 'VTK' or 'mapper ok' in r.stdout),
          'and runs: %s' % (r.stdout.strip() if r else 'not built'))

# 2. The Debian packages, in a scratch dpkg root.
r = run(['cpack', '-G', 'DEB', '-B', os.path.join(work, 'deb')], cwd=build)
debs = sorted(glob.glob(os.path.join(work, 'deb', '*.deb')))
check(r.returncode == 0 and len(debs) == 2, 'cpack -G DEB makes shadinglab and shadinglab-dev (%s)'
      % [os.path.basename(d) for d in debs])
runtime = [d for d in debs if os.path.basename(d).startswith('shadinglab_')]
if runtime:
    r = run(['dpkg-deb', '-f', runtime[0], 'Depends'])
    depends = r.stdout.strip()
    check('libc6' in depends and 'libvtk' in depends.lower() or 'paraview' in depends.lower(),
          'dpkg-shlibdeps filled Depends: %s' % depends[:160])
# Where the package tells ParaView of the plugin: bin/paraview.conf (ParaView
# 5.11), or a link in the plugin folder Debian 13 and later list in their
# own paraview.conf.
debian_conf = glob.glob('/usr/lib/*/paraview-*/paraview.conf')
plugin_list = ('usr/share/paraview/plugins/ShadingLab.so' if debian_conf
               else 'usr/bin/paraview.conf')
root = os.path.join(work, 'dpkg-root')
for d in ('var/lib/dpkg/info', 'var/lib/dpkg/updates', 'var/lib/dpkg/triggers'):
    os.makedirs(os.path.join(root, d), exist_ok=True)
open(os.path.join(root, 'var/lib/dpkg/status'), 'w').close()
dpkg = ['dpkg', '--root=' + root, '--force-depends', '--force-not-root', '--force-script-chrootless',
        '--log=' + os.path.join(work, 'dpkg.log')]
if debs:
    r = run(dpkg + ['-i'] + debs)
    check(r.returncode == 0 and os.path.exists(os.path.join(root, 'usr', 'bin', 'shadinglab'))
          and os.path.lexists(os.path.join(root, plugin_list))
          and os.path.exists(os.path.join(root, 'usr/lib/python3/dist-packages/shadinglab/__init__.py')),
          'dpkg --root installs both packages (usr/bin/shadinglab, %s, '
          'usr/lib/python3/dist-packages/shadinglab)' % plugin_list)
    r = run([os.path.join(root, 'usr', 'bin', 'shadinglab'), '--version'])
    check(r.returncode == 0, 'the packaged CLI runs from the scratch root')
    r = run(dpkg + ['-r', 'shadinglab-dev', 'shadinglab'])
    left = [f for f in glob.glob(os.path.join(root, 'usr', '**'), recursive=True)
            if os.path.isfile(f) or os.path.islink(f)]
    check(r.returncode == 0 and not left, 'dpkg -r removes every file (%d left)' % len(left))

# 3. A real install (root, ShadingLab not installed, ParaView's bindir free).
real = (os.geteuid() == 0 and runtime and not os.path.lexists('/' + plugin_list)
        and run(['dpkg', '-s', 'shadinglab']).returncode != 0)
if real:
    r = run(['dpkg', '-i', runtime[0]])
    try:
        check(r.returncode == 0, 'dpkg -i ' + os.path.basename(runtime[0]))
        probe = os.path.join(work, 'distributed.py')
        with open(probe, 'w') as f:
            f.write("from paraview.simple import *\n"
                    "LoadDistributedPlugin('ShadingLab', remote=False, ns=globals())\n"
                    "rep = Show(Sphere())\nrep.SetRepresentationType('ShadingLab Surface')\n"
                    "print('distributed', rep.Representation)\n")
        r = run(['pvpython', '--force-offscreen-rendering', probe], env=env)
        check('ShadingLab Surface' in r.stdout,
              "LoadDistributedPlugin('ShadingLab') finds the installed plugin without PV_PLUGIN_PATH")
        r = run(['pvpython', '-c', 'import shadinglab; print(shadinglab.vtkShadingLabPolyDataMapper)'],
                env=env)
        check(r.returncode == 0 and 'vtkShadingLabPolyDataMapper' in r.stdout,
              'pvpython imports the packaged shadinglab without PYTHONPATH')
    finally:
        r = run(['dpkg', '-r', 'shadinglab'])
    check(r.returncode == 0 and not os.path.exists('/usr/bin/shadinglab')
          and not os.path.lexists('/' + plugin_list), 'dpkg -r shadinglab removes it')
else:
    print('note: no real dpkg -i here (needs root, no ShadingLab installed, no /%s)' % plugin_list)

print('%d failure(s)' % failures)
sys.exit(1 if failures else 0)
