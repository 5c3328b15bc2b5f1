// SPDX-License-Identifier: BSD-3-Clause
// VTK's OpenGL function loader, for the GL enums and calls: GLEW
// (vtk_glew.h) up to VTK 9.3, glad (vtk_glad.h) from VTK 9.4 on. The GL
// side's part of VtkCompat.h, apart so the mesh code does not see GL.
#ifndef shadinglab_VtkOpenGL_h
#define shadinglab_VtkOpenGL_h

#include <vtkVersionMacros.h>

#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 4, 0)
#include <vtk_glad.h>
#else
#include <vtk_glew.h>
#endif

#endif
