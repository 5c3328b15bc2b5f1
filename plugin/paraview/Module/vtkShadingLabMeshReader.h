// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadingLabMeshReader
 * @brief   ParaView reader: PLY, STL, OFF and OBJ at memory speed (ShadingLab)
 *
 * Reads a mesh file through ShadingLab's ReadMesh: binary and ASCII PLY
 * and STL, OFF and OBJ by the fast readers (mesh/io/FastReaders.h: the same
 * points, cells and arrays as VTK's vtkPLYReader, vtkSTLReader and vtkOBJReader, read
 * in one walk over a memory map), any other file through the checked VTK
 * path. A file that cannot be read gives one error naming the problem
 * and an empty output. The whole mesh goes to piece 0 (as vtkSTLReader
 * does); other pieces are empty.
 */
#ifndef vtkShadingLabMeshReader_h
#define vtkShadingLabMeshReader_h

#include "shadinglabParaViewModule.h" // for export macro

#include <vtkPolyDataAlgorithm.h>

#include <string>

class SHADINGLABPARAVIEW_EXPORT vtkShadingLabMeshReader : public vtkPolyDataAlgorithm
{
public:
  static vtkShadingLabMeshReader* New();
  vtkTypeMacro(vtkShadingLabMeshReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to read.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /// Whether the extension is one this reader takes (.ply, .stl, .off, .obj).
  int CanReadFile(const char* name);

  /// The last read's error, one line ("" after a successful read).
  const char* GetLastError() const { return this->LastError.c_str(); }

protected:
  vtkShadingLabMeshReader();
  ~vtkShadingLabMeshReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkShadingLabMeshReader(const vtkShadingLabMeshReader&) = delete;
  void operator=(const vtkShadingLabMeshReader&) = delete;

  char* FileName = nullptr;
  std::string LastError;
};

#endif
