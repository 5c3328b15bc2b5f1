// SPDX-License-Identifier: BSD-3-Clause
// vtkPolyData <-> the renderers' flat Mesh arrays.
#pragma once

#include "shadinglab/render/Scene.h"

class vtkPolyData;

namespace shadinglab::render
{

/**
 * Copies points, point normals (active normals), point colours (active
 * scalars when unsigned char with 3 or 4 components, used as linear RGB like
 * VTK's GL path does), polygons (triangle strips converted to triangles) and
 * active cell normals. The input is not modified.
 */
Mesh MeshFromPolyData(vtkPolyData* polydata);

/**
 * The same in a local frame (see WorldFrame): points centred on their
 * bounds and scaled to a unit bounding sphere in double before the
 * conversion to float; `frame` says how to map world coordinates.
 */
Mesh MeshFromPolyData(vtkPolyData* polydata, WorldFrame& frame);

/**
 * The inverse: points, point normals (active), colours as a float RGB
 * array in [0, 1] (active scalars, to be mapped as direct scalars), polygons
 * and cell normals (active). The caller owns the result (refcount 1).
 */
vtkPolyData* PolyDataFromMesh(const Mesh& mesh);

} // namespace shadinglab::render
