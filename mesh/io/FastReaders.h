// SPDX-License-Identifier: BSD-3-Clause
// Readers at memory speed for the formats scans come in: binary and ASCII
// PLY, binary and ASCII STL, OFF, OBJ. Each parses its file in one walk over a
// memory map, checking as it goes what the precheck (MeshPrecheck.h) and
// ValidateMesh check: counts against the bytes present, indices within the
// points, finite coordinates. Their output is the one VTK's reader (ours
// for OFF) gives, point for point and cell for cell (tests/mesh/
// FastReadersTest.cxx compares them bit for bit).
//
// A fast reader takes only the files it reads exactly. For anything else
// (a property or keyword VTK's reader turns into an array the fast path
// does not make, and every malformed file) it returns null and the caller
// takes the checked VTK path, whose precheck names the problem in the same
// one line as before: a bad file costs a second walk, a good one none.
#pragma once

#include <string>

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace shadinglab
{

/// The fast reader for `ext` ("ply", "stl", "off", "obj"), or null when there is
/// none for it or it leaves this file to the checked path (see above).
/// Throws MeshError only when the file cannot be opened or mapped.
vtkSmartPointer<vtkPolyData> ReadFast(const std::string& path, const std::string& ext);

/// Whether ReadMesh may use the fast readers: on unless the environment
/// sets SHADINGLAB_VTK_READERS=1 (benchmarks and tests compare the two).
bool FastReadersEnabled();

} // namespace shadinglab
