// SPDX-License-Identifier: BSD-3-Clause
// Meshes the scenes are made of, beyond ShadingLab::Analytic's: every one
// returns a new vtkPolyData (the caller owns a reference through the smart
// pointer) and never modifies its input.
#pragma once

#include "MeshPreparation.h"

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace shadinglab::gui
{

using PolyPtr = vtkSmartPointer<vtkPolyData>;

/// Adopts a new reference (the generators' convention).
PolyPtr Adopt(vtkPolyData* mesh);
/// A copy whose active normals are the "ExactNormal" array.
PolyPtr WithExactNormals(vtkPolyData* mesh);
/// Weighted vertex normals, creases at `featureAngle` (no repair).
PolyPtr WithNormals(vtkPolyData* mesh, mesh::NormalWeighting weighting, double featureAngle);
/// The full preparation step (repair, subdivision with limit normals or
/// weighted normals); throws std::invalid_argument with one line.
PolyPtr Prepared(vtkPolyData* mesh, const mesh::PreparationOptions& options);
/// Rotated by `degrees` about the axis (0 x, 1 y, 2 z) through the origin.
PolyPtr Rotated(vtkPolyData* mesh, int axis, double degrees);
/// One square [-1, 1]^2 at z = 0 facing +z, as a single quad, rotated by
/// `degrees` in its plane, with point colours 0.9, 0.1, 0.9, 0.1 (opposite
/// corners equal): bilinear interpolation gives 0.5 at the centre, scan
/// conversion of the polygon a value that depends on the rotation.
PolyPtr OrientationQuad(double degrees);
/// z = 0.12 sin(2 pi x) on [-1, 1]^2, triangulated on a grid with uneven
/// column spacing and diagonals that alternate by a fixed pattern, so
/// vertices have different valences and triangle shapes: the weightings
/// disagree. Carries the exact normal ("ExactNormal").
PolyPtr CorrugatedSurface(int n);
/// The T-junction patch with each T vertex lifted onto the true surface
/// (as a displacement would): the geometry cracks open.
PolyPtr CrackedTJunctions(vtkPolyData* patch);

} // namespace shadinglab::gui
