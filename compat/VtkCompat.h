// SPDX-License-Identifier: BSD-3-Clause
// The VTK API differences between the releases ShadingLab builds against
// (VTK 9.2 in ParaView 5.11, 9.3 in Debian 13, 9.6 in Debian unstable),
// absorbed here so no other file tests VTK's version.
#ifndef shadinglab_VtkCompat_h
#define shadinglab_VtkCompat_h

#include <vtkVersionMacros.h>

#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 6, 0)
#include <vtkCellTypeUtilities.h>
#else
#include <vtkCellTypes.h>
#endif

namespace shadinglab::vtkcompat
{

/// The topological dimension (0-3) of a VTK cell type. VTK 9.6 moved it from
/// vtkCellTypes (deprecated there) to vtkCellTypeUtilities.
inline int CellDimension(unsigned char type)
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 6, 0)
  return vtkCellTypeUtilities::GetDimension(type);
#else
  return vtkCellTypes::GetDimension(type);
#endif
}

/// Whether a VTK cell type is linear (moved as CellDimension).
inline bool CellIsLinear(unsigned char type)
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 6, 0)
  return vtkCellTypeUtilities::IsLinear(type) != 0;
#else
  return vtkCellTypes::IsLinear(type) != 0;
#endif
}

} // namespace shadinglab::vtkcompat

#endif
