// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadingLabRepair
 * @brief   ParaView filter: mesh repair (ShadingLab)
 *
 * Runs vtkMeshRepair (mesh/vtk, OpenMesh for non-manifold faces): welds
 * coincident points within a tolerance relative to the bounding box
 * (keeping seams where point data differ, when asked), removes degenerate
 * faces, orients each component consistently (outward when closed) and
 * splits edges at T-junctions. The input is not modified.
 * On distributed data (several MPI ranks) the mesh is gathered on rank 0,
 * repaired as a whole and handed back by owner (GatheredPolyData.h): the
 * result is the one-rank result, partitioned as the input was; the
 * OriginalPointIds array is then dropped (it would number the gathered
 * mesh's points).
 */
#ifndef vtkShadingLabRepair_h
#define vtkShadingLabRepair_h

#include "shadinglabParaViewModule.h" // for export macro

#include <vtkPolyDataAlgorithm.h>

class SHADINGLABPARAVIEW_EXPORT vtkShadingLabRepair : public vtkPolyDataAlgorithm
{
public:
  static vtkShadingLabRepair* New();
  vtkTypeMacro(vtkShadingLabRepair, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Weld coincident points (default on).
  vtkSetMacro(Weld, bool);
  vtkGetMacro(Weld, bool);
  ///@}

  ///@{
  /// Weld distance relative to the bounding-box diagonal, [0, 0.1] (default 1e-6).
  vtkSetClampMacro(WeldTolerance, double, 0.0, 0.1);
  vtkGetMacro(WeldTolerance, double);
  ///@}

  ///@{
  /// Keep points apart where their point data differ (default on).
  vtkSetMacro(KeepAttributeSeams, bool);
  vtkGetMacro(KeepAttributeSeams, bool);
  ///@}

  ///@{
  /// Make orientation consistent, outward for closed components (default on).
  vtkSetMacro(FixOrientation, bool);
  vtkGetMacro(FixOrientation, bool);
  ///@}

  ///@{
  /// Split edges at T-junctions (default off).
  vtkSetMacro(FixTJunctions, bool);
  vtkGetMacro(FixTJunctions, bool);
  ///@}

  ///@{
  /// T-junction distance relative to the bounding-box diagonal, [0, 0.1] (default 1e-6).
  vtkSetClampMacro(TJunctionTolerance, double, 0.0, 0.1);
  vtkGetMacro(TJunctionTolerance, double);
  ///@}

protected:
  vtkShadingLabRepair() = default;
  ~vtkShadingLabRepair() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  bool Weld = true;
  double WeldTolerance = 1e-6;
  bool KeepAttributeSeams = true;
  bool FixOrientation = true;
  bool FixTJunctions = false;
  double TJunctionTolerance = 1e-6;

private:
  vtkShadingLabRepair(const vtkShadingLabRepair&) = delete;
  void operator=(const vtkShadingLabRepair&) = delete;
};

#endif
