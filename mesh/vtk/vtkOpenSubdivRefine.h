// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOpenSubdivRefine
 * @brief   uniform subdivision with OpenSubdiv, limit positions and normals
 *
 * Refines a polygonal surface Levels times (default 2, range 1..6) with Loop
 * subdivision when every polygon is a triangle and Catmull-Clark otherwise
 * (Scheme AUTO), or with the scheme chosen. Creases: the input's line cells
 * and, when UseFeatureAngle is on, edges whose dihedral angle exceeds
 * FeatureAngle are given CreaseSharpness (default 10: sharp at every level,
 * OpenSubdiv's semi-sharp creases soften after that many levels).
 *
 * Output points are the limit-surface positions of the last level's
 * vertices (ProjectToLimit, default on) and "Normals" the unit cross product
 * of the limit surface's two tangents (du x dv), oriented like the input's
 * polygons. Numeric point data is refined with the same vertex weights;
 * cell data is inherited by each child face from its parent.
 *
 * @warning Loop needs triangles: with Scheme LOOP a non-triangle input is an
 * error. The input is never modified.
 */
#ifndef vtkOpenSubdivRefine_h
#define vtkOpenSubdivRefine_h

#include "shadinglabMeshModule.h" // for export macro

#include <vtkPolyDataAlgorithm.h>

class SHADINGLABMESH_EXPORT vtkOpenSubdivRefine : public vtkPolyDataAlgorithm
{
public:
  static vtkOpenSubdivRefine* New();
  vtkTypeMacro(vtkOpenSubdivRefine, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Schemes
  {
    AUTO = 0,
    LOOP = 1,
    CATMULL_CLARK = 2
  };

  ///@{
  /// Subdivision scheme (default AUTO).
  vtkSetClampMacro(Scheme, int, AUTO, CATMULL_CLARK);
  vtkGetMacro(Scheme, int);
  ///@}

  ///@{
  /// Refinement levels (default 2, range 1..6; each level multiplies the
  /// face count by 4).
  vtkSetClampMacro(Levels, int, 1, 6);
  vtkGetMacro(Levels, int);
  ///@}

  ///@{
  /// Creases from the dihedral angle (default off) above FeatureAngle
  /// (default 30 degrees).
  vtkSetMacro(UseFeatureAngle, bool);
  vtkGetMacro(UseFeatureAngle, bool);
  vtkBooleanMacro(UseFeatureAngle, bool);
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /// Sharpness given to crease edges (default 10, range 0..10).
  vtkSetClampMacro(CreaseSharpness, double, 0.0, 10.0);
  vtkGetMacro(CreaseSharpness, double);
  ///@}

  ///@{
  /// Move the output points to the limit surface (default on).
  vtkSetMacro(ProjectToLimit, bool);
  vtkGetMacro(ProjectToLimit, bool);
  vtkBooleanMacro(ProjectToLimit, bool);
  ///@}

  /// Scheme used by the last execution (LOOP or CATMULL_CLARK).
  vtkGetMacro(SchemeUsed, int);
  vtkGetMacro(NumberOfCreaseEdges, vtkIdType);

protected:
  vtkOpenSubdivRefine() = default;
  ~vtkOpenSubdivRefine() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Scheme = AUTO;
  int Levels = 2;
  bool UseFeatureAngle = false;
  double FeatureAngle = 30.0;
  double CreaseSharpness = 10.0;
  bool ProjectToLimit = true;
  int SchemeUsed = AUTO;
  vtkIdType NumberOfCreaseEdges = 0;

private:
  vtkOpenSubdivRefine(const vtkOpenSubdivRefine&) = delete;
  void operator=(const vtkOpenSubdivRefine&) = delete;
};

#endif
