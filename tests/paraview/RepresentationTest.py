# ShadingLab Surface in pvbatch: loads the plugin, renders every shading mode
# x reflectance model of a shipped mesh coloured by a data array, checks that
# the modes differ where they must, and compares each mode with the
# standalone GL renderer (shadinglab render --backend gpu) for the same
# camera, light and material.
#
#   pvbatch --force-offscreen-rendering RepresentationTest.py PLUGIN MESH COARSE CLI OUTDIR
#
# COARSE is a mesh of large facets for the flat-mode comparison.
import math
import os
import subprocess
import sys

from paraview.simple import *
import numpy
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pngs import read_png  # noqa: E402

plugin, mesh, coarse, cli, outdir = sys.argv[1:6]
os.makedirs(outdir, exist_ok=True)
LoadPlugin(plugin, remote=False, ns=globals())

W, H = 320, 240
failures = []


def check(condition, message):
    print(('ok   ' if condition else 'FAIL ') + message)
    if not condition:
        failures.append(message)


def corner_elevation(source):
    """Elevation from (1, 1, 1) to (-1, -1, -1), the points ParaView 5.11
    gives a new Elevation filter, named: ParaView 6 leaves both at 0 (a zero
    vector, for which VTK falls back to z)."""
    return Elevation(Input=source, LowPoint=[1, 1, 1], HighPoint=[-1, -1, -1])


reader = OpenDataFile(mesh)
elevation = corner_elevation(reader)
view = CreateView('RenderView')
view.ViewSize = [W, H]
view.OrientationAxesVisibility = 0
view.Background = [0.0, 0.0, 0.0]
view.UseColorPaletteForBackground = 0
rep = Show(elevation, view)
rep.Representation = 'ShadingLab Surface'
check(rep.Representation == 'ShadingLab Surface', 'representation is offered and set')
ResetCamera(view)
camera = view.GetActiveCamera()
camera.Azimuth(20)
camera.Elevation(25)
view.CameraParallelProjection = 0
Render(view)


def shot(name):
    path = os.path.join(outdir, name + '.png')
    Render(view)
    SaveScreenshot(path, view, ImageResolution=[W, H])
    return read_png(path)


def covered(image):
    return image.sum(axis=2) > 0


# 1. Coloured by a data array: every mode x model renders, and the
#    interpolation modes differ from one another.
ColorBy(rep, ('POINTS', 'Elevation'))
images = {}
for model in ['Lambert', 'Phong', 'Blinn-Phong', 'Cook-Torrance']:
    rep.ReflectanceModel = model
    for mode in ['Flat', 'Gouraud', 'Phong', 'Fast Phong']:
        rep.ShadingMode = mode
        image = shot('colored_%s_%s' % (mode.replace(' ', ''), model))
        images[(mode, model)] = image
        mask = covered(image)
        check(mask.sum() > 5000, '%s/%s covers the mesh (%d pixels)' % (mode, model, mask.sum()))
        # Coloured by elevation: the picture is not grey.
        spread = numpy.abs(image[mask][:, 0] - image[mask][:, 2]).mean()
        check(spread > 5, '%s/%s shows the colour map (mean |R-B| %.1f)' % (mode, model, spread))


def difference(a, b):
    mask = covered(a) & covered(b)
    return numpy.abs(a[mask] - b[mask]).mean()


for model in ['Blinn-Phong', 'Cook-Torrance']:
    flat = images[('Flat', model)]
    gouraud = images[('Gouraud', model)]
    phong = images[('Phong', model)]
    check(difference(flat, gouraud) > 1.0, 'flat differs from gouraud (%s): %.2f' % (model, difference(flat, gouraud)))
    check(difference(gouraud, phong) > 0.3, 'gouraud differs from phong (%s): %.2f' % (model, difference(gouraud, phong)))

# 2. The same picture as the standalone GL renderer: solid colour, the
#    headlight only, the representation's default material.
ColorBy(rep, None)
rep.DiffuseColor = [1.0, 1.0, 1.0]
view.UseLight = 0                 # no light kit
headlight = AddLight(view=view)   # one white headlight of intensity 1
headlight.Coords = 'Headlight'
headlight.Intensity = 1.0
headlight.DiffuseColor = [1.0, 1.0, 1.0]
pos = camera.GetPosition()
focal = camera.GetFocalPoint()
up = camera.GetViewUp()
direction = [p - f for p, f in zip(pos, focal)]
vector = lambda v: ','.join('%.17g' % x for x in v)
coarse_reader = OpenDataFile(coarse)
coarse_rep = Show(coarse_reader, view)
coarse_rep.Representation = 'ShadingLab Surface'
cases = [('Flat', 'flat', 'Lambert'), ('Flat', 'flat', 'Blinn-Phong'),
         ('Gouraud', 'gouraud', 'Blinn-Phong'), ('Phong', 'phong', 'Blinn-Phong'),
         ('Fast Phong', 'fast-phong', 'Blinn-Phong'), ('Phong', 'phong', 'Cook-Torrance'),
         ('Gouraud', 'gouraud', 'Cook-Torrance')]
for mode, cli_mode, model in cases:
    # Flat on large facets: its edges are where the two renderers may differ.
    shown, hidden, path = (coarse_rep, rep, coarse) if mode == 'Flat' else (rep, coarse_rep, mesh)
    shown.Visibility = 1
    hidden.Visibility = 0
    shown.ShadingMode = mode
    shown.ReflectanceModel = model
    name = '%s_%s' % (cli_mode, model.lower())
    ours = shot('solid_' + name)
    ref_path = os.path.join(outdir, 'cli_%s.png' % name)
    subprocess.run([cli, 'render', path, '--backend', 'gpu', '--mode', cli_mode,
                    '--model', model.lower(), '--kd', '0.7', '--ks', '0.3', '--shininess', '32',
                    '--size', '%dx%d' % (W, H), '--camera-position', vector(pos),
                    '--focal-point', vector(focal), '--view-up', vector(up),
                    '--view-angle', '%.17g' % camera.GetViewAngle(),
                    '--light', 'dir:' + vector(direction), '--out', ref_path], check=True)
    ref = read_png(ref_path)
    mask = covered(ours) & (numpy.abs(ref - numpy.array([0.32, 0.34, 0.43]) * 255).sum(axis=2) > 3)
    # Interior pixels only: a silhouette pixel is covered in one image and
    # half-covered in the other when the two clipping ranges round depth
    # differently.
    interior = mask.copy()
    interior[1:, :] &= mask[:-1, :]
    interior[:-1, :] &= mask[1:, :]
    interior[:, 1:] &= mask[:, :-1]
    interior[:, :-1] &= mask[:, 1:]
    mask = interior
    mean = numpy.abs(ours[mask] - ref[mask]).mean()
    p99 = numpy.percentile(numpy.abs(ours[mask] - ref[mask]), 99)
    p90 = numpy.percentile(numpy.abs(ours[mask] - ref[mask]), 90)
    # Thresholds in 1/255: the same mapper and shaders on the same llvmpipe.
    # ParaView keeps the file's double coordinates (VTK shifts and scales
    # them for the GPU) where the standalone renderer uploads floats, so
    # triangle edges move by a fraction of a pixel and some edge pixels
    # change triangle. In smooth modes that changes nothing visible; in
    # flat mode neighbouring facets differ by a facet step, so flat is
    # compared on large facets and held to its 90th percentile.
    if mode == 'Flat':
        ok = mean <= 2.0 and p90 <= 2
    else:
        ok = mean <= 1.0 and p99 <= 4
    check(mask.sum() > 5000 and ok,
          '%s/%s matches the standalone GL renderer: mean %.3f, p90 %.1f, p99 %.1f over %d pixels'
          % (mode, model, mean, p90, p99, mask.sum()))

# 2b. Auto: per render, the cheapest mode predicted under Max Error. Its
#     choice is the CLI's `--mode auto` choice for the same mesh, camera,
#     light and size, and its picture is that mode's picture exactly.
coarse_rep.Visibility = 0
rep.Visibility = 1
rep.ReflectanceModel = 'Blinn-Phong'
fixed = {}
for mode in ['Flat', 'Gouraud', 'Phong']:
    rep.ShadingMode = mode
    fixed[mode] = shot('auto_fixed_' + mode.lower())
chosen = set()
for budget in [0.05, 7.0, 60.0]:
    rep.ShadingMode = 'Auto'
    rep.MaxError = budget
    image = shot('auto_%g' % budget)
    rep.UpdatePropertyInformation()
    why = rep.GetProperty('AutoChoice').GetData()
    ours_mode = why.strip().split('-> ')[-1].split(',')[0].strip() if '-> ' in why else ''
    stats = subprocess.run([cli, 'render', mesh, '--backend', 'cpu', '--mode', 'auto',
                            '--max-error', '%g' % budget, '--stats',
                            '--model', 'blinn-phong', '--kd', '0.7', '--ks', '0.3', '--shininess', '32',
                            '--size', '%dx%d' % (W, H), '--camera-position', vector(pos),
                            '--focal-point', vector(focal), '--view-up', vector(up),
                            '--view-angle', '%.17g' % camera.GetViewAngle(),
                            '--light', 'dir:' + vector(direction),
                            '--out', os.path.join(outdir, 'cli_auto.png')],
                           check=True, capture_output=True, text=True).stdout
    cli_mode = stats.split('-> ')[-1].split(',')[0].split('"')[0].strip() if '-> ' in stats else '?'
    check(ours_mode != '' and ours_mode == cli_mode,
          'auto, max error %g: ParaView chose %r, the CLI %r (%s)' % (budget, ours_mode, cli_mode, why.strip()))
    name = {'flat': 'Flat', 'gouraud': 'Gouraud', 'phong': 'Phong'}.get(ours_mode)
    if name:
        chosen.add(name)
        d = numpy.abs(image.astype(float) - fixed[name].astype(float)).max()
        check(d == 0, 'auto, max error %g: the picture is %s\'s (max difference %g)' % (budget, name, d))
# The tightest budget takes Phong, the loosest a cheaper mode (flat or
# Gouraud: on 2304 triangles their predicted costs are within 1%).
check('Phong' in chosen and len(chosen) >= 2,
      'auto: the budgets choose Phong and a cheaper mode (%s)' % sorted(chosen))
rep.ShadingMode = 'Phong'
rep.MaxError = 1.0

# 3. Normals made for data without normals: with a feature angle below the
#    facets' dihedral angles every edge is a crease and Phong shading looks
#    faceted; at 180 (the default) it is smooth.
coarse_rep.Visibility = 1
rep.Visibility = 0
coarse_rep.ShadingMode = 'Phong'
coarse_rep.ReflectanceModel = 'Blinn-Phong'
coarse_rep.FeatureAngle = 180
smooth = shot('normals_smooth')
coarse_rep.FeatureAngle = 5
creased = shot('normals_creased')
coarse_rep.ShadingMode = 'Flat'
faceted = shot('normals_flat')
check(difference(smooth, creased) > 2.0,
      'feature angle 5 creases every edge: differs from smooth by %.2f' % difference(smooth, creased))
check(difference(creased, faceted) < difference(smooth, faceted),
      'creased Phong is closer to flat than smooth Phong is (%.2f < %.2f)'
      % (difference(creased, faceted), difference(smooth, faceted)))

# 4. Opacity and multiblock data.
coarse_rep.Visibility = 0
rep.Visibility = 1
rep.ShadingMode = 'Phong'
rep.Opacity = 1.0
opaque = shot('opacity_1')
rep.Opacity = 0.4
translucent = shot('opacity_04')
mask = covered(opaque) & covered(translucent)
check(mask.sum() > 5000 and numpy.abs(opaque[mask] - translucent[mask]).mean() > 10,
      'opacity 0.4 lets the background through (mean change %.1f)'
      % numpy.abs(opaque[mask] - translucent[mask]).mean())
rep.Opacity = 1.0
rep.Visibility = 0
group = GroupDatasets(Input=[elevation, OpenDataFile(coarse)])
group_rep = Show(group, view)
group_rep.Representation = 'ShadingLab Surface'
group_rep.ShadingMode = 'Gouraud'
ColorBy(group_rep, ('POINTS', 'Elevation'))
ResetCamera(view)
blocks = shot('multiblock')
check(covered(blocks).sum() > 5000, 'multiblock data draws (%d pixels)' % covered(blocks).sum())
group_rep.ShadingMode = 'Flat'
flat_blocks = shot('multiblock_flat')
check(difference(blocks, flat_blocks) > 1.0,
      'multiblock: the shading mode reaches every block (flat vs gouraud %.2f)'
      % difference(blocks, flat_blocks))

# 5. ParaView's per-block colours, opacities and visibility (Block Colors,
#    Block Opacities, the block selectors) reach the blocks.
group_rep.Visibility = 0
left = Sphere(Center=[-1, 0, 0], ThetaResolution=32, PhiResolution=32)
right = Sphere(Center=[1, 0, 0], ThetaResolution=32, PhiResolution=32)
pair = GroupDatasets(Input=[left, right])
pair_rep = Show(pair, view)
pair_rep.Representation = 'ShadingLab Surface'
pair_rep.ShadingMode = 'Phong'
pair_rep.ColorArrayName = [None, '']
pair_rep.DiffuseColor = [1.0, 1.0, 1.0]
view.ResetCamera(False)
camera.SetFocalPoint(0, 0, 0)
camera.SetPosition(0, 0, 7)
camera.SetViewUp(0, 1, 0)
L, R = (H // 2, W // 4), (H // 2, 3 * W // 4)  # the spheres' centres in the image
plain = shot('blocks_plain')
pair_rep.BlockColors = ['/Root/Sphere1', '1', '0', '0']
red = shot('blocks_color')
check(red[L][0] > 4 * red[L][1] + 20 and abs(red[R][0] - red[R][1]) < 10,
      'block colour: the left block red %s, the right one still white %s' % (red[L], red[R]))
pair_rep.BlockOpacities = ['/Root/Sphere2', '0.3']
faded = shot('blocks_opacity')
check(covered(faded)[R] and faded[R].sum() < 0.5 * red[R].sum() and abs(faded[L] - red[L]).max() <= 1,
      'block opacity 0.3: the right block fades over the black background (%s -> %s), the left one does not'
      % (red[R], faded[R]))
pair_rep.BlockSelectors = ['/Root/Sphere2']
hidden = shot('blocks_visibility')
check(hidden[L].sum() == 0 and covered(hidden)[R],
      'block visibility: only the selected (right) block is drawn (left %s, right %s)' % (hidden[L], hidden[R]))
pair_rep.Visibility = 0

# 6. The settings table's spellings and its newest row: a preset in
#    ParaView's Title Case and in the command line's kebab-case is the same
#    material; LightIntensity scales the lights (the plain white sphere,
#    the headlight of section 2).
rep.Visibility = 1
rep.ShadingMode = 'Phong'
rep.ColorArrayName = [None, '']
ResetCamera(view)
rep.MaterialPreset = 'Gold'
gold_title = shot('preset_Gold')
rep.MaterialPreset = 'gold'
gold_kebab = shot('preset_gold')
# Spectral Fresnel (docs/model.md section 7): gold's measured spectrum
# is another gold than its three RGB samples, and the representation draws
# what the standalone GL renderer draws for --material gold --spectral.
rep.Spectral = 1
gold_spectral = shot('preset_gold_spectral')
pos, focal, up = camera.GetPosition(), camera.GetFocalPoint(), camera.GetViewUp()
ref_path = os.path.join(outdir, 'cli_gold_spectral.png')
subprocess.run([cli, 'render', mesh, '--backend', 'gpu', '--mode', 'phong', '--material', 'gold',
                '--spectral', '--size', '%dx%d' % (W, H), '--camera-position', vector(pos),
                '--focal-point', vector(focal), '--view-up', vector(up),
                '--view-angle', '%.17g' % camera.GetViewAngle(),
                '--light', 'dir:' + vector([p - f for p, f in zip(pos, focal)]),
                '--out', ref_path], check=True)
ref = read_png(ref_path)
mask = covered(gold_spectral)
spectral_mean = numpy.abs(gold_spectral[mask] - ref[mask]).mean()
# The preset's RGB n, k are fitted to the spectrum's colour (CIEDE2000
# 1.24 at most), so the two golds differ by little, but by more than the
# two renderers' spectral pictures do.
check(difference(gold_spectral, gold_title) > 0.3 and spectral_mean <= 1.0 and
      spectral_mean < difference(gold_spectral, gold_title),
      'Spectral gold differs from RGB gold (%.2f) and matches the standalone renderer '
      '(mean %.3f over %d pixels)' % (difference(gold_spectral, gold_title), spectral_mean,
                                       mask.sum()))
# OpticalDataFile (--nk): a refractiveindex.info file on the server gives
# spectral Fresnel its n and k. Gold's own table draws the preset's
# spectral gold; copper's table on the gold preset draws copper; a file
# that does not parse is one error and the file is set aside.
optical = os.path.join(os.path.dirname(mesh), 'optical')
rep.OpticalDataFile = os.path.join(optical, 'Au_Johnson.yml')
gold_file = shot('nk_gold_file')
rep.OpticalDataFile = os.path.join(optical, 'Cu_Johnson.yml')
copper_file = shot('nk_copper_file')
bad_nk = os.path.join(outdir, 'bad_nk.yml')
with open(bad_nk, 'w') as f:
    f.write('DATA:\n  - type: formula 5\n    coefficients: 1 2 3\n')
rep.OpticalDataFile = bad_nk
after_bad = shot('nk_bad_file')
rep.OpticalDataFile = ''
check(abs(gold_file.astype(int) - gold_spectral).max() <= 1 and
      difference(copper_file, gold_spectral) > 1 and
      abs(after_bad.astype(int) - gold_spectral).max() <= 1,
      'OpticalDataFile: gold\'s table draws the spectral gold preset (max %d), copper\'s '
      'another metal (%.2f), a bad file is refused and set aside (max %d)'
      % (abs(gold_file.astype(int) - gold_spectral).max(), difference(copper_file, gold_spectral),
         abs(after_bad.astype(int) - gold_spectral).max()))
# A polarizer in front of the camera (docs/model.md section 8): glass lit
# from the side, its highlight s-polarized; crossed polarizers give
# different pictures, and -1 (none) gives back the unpolarized one exactly.
rep.Spectral = 0
rep.MaterialPreset = 'Glass'
headlight.Intensity = 0.0
side = AddLight(view=view)  # from the left, nearly at right angles to the view
side.Coords = 'Camera'
side.Position = [-1.0, 0.0, 0.15]
side.FocalPoint = [0.0, 0.0, 0.0]
side.Intensity = 3.0
unpolarized = shot('glass_unpolarized')
rep.Polarizer = 0
at0 = shot('glass_polarizer_0')
rep.Polarizer = 90
at90 = shot('glass_polarizer_90')
rep.Polarizer = -1
again = shot('glass_unpolarized_again')
check(difference(at0, at90) > 0.3 and difference(unpolarized, at0) > 1 and
      abs(again - unpolarized).max() == 0,
      'Polarizer 0 and 90 differ (%.2f), both darker than none (%.2f), -1 restores it (max %d)'
      % (difference(at0, at90), difference(unpolarized, at0), abs(again - unpolarized).max()))
# PolarizationImage (eq. 8.5): what a polarization camera measures, drawn
# by the CPU backend in false colour. Near Brewster's angle the glass's
# highlight is strongly polarized (viridis' yellow end: red and green high,
# blue low), the diffuse rest hardly (its purple end); AoP is another
# picture; Intensity gives back the picture exactly.
rep.PolarizationImage = 'DoLP'
dolp_image = shot('glass_dolp')
rep.PolarizationImage = 'AoP'
aop_image = shot('glass_aop')
rep.PolarizationImage = 'Intensity'
intensity_again = shot('glass_intensity_again')
lit = covered(unpolarized)
brightest = unpolarized[..., :3].astype(int).sum(axis=-1) * lit
peak = numpy.unravel_index(numpy.argmax(brightest), brightest.shape)
hi = dolp_image[peak][:3].astype(int)
check(hi[1] > 170 and hi[2] < 120 and difference(dolp_image, aop_image) > 5 and
      abs(intensity_again - unpolarized).max() == 0,
      'PolarizationImage DoLP: the highlight is highly polarized (colour %s); AoP differs (%.1f); '
      'Intensity restores the picture (max %d)'
      % (list(hi), difference(dolp_image, aop_image), abs(intensity_again - unpolarized).max()))
RemoveLight(side)
headlight.Intensity = 1.0
# Polarized lights (eq. 8.6): the headlight's reflection off glass keeps its
# polarization, so an analyser parallel to the light's polarizer passes the
# highlight and a crossed one removes it; -1 gives back the picture.
before = shot('glass_headlight')
rep.LightPolarizer = 0
rep.Polarizer = 0
parallel = shot('glass_light_polarizer_0_analyser_0')
rep.Polarizer = 90
crossed = shot('glass_light_polarizer_0_analyser_90')
rep.Polarizer = -1
rep.LightPolarizer = -1
restored = shot('glass_headlight_again')
check(parallel.astype(float).sum() > crossed.astype(float).sum() and
      difference(parallel, crossed) > 0.1 and abs(restored - before).max() == 0,
      'LightPolarizer 0: the analyser at 0 passes the highlight, at 90 removes it '
      '(mean difference %.2f); -1 restores the picture (max %d)'
      % (difference(parallel, crossed), abs(restored - before).max()))
rep.MaterialPreset = 'Custom'
custom = shot('preset_custom')
check(abs(gold_title - gold_kebab).max() == 0 and difference(gold_title, custom) > 5,
      "MaterialPreset 'Gold' and 'gold' are one material (max diff %d), unlike Custom (%.1f)"
      % (abs(gold_title - gold_kebab).max(), difference(gold_title, custom)))
rep.Ambient = 0.0
rep.AmbientReflectance = 0.0
# Linearity is a property of the Clamp display (PBR Neutral, the default,
# compresses highlights): measured there.
rep.DisplayTransform = 'Clamp'
full = shot('light_intensity_1')
rep.LightIntensity = 0.5
half = shot('light_intensity_half')
rep.LightIntensity = 1.0
mask = covered(full) & (full.max(axis=2) < 250)  # unclipped pixels only
ratio = half[mask].sum() / max(full[mask].sum(), 1)
check(abs(ratio - 0.5) < 0.02, 'LightIntensity 0.5 halves the unclipped pixels (ratio %.3f)' % ratio)
# The default display does not clip: the highlight that saturates under
# Clamp stays below 255 under PBR Neutral.
rep.LightIntensity = 3.0
clamped = shot('display_clamp')
rep.DisplayTransform = 'PBR Neutral'
neutral = shot('display_neutral')
rep.LightIntensity = 1.0
at255 = lambda img: int((covered(img) & (img.max(axis=2) == 255)).sum())
check(at255(clamped) > 100 and at255(neutral) == 0,
      'DisplayTransform: Clamp saturates %d pixels, PBR Neutral %d' % (at255(clamped), at255(neutral)))
rep.AmbientReflectance = 0.05

# 7. Coloured by data on the CPU: `shadinglab render --backend cpu
#    --color-by Elevation` (ParaView's Cool to Warm, the data's range, the
#    scalar interpolated before mapping) against the representation
#    coloured by Elevation with ParaView's default lookup table, for the
#    same camera, headlight and material: within the parity thresholds.
rep.MaterialPreset = 'Custom'
rep.ReflectanceModel = 'Blinn-Phong'
rep.Kd = 0.7
rep.Ks = 0.3
rep.Shininess = 32
rep.AmbientReflectance = 0.0
# The whole model on data, highlights included (Auto leaves them off a
# surface coloured by data: section 7c).
rep.Highlights = 'On'
ColorBy(rep, ('POINTS', 'Elevation'))
# The CLI's default map, named: ParaView 6.0's default is Fast.
GetColorTransferFunction('Elevation').ApplyPreset('Cool to Warm', True)
rep.RescaleTransferFunctionToDataRange(True)
camera = view.GetActiveCamera()  # as section 2 set it up, then reset in 6
camera.Azimuth(20)
camera.Elevation(25)
Render(view)
pos, focal, up = camera.GetPosition(), camera.GetFocalPoint(), camera.GetViewUp()
direction = [p - f for p, f in zip(pos, focal)]
colored_camera = (pos, focal, up, camera.GetParallelScale(), camera.GetClippingRange())
colored_path = os.path.join(outdir, 'elevation.vtp')
SaveData(colored_path, proxy=elevation)
# Flat on the large facets (as in section 2: ParaView's double coordinates
# move facet edges by a fraction of a pixel, and a facet step is large).
coarse_elevation = corner_elevation(coarse_reader)
coarse_colored_path = os.path.join(outdir, 'coarse_elevation.vtp')
SaveData(coarse_colored_path, proxy=coarse_elevation)
coarse_colored = Show(coarse_elevation, view)
coarse_colored.Representation = 'ShadingLab Surface'
for prop in ['ReflectanceModel', 'Kd', 'Ks', 'Shininess', 'AmbientReflectance', 'Highlights']:
    coarse_colored.GetProperty(prop).SetData(rep.GetProperty(prop).GetData())
ColorBy(coarse_colored, ('POINTS', 'Elevation'))
coarse_colored.ShadingMode = 'Flat'
def cpu_parity(label, path, cli_mode, flat=False, model='blinn-phong', highlights='on'):
    """The view against `shadinglab render --backend cpu` of `path`
    coloured by Elevation for the same camera, light and material; returns
    the view's picture."""
    ours = shot('cpu_colored_' + label)
    ref_path = os.path.join(outdir, 'cli_cpu_colored_%s.png' % label)
    subprocess.run([cli, 'render', path, '--backend', 'cpu', '--mode', cli_mode,
                    '--model', model, '--kd', '0.7', '--ks', '0.3', '--shininess', '32',
                    '--ambient', '0', '--color-by', 'Elevation', '--display', 'neutral',
                    '--highlights', highlights,
                    '--size', '%dx%d' % (W, H), '--camera-position', vector(pos),
                    '--focal-point', vector(focal), '--view-up', vector(up),
                    '--view-angle', '%.17g' % camera.GetViewAngle(),
                    '--light', 'dir:' + vector(direction), '--out', ref_path], check=True)
    ref = read_png(ref_path)
    mask = covered(ours)
    mask[:, W - W // 4:] = False  # the CLI's legend
    interior = mask.copy()
    interior[1:, :] &= mask[:-1, :]
    interior[:-1, :] &= mask[1:, :]
    interior[:, 1:] &= mask[:, :-1]
    interior[:, :-1] &= mask[:, 1:]
    d = numpy.abs(ours[interior] - ref[interior])
    mean, p99 = d.mean(), numpy.percentile(d, 99)
    # The CPU renderer's thresholds against the GPU (GpuParityGLTest): mean
    # 1/255, p99 4/255; flat held to its 90th percentile (facet edges).
    ok = (d.mean() <= 2.0 and numpy.percentile(d, 90) <= 2) if flat else (mean <= 1.0 and p99 <= 4)
    check(interior.sum() > 5000 and ok,
          '%s coloured by Elevation: the CPU renderer matches ParaView (mean %.3f, p90 %.1f, p99 %.1f '
          'over %d pixels)' % (label, mean, numpy.percentile(d, 90), p99, interior.sum()))
    return ours


for mode, cli_mode in [('Flat', 'flat'), ('Gouraud', 'gouraud'), ('Phong', 'phong'),
                       ('Fast Phong', 'fast-phong')]:
    rep.ShadingMode = mode
    rep.Visibility = int(mode != 'Flat')
    coarse_colored.Visibility = int(mode == 'Flat')
    path = coarse_colored_path if mode == 'Flat' else colored_path
    # One lookup table per array name: spanned to the shown mesh's range.
    (coarse_colored if mode == 'Flat' else rep).RescaleTransferFunctionToDataRange(False)
    cpu_parity(cli_mode, path, cli_mode, flat=mode == 'Flat')

# 7b. A mesh without normals whose default crease split (Feature Angle 30)
#     adds points: a closed cylinder, points shared where the caps meet the
#     side. The split points keep their Elevation colour (the mapper once
#     mapped the unsplit input's scalars: they took colours from past the
#     array's end), as the CPU renderer draws them.
from vtkmodules.vtkFiltersSources import vtkCylinderSource  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkTriangleFilter  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter  # noqa: E402
source = vtkCylinderSource()
source.SetResolution(32)
source.SetHeight(1.5)
source.Update()
bare = source.GetOutput()
bare.GetPointData().SetNormals(None)
bare.GetPointData().SetTCoords(None)
merged = vtkCleanPolyData()
merged.SetInputData(bare)
triangles = vtkTriangleFilter()
triangles.SetInputConnection(merged.GetOutputPort())
cylinder_path = os.path.join(outdir, 'creased_cylinder.vtp')
writer = vtkXMLPolyDataWriter()
writer.SetInputConnection(triangles.GetOutputPort())
writer.SetFileName(cylinder_path)
writer.Write()
cylinder_elevation = Elevation(Input=OpenDataFile(cylinder_path), LowPoint=[0, -0.75, 0],
                               HighPoint=[0, 0.75, 0])
cylinder_colored_path = os.path.join(outdir, 'creased_cylinder_elevation.vtp')
SaveData(cylinder_colored_path, proxy=cylinder_elevation)
rep.Visibility = 0
coarse_colored.Visibility = 0
cylinder = Show(OpenDataFile(cylinder_colored_path), view)
cylinder.Representation = 'ShadingLab Surface'
for prop in ['ReflectanceModel', 'Kd', 'Ks', 'Shininess', 'AmbientReflectance', 'Highlights']:
    cylinder.GetProperty(prop).SetData(rep.GetProperty(prop).GetData())
cylinder.ShadingMode = 'Phong'
ColorBy(cylinder, ('POINTS', 'Elevation'))
cylinder.RescaleTransferFunctionToDataRange(False)
ResetCamera(view)
camera.Elevation(30)
Render(view)
pos, focal, up = camera.GetPosition(), camera.GetFocalPoint(), camera.GetViewUp()
direction = [p - f for p, f in zip(pos, focal)]
cpu_parity('creased_cylinder_phong', cylinder_colored_path, 'phong')

# 7c. Highlights Auto (the default): a surface coloured by data is drawn
#     without its specular lobe or grey ambient (render::MaterialForData),
#     as the CLI draws it, and differs from the picture with highlights.
with_highlights = shot('cylinder_highlights_on')
cylinder.Highlights = 'Auto'
Render(view)
without = cpu_parity('creased_cylinder_phong_auto', cylinder_colored_path, 'phong', highlights='auto')
inside = covered(without) & covered(with_highlights)
check(numpy.abs(without[inside] - with_highlights[inside]).max() > 40,
      'Highlights Auto on data drops the highlights (max change %d over %d pixels)' % (
          numpy.abs(without[inside] - with_highlights[inside]).max(), inside.sum()))
cylinder.Highlights = 'On'

# 8. The lights' solid angle (LightSolidAngle, eq. 1.1): irradiance I_L dw,
#    so pi / 2 halves a white Lambertian sphere's brightest pixel (linear,
#    Clamp display).
cylinder.Visibility = 0
ball = Show(Sphere(ThetaResolution=64, PhiResolution=32), view)
ball.Representation = 'ShadingLab Surface'
ball.ShadingMode = 'Phong'
ball.MaterialPreset = 'Custom'
ball.ReflectanceModel = 'Lambert'
ball.Ks = 0.0
ball.Kd = 1.0
ball.AmbientReflectance = 0.0
ball.DisplayTransform = 'Clamp'
ResetCamera(view)
brightest = {}
for solid_angle in (math.pi, math.pi / 2):
    ball.LightSolidAngle = solid_angle
    brightest[solid_angle] = shot('solid_angle_%.4f' % solid_angle)[:, :, 1].max()
check(brightest[math.pi] > 200 and abs(brightest[math.pi / 2] - brightest[math.pi] / 2) <= 1.5,
      'LightSolidAngle pi/2 halves the irradiance (%.0f -> %.0f)' % (brightest[math.pi], brightest[math.pi / 2]))

# 9. Backend CPU: the representation drawn by the CPU renderer and handed to
#    OpenGL as colour and depth. Every mode x model coloured by Elevation
#    against the standalone CPU renderer (section 7's check; flat against
#    the GPU only) and against Backend GPU (the parity thresholds); a native Surface plane cutting
#    through it occludes the same pixels on both backends.
ball.Visibility = 0
rep.Visibility = 1
# Section 7's camera, where the standalone comparison is known to hold.
pos, focal, up = colored_camera[:3]
camera.SetPosition(pos)
camera.SetFocalPoint(focal)
camera.SetViewUp(up)
view.CameraParallelScale = colored_camera[3]
Render(view)
direction = [p - f for p, f in zip(pos, focal)]
rep.RescaleTransferFunctionToDataRange(False)
for mode, cli_mode in [('Gouraud', 'gouraud'), ('Phong', 'phong'), ('Fast Phong', 'fast-phong'),
                       ('Flat', 'flat')]:
    for model in ['Blinn-Phong', 'Cook-Torrance', 'Lambert']:
        if mode == 'Fast Phong' and model == 'Cook-Torrance':
            continue  # no quadratic form: the GPU draws it as Phong
        rep.ShadingMode = mode
        rep.ReflectanceModel = model
        rep.Backend = 'GPU'
        on_gpu = shot('backend_gpu_%s_%s' % (cli_mode, model.lower()))
        rep.Backend = 'CPU'
        if mode == 'Flat':
            # Flat on this fine torus: ParaView's double coordinates move
            # facet edges by a fraction of a pixel against the file's floats
            # (section 7 compares flat on large facets); the backends agree.
            on_cpu = shot('backend_cpu_%s_%s' % (cli_mode, model.lower()))
        else:
            on_cpu = cpu_parity('backend_cpu_%s_%s' % (cli_mode, model.lower()), colored_path,
                                cli_mode, model=model.lower())
        both = covered(on_gpu) & covered(on_cpu)
        d = numpy.abs(on_gpu[both] - on_cpu[both])
        ok = (d.mean() <= 2.0 and numpy.percentile(d, 90) <= 2) if mode == 'Flat' else \
            (d.mean() <= 1.0 and numpy.percentile(d, 99) <= 4)
        check(both.sum() > 5000 and ok, 'Backend CPU against GPU, %s %s: mean %.3f, p99 %.1f'
              % (mode, model, d.mean(), numpy.percentile(d, 99)))
rep.ShadingMode = 'Phong'
rep.ReflectanceModel = 'Blinn-Phong'
# The backend each render drew with, reported as the auto mode reports its
# choice (information property BackendChoice): CPU and GPU as asked; Auto
# names the context's renderer and the polygon count against the crossover.
choices = {}
for backend in ['CPU', 'GPU', 'Auto']:
    rep.Backend = backend
    Render(view)
    rep.UpdatePropertyInformation()
    choices[backend] = rep.GetProperty('BackendChoice').GetData().strip()
auto = choices['Auto']
check(choices['CPU'] == 'cpu' and choices['GPU'] == 'gpu' and
      auto.split(':')[0] in ('cpu', 'gpu') and "OpenGL renderer '" in auto and 'polygons' in auto,
      'BackendChoice reports each render: %r' % choices)
rep.Backend = 'GPU'
plane = Show(Plane(Origin=[-2, -2, -1], Point1=[2, -2, 1], Point2=[-2, 2, -1]), view)
plane.ColorArrayName = [None, '']
plane.AmbientColor = plane.DiffuseColor = [0.0, 1.0, 0.0]
plane.Ambient, plane.Diffuse, plane.Specular = 1.0, 0.0, 0.0
green = {}
for backend in ['GPU', 'CPU']:
    rep.Backend = backend
    image = shot('interpenetrating_' + backend.lower())
    green[backend] = int(((image[:, :, 1] > 230) & (image[:, :, 0] < 25) & (image[:, :, 2] < 25)).sum())
rep.Visibility = 0
alone = shot('plane_alone')
green_alone = int(((alone[:, :, 1] > 230) & (alone[:, :, 0] < 25) & (alone[:, :, 2] < 25)).sum())
check(green['GPU'] > 2000 and abs(green['CPU'] - green['GPU']) <= 0.01 * green['GPU']
      and green_alone > green['GPU'] + 1000,
      'a native plane through the surface occludes alike on both backends (%d, %d green pixels; '
      '%d without the surface)' % (green['GPU'], green['CPU'], green_alone))

# The same plane translucent (depth peeling, ParaView's default) over the
# surface, and a selection's highlight (cells picked by id, drawn by
# ParaView's selection representation on top): both native passes see the
# CPU backend's colour and depth as they see the GL path's.
rep.Visibility = 1
plane.Opacity = 0.5
SelectIDs(IDs=sum(([0, k] for k in range(0, 2000, 7)), []),
          FieldType='CELL', Source=elevation)
layered = {}
for backend in ['GPU', 'CPU']:
    rep.Backend = backend
    layered[backend] = shot('translucent_selected_' + backend.lower())
ClearSelection(elevation)
plain = shot('translucent_unselected_cpu')
both = covered(layered['GPU']) & covered(layered['CPU'])
d = numpy.abs(layered['GPU'][both] - layered['CPU'][both])
highlighted = numpy.any(layered['CPU'] != plain, axis=2).sum()
check(both.sum() > 5000 and d.mean() <= 1.0 and numpy.percentile(d, 99) <= 4 and highlighted > 500,
      'translucent native plane and selection highlight over Backend CPU as over GPU: mean %.3f, '
      'p99 %.1f /255; the selection changes %d pixels' % (d.mean(), numpy.percentile(d, 99), highlighted))
plane.Opacity = 1.0

print('%d failure(s)' % len(failures))
sys.exit(1 if failures else 0)
