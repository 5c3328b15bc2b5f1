// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadingLabNormals
 * @brief   ParaView filter: weighted vertex normals with creases (ShadingLab)
 *
 * Runs vtkWeightedPolyDataNormals (mesh/vtk): uniform, area (default),
 * angle (Thurmer & Wuthrich 1998) or Max (1999) weighting; normals split at
 * edges sharper than FeatureAngle when Splitting is on. The input is not
 * modified. In parallel it asks for one ghost level, so normals at
 * partition boundaries see the faces of the neighbouring partition.
 */
#ifndef vtkShadingLabNormals_h
#define vtkShadingLabNormals_h

#include "shadinglabParaViewModule.h" // for export macro

#include <vtkPolyDataAlgorithm.h>

class SHADINGLABPARAVIEW_EXPORT vtkShadingLabNormals : public vtkPolyDataAlgorithm
{
public:
  static vtkShadingLabNormals* New();
  vtkTypeMacro(vtkShadingLabNormals, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// 0 uniform, 1 area (default), 2 angle, 3 Max.
  vtkSetClampMacro(Weighting, int, 0, 3);
  vtkGetMacro(Weighting, int);
  ///@}

  ///@{
  /// Crease angle in degrees, [0, 180] (default 30).
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /// Split normals at creases (default on).
  vtkSetMacro(Splitting, bool);
  vtkGetMacro(Splitting, bool);
  ///@}

protected:
  vtkShadingLabNormals() = default;
  ~vtkShadingLabNormals() override = default;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Weighting = 1;
  double FeatureAngle = 30.0;
  bool Splitting = true;

private:
  vtkShadingLabNormals(const vtkShadingLabNormals&) = delete;
  void operator=(const vtkShadingLabNormals&) = delete;
};

#endif
