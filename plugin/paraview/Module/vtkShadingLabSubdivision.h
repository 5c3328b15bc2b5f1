// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadingLabSubdivision
 * @brief   ParaView filter: OpenSubdiv refinement with limit normals (ShadingLab)
 *
 * Runs vtkOpenSubdivRefine (mesh/vtk): Loop for triangle meshes,
 * Catmull-Clark for quads and polygons (or either on request), 1 to 6
 * levels, edges sharper than FeatureAngle (and line cells) carried as
 * creases of the given sharpness, points projected to the limit surface
 * with its normals. The input is not modified.
 * On distributed data each rank refines its piece with two rings of its
 * neighbours' faces (BoundaryGhosts.h) and keeps only its own: the limit
 * surface is the serial one, with no seam at partition boundaries.
 */
#ifndef vtkShadingLabSubdivision_h
#define vtkShadingLabSubdivision_h

#include "shadinglabParaViewModule.h" // for export macro

#include <vtkPolyDataAlgorithm.h>

class SHADINGLABPARAVIEW_EXPORT vtkShadingLabSubdivision : public vtkPolyDataAlgorithm
{
public:
  static vtkShadingLabSubdivision* New();
  vtkTypeMacro(vtkShadingLabSubdivision, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// 0 automatic (default: Loop for triangles, else Catmull-Clark), 1 Loop, 2 Catmull-Clark.
  vtkSetClampMacro(Scheme, int, 0, 2);
  vtkGetMacro(Scheme, int);
  ///@}

  ///@{
  /// Refinement levels, [1, 6] (default 1); each level multiplies the faces by 4.
  vtkSetClampMacro(Levels, int, 1, 6);
  vtkGetMacro(Levels, int);
  ///@}

  ///@{
  /// Carry edges sharper than FeatureAngle as creases (default on).
  vtkSetMacro(UseFeatureAngle, bool);
  vtkGetMacro(UseFeatureAngle, bool);
  ///@}

  ///@{
  /// Crease angle in degrees, [0, 180] (default 30).
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /// OpenSubdiv sharpness of creases, [0, 10] (default 10: infinitely sharp).
  vtkSetClampMacro(CreaseSharpness, double, 0.0, 10.0);
  vtkGetMacro(CreaseSharpness, double);
  ///@}

  ///@{
  /// Points on the limit surface with limit normals (default on).
  vtkSetMacro(ProjectToLimit, bool);
  vtkGetMacro(ProjectToLimit, bool);
  ///@}

protected:
  vtkShadingLabSubdivision() = default;
  ~vtkShadingLabSubdivision() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int Scheme = 0;
  int Levels = 1;
  bool UseFeatureAngle = true;
  double FeatureAngle = 30.0;
  double CreaseSharpness = 10.0;
  bool ProjectToLimit = true;

private:
  vtkShadingLabSubdivision(const vtkShadingLabSubdivision&) = delete;
  void operator=(const vtkShadingLabSubdivision&) = delete;
};

#endif
