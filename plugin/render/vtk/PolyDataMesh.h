// SPDX-License-Identifier: BSD-3-Clause
// vtkPolyData <-> the renderers' flat Mesh arrays.
#pragma once

#include "shadinglab/render/ColorMap.h"
#include "shadinglab/render/Scene.h"
#include "shadinglab/render/Settings.h"

#include <vtkSmartPointer.h>

#include <string>

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
 * Concave polygons, and polygons of more than 63 corners, are split by
 * ear clipping, unless `polygons` is Direct: then polygons of up to 63
 * corners stay whole, concave or not, for the CPU renderer's even-odd scan
 * (pass Direct only where ScansPolygonsWhole: a fan of a concave polygon
 * fills its notches).
 */
Mesh MeshFromPolyData(vtkPolyData* polydata, WorldFrame& frame,
  PolygonHandling polygons = PolygonHandling::Triangulate);

/**
 * MeshFromPolyData(polydata, frame, polygons) for a caller that is done
 * with `polydata` (pass it with std::move): triangles in 64-bit storage
 * are not copied, the mesh shares their arrays (IdArray::Shared); other
 * polygons are released as soon as they are copied, before the points and
 * normals. Either way the two copies of a big mesh never coexist whole
 * (16M triangles: 0.5 GB less at the peak). The polydata is left without
 * polygons.
 */
Mesh MeshFromPolyDataReleasing(vtkSmartPointer<vtkPolyData> polydata, WorldFrame& frame,
  PolygonHandling polygons = PolygonHandling::Triangulate);

/// The data array to colour by, as `--color-by` spells it:
/// "[POINTS:|CELLS:]NAME[:COMPONENT|Magnitude]".
struct ScalarField
{
  enum class Association
  {
    Any,    ///< point data first, then cell data (as ParaView looks a name up)
    Points,
    Cells
  };
  std::string name;
  Association association = Association::Any;
  int component = -1; ///< -1: the magnitude (ParaView's default for vectors)
};

/// Parses a --color-by spelling; "" or a one-line error.
std::string ParseScalarField(const std::string& spec, ScalarField& field);

/**
 * MeshFromPolyData(polydata, frame) that also copies `field` into
 * mesh.scalars (point data) or mesh.cellScalars (cell data, following
 * the polygons the conversion makes). Throws std::invalid_argument with one
 * line naming the arrays there are when the field is not found or its
 * component does not exist. `range` gets the finite values' [min, max]
 * ([0, 1] when there are none; their middle twice when they span at most a
 * few float ulps, kConstantFieldUlps: a field constant up to rounding is
 * drawn as a constant one).
 */
Mesh MeshFromPolyData(vtkPolyData* polydata, WorldFrame& frame, const ScalarField& field,
  double range[2], PolygonHandling polygons = PolygonHandling::Triangulate);

/**
 * Colour by data as every front end spells it (render::ColorBySettings:
 * the array, the colour map, "auto" or "MIN,MAX"): the mesh in `frame` with
 * the array's values, `map` through the named colour map over the range
 * (the data's for "auto"), and the legend's `title` ("Velocity 0").
 * Returns "" or a one-line error naming the setting with `prefix` ("--"
 * on the command line). `polygons` as for MeshFromPolyData.
 */
std::string MeshColoredBy(vtkPolyData* polydata, WorldFrame& frame, const ColorBySettings& color,
  const std::string& prefix, Mesh& mesh, ColorMap& map, std::string& title,
  PolygonHandling polygons = PolygonHandling::Triangulate);

/**
 * MeshColoredBy's check of the array alone: "" when `polydata` has it (and
 * the component), or the same one-line error. Front ends check the mesh as
 * read, before preparing it adds arrays of its own (Normals,
 * OriginalPointIds) that an error listing the arrays would name.
 */
std::string CheckColorArray(vtkPolyData* polydata, const ColorBySettings& color,
  const std::string& prefix);

/**
 * The inverse: points, point normals (active), colours as a float RGB
 * array in [0, 1] (active scalars, to be mapped as direct scalars), polygons
 * and cell normals (active), and the scalars or cellScalars as a point or
 * cell array "Scalars". The caller owns the result (refcount 1).
 */
vtkPolyData* PolyDataFromMesh(const Mesh& mesh);

} // namespace shadinglab::render
