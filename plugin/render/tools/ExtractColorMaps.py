# SPDX-License-Identifier: BSD-3-Clause
"""Build step (pvpython): ParaView's colour-map presets as C++ tables.

ParaView compiles its presets into its libraries (vtkSMTransferFunctionPresets).
For each preset below this evaluates ParaView's own lookup table as the
ShadingLab Surface representation gets it by default (a
vtkDiscretizableColorTransferFunction with the preset's points and colour
space, Discretize on, 256 values) at the centre of each of the 256 bins,
as 8-bit RGB (what VTK uploads), and writes them with the NaN colour.

usage: pvpython ExtractColorMaps.py OUT.h
"""
import json
import sys

from paraview.modules.vtkRemotingViews import vtkSMTransferFunctionPresets
from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkRenderingCore import vtkDiscretizableColorTransferFunction

# The names users know from ParaView's Choose Preset dialog, with the older
# spelling where ParaView renamed a preset ("Viridis (matplotlib)" became
# "Viridis" in 6.0): the table is the same whichever ParaView builds it, and
# users may type either spelling.
NAMES = [("Cool to Warm", ""), ("Viridis", "Viridis (matplotlib)"),
         ("Inferno", "Inferno (matplotlib)"), ("Plasma", "Plasma (matplotlib)"),
         ("Rainbow Uniform", ""), ("Jet", ""), ("Turbo", ""), ("Grayscale", ""), ("X Ray", ""),
         ("Black-Body Radiation", ""), ("Blue Orange (divergent)", "")]
BINS = 256  # ParaView's default NumberOfTableValues

presets = vtkSMTransferFunctionPresets.GetInstance()
index = {presets.GetPresetName(i): i for i in range(presets.GetNumberOfPresets())}


def key_of(name):
    """Command-line spelling: 'Viridis (matplotlib)' -> 'viridis'."""
    return name.split(' (')[0].lower().replace(' ', '-')


rows = []
for name, alias in NAMES:
    found = [n for n in (name, alias) if n in index]
    if not found:
        sys.exit("ExtractColorMaps.py: this ParaView has no preset '%s'%s" %
                 (name, " or '%s'" % alias if alias else ""))
    preset = json.loads(presets.GetPresetAsString(index[found[0]]))
    points = preset['RGBPoints']
    x0, x1 = points[0], points[-4]
    lut = vtkDiscretizableColorTransferFunction()
    space = preset.get('ColorSpace', 'RGB')
    {'RGB': lut.SetColorSpaceToRGB, 'Lab': lut.SetColorSpaceToLab, 'HSV': lut.SetColorSpaceToHSV,
     'Diverging': lut.SetColorSpaceToDiverging, 'Step': lut.SetColorSpaceToStep,
     'Lab/CIEDE2000': lut.SetColorSpaceToLabCIEDE2000}.get(space, lut.SetColorSpaceToRGB)()
    for i in range(0, len(points), 4):
        lut.AddRGBPoint((points[i] - x0) / (x1 - x0), points[i + 1], points[i + 2], points[i + 3])
    lut.DiscretizeOn()
    lut.SetNumberOfValues(BINS)
    lut.Build()
    centres = vtkDoubleArray()
    for b in range(BINS):
        centres.InsertNextValue((b + 0.5) / BINS)
    mapped = lut.MapScalars(centres, 0, -1)  # 8-bit RGBA, as VTK uploads it
    rgb = []
    for b in range(BINS):
        rgb += [mapped.GetValue(4 * b + c) for c in range(3)]
    nan = preset.get('NanColor', [1, 1, 0])
    rows.append((name, alias, key_of(name), rgb, [int(round(255 * v)) for v in nan[:3]]))

with open(sys.argv[1], 'w') as out:
    out.write('// Generated at build time by plugin/render/tools/ExtractColorMaps.py from\n'
              '// ParaView\'s presets (vtkSMTransferFunctionPresets). Do not edit.\n#pragma once\n\n'
              'namespace shadinglab::render::generated\n{\n'
              'struct ColorMapTable\n{\n  const char* label;\n  const char* alias;\n  const char* key;\n'
              '  unsigned char rgb[%d];\n  unsigned char nan[3];\n};\n\n' % (3 * BINS))
    out.write('inline constexpr int kColorMapBins = %d;\n' % BINS)
    out.write('inline constexpr ColorMapTable kColorMapTables[] = {\n')
    for name, alias, key, rgb, nan in rows:
        out.write('  { "%s", "%s", "%s", { %s }, { %s } },\n' % (name, alias, key, ', '.join(map(str, rgb)),
                                                           ', '.join(map(str, nan))))
    out.write('};\n\n} // namespace shadinglab::render::generated\n')
