// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkMeshRepair
 * @brief   welds, cleans, orients and makes manifold a polygonal surface
 *
 * In order: optional welding of coincident points (Weld, tolerance relative
 * to the bounding-box diagonal, default 1e-6; with KeepAttributeSeams points
 * whose point data differ stay apart), removal of degenerate polygons
 * (repeated vertices, zero area), consistent orientation per connected
 * component (outward for closed components), optional T-junction repair
 * (FixTJunctions: vertices lying on another polygon's edge are inserted into
 * that edge), and non-manifold resolution through OpenMesh: a polygon that a
 * halfedge mesh cannot hold (complex edge or vertex) gets its own copies of
 * its vertices rather than being dropped.
 *
 * Point data is copied from each output point's source point
 * ("OriginalPointIds"); cell data from each polygon's source polygon.
 *
 * @warning Only polygons are processed (strips are triangulated; lines and
 * vertices are dropped). The input is never modified.
 */
#ifndef vtkMeshRepair_h
#define vtkMeshRepair_h

#include "shadinglabMeshModule.h" // for export macro

#include <vtkPolyDataAlgorithm.h>

class SHADINGLABMESH_EXPORT vtkMeshRepair : public vtkPolyDataAlgorithm
{
public:
  static vtkMeshRepair* New();
  vtkTypeMacro(vtkMeshRepair, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Weld coincident points (default off) within WeldTolerance times the
  /// bounding-box diagonal (default 1e-6, range 0..0.1).
  vtkSetMacro(Weld, bool);
  vtkGetMacro(Weld, bool);
  vtkBooleanMacro(Weld, bool);
  vtkSetClampMacro(WeldTolerance, double, 0.0, 0.1);
  vtkGetMacro(WeldTolerance, double);
  ///@}

  ///@{
  /// Keep seams: weld only points whose point data are equal (default off).
  vtkSetMacro(KeepAttributeSeams, bool);
  vtkGetMacro(KeepAttributeSeams, bool);
  vtkBooleanMacro(KeepAttributeSeams, bool);
  ///@}

  ///@{
  /// Make orientation consistent, outward on closed parts (default on).
  vtkSetMacro(FixOrientation, bool);
  vtkGetMacro(FixOrientation, bool);
  vtkBooleanMacro(FixOrientation, bool);
  ///@}

  ///@{
  /// Split edges at T-junction vertices (default off), within
  /// TJunctionTolerance times the bounding-box diagonal (default 1e-6).
  vtkSetMacro(FixTJunctions, bool);
  vtkGetMacro(FixTJunctions, bool);
  vtkBooleanMacro(FixTJunctions, bool);
  vtkSetClampMacro(TJunctionTolerance, double, 0.0, 0.1);
  vtkGetMacro(TJunctionTolerance, double);
  ///@}

  ///@{
  /// Counts from the last execution.
  vtkGetMacro(NumberOfWeldedPoints, vtkIdType);
  vtkGetMacro(NumberOfDegenerateCellsRemoved, vtkIdType);
  vtkGetMacro(NumberOfFlippedCells, vtkIdType);
  vtkGetMacro(NumberOfNonManifoldEdges, vtkIdType);
  vtkGetMacro(NumberOfDuplicatedPoints, vtkIdType);
  vtkGetMacro(NumberOfTJunctionsFixed, vtkIdType);
  ///@}

protected:
  vtkMeshRepair() = default;
  ~vtkMeshRepair() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool Weld = false;
  double WeldTolerance = 1e-6;
  bool KeepAttributeSeams = false;
  bool FixOrientation = true;
  bool FixTJunctions = false;
  double TJunctionTolerance = 1e-6;
  vtkIdType NumberOfWeldedPoints = 0;
  vtkIdType NumberOfDegenerateCellsRemoved = 0;
  vtkIdType NumberOfFlippedCells = 0;
  vtkIdType NumberOfNonManifoldEdges = 0;
  vtkIdType NumberOfDuplicatedPoints = 0;
  vtkIdType NumberOfTJunctionsFixed = 0;

private:
  vtkMeshRepair(const vtkMeshRepair&) = delete;
  void operator=(const vtkMeshRepair&) = delete;
};

#endif
