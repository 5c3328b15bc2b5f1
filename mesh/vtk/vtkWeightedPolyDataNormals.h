// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkWeightedPolyDataNormals
 * @brief   vertex normals with selectable weights and crease splitting
 *
 * Computes point normals of a polygonal surface from its face normals with
 * one of four weightings: UNIFORM (unit face normals, what OpenMesh's
 * update_vertex_normals and Gouraud's average do), AREA (face area, the
 * default), ANGLE (corner angle; Thurmer & Wuthrich 1998) or MAX (Max 1999,
 * exact for a sphere). Edges whose dihedral angle exceeds FeatureAngle
 * (default 30 degrees), boundary and non-manifold edges, and edges given as
 * input lines (UseLinesAsFeatureEdges) are creases: the points on them are
 * split so each side keeps its own normal. Split points copy the point data
 * of their original; "OriginalPointIds" maps every output point to its input
 * point. Cell data is passed unchanged.
 *
 * With Consistency on (the default, as in vtkPolyDataNormals), polygons
 * whose neighbours run a shared edge the same way are first turned so that
 * each connected component is consistently oriented (outward when closed;
 * mesh/core/Orientation.h); the output's polygons are the turned ones.
 *
 * @warning Triangle strips are triangulated first. The input is never
 * modified.
 */
#ifndef vtkWeightedPolyDataNormals_h
#define vtkWeightedPolyDataNormals_h

#include "shadinglabMeshModule.h" // for export macro

#include <vtkPolyDataAlgorithm.h>
#include <vtkSmartPointer.h> // for MakeOutput

#include <functional> // for MakeOutput

class vtkCellArray;
#ifndef __VTK_WRAP__
namespace shadinglab
{
namespace mesh
{
struct NormalResult;
}
}
#endif

class SHADINGLABMESH_EXPORT vtkWeightedPolyDataNormals : public vtkPolyDataAlgorithm
{
public:
  static vtkWeightedPolyDataNormals* New();
  vtkTypeMacro(vtkWeightedPolyDataNormals, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Weightings
  {
    UNIFORM = 0,
    AREA = 1,
    ANGLE = 2,
    MAX = 3
  };

  ///@{
  /// Face-normal weighting (default AREA).
  vtkSetClampMacro(Weighting, int, UNIFORM, MAX);
  vtkGetMacro(Weighting, int);
  ///@}

  ///@{
  /// Split points on creases (default on).
  vtkSetMacro(Splitting, bool);
  vtkGetMacro(Splitting, bool);
  vtkBooleanMacro(Splitting, bool);
  ///@}

  ///@{
  /// Dihedral angle in degrees above which an edge is a crease (default 30,
  /// range 0..180).
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /// Treat the input's line cells as explicit feature edges (default on).
  vtkSetMacro(UseLinesAsFeatureEdges, bool);
  vtkGetMacro(UseLinesAsFeatureEdges, bool);
  vtkBooleanMacro(UseLinesAsFeatureEdges, bool);
  ///@}

  ///@{
  /// Make the orientation consistent first when it is not (default on).
  vtkSetMacro(Consistency, bool);
  vtkGetMacro(Consistency, bool);
  vtkBooleanMacro(Consistency, bool);
  ///@}

  ///@{
  /// Counts from the last execution (edge counts need Splitting on).
  vtkGetMacro(NumberOfCreaseEdges, vtkIdType);
  vtkGetMacro(NumberOfSplitPoints, vtkIdType);
  vtkGetMacro(NumberOfNonManifoldEdges, vtkIdType);
  vtkGetMacro(NumberOfBoundaryEdges, vtkIdType);
  vtkGetMacro(NumberOfFlippedPolygons, vtkIdType);
  ///@}

protected:
  vtkWeightedPolyDataNormals() = default;
  ~vtkWeightedPolyDataNormals() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Weighting = AREA;
  bool Splitting = true;
  double FeatureAngle = 30.0;
  bool UseLinesAsFeatureEdges = true;
  bool Consistency = true;
  vtkIdType NumberOfFlippedPolygons = 0;
  vtkIdType NumberOfCreaseEdges = 0;
  vtkIdType NumberOfSplitPoints = 0;
  vtkIdType NumberOfNonManifoldEdges = 0;
  vtkIdType NumberOfBoundaryEdges = 0;

private:
#ifndef __VTK_WRAP__
  /// The output from the normals: points (split copies appended), the
  /// normals and OriginalPointIds, and the input's polygons, or
  /// newPolygons() when corners moved to split points or faces were turned.
  void MakeOutput(vtkPolyData* source, vtkPolyData* output, shadinglab::mesh::NormalResult& result,
    const std::function<vtkSmartPointer<vtkCellArray>()>& newPolygons, bool turned = false);
#endif
  vtkWeightedPolyDataNormals(const vtkWeightedPolyDataNormals&) = delete;
  void operator=(const vtkWeightedPolyDataNormals&) = delete;
};

#endif
