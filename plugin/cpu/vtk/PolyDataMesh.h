// SPDX-License-Identifier: BSD-3-Clause
// vtkPolyData -> the renderer's flat Mesh arrays.
#pragma once

#include "shadinglab/cpu/SoftwareRenderer.h"

class vtkPolyData;

namespace shadinglab::cpu
{

/**
 * Copies points, point normals (active normals), point colours (active
 * scalars when unsigned char with 3 or 4 components, used as linear RGB like
 * VTK's GL path does), polygons (triangle strips converted to triangles) and
 * active cell normals. The input is not modified.
 */
Mesh MeshFromPolyData(vtkPolyData* polydata);

} // namespace shadinglab::cpu
