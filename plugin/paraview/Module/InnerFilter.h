// SPDX-License-Identifier: BSD-3-Clause
// Runs one of ShadingLab's mesh filters (mesh/vtk, not wrapped for ParaView)
// inside a wrapped ParaView filter: on a shallow copy of the input (the
// input is never modified), with the inner filter's progress forwarded.
#pragma once

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

namespace shadinglab::paraview
{

/// Runs `inner` on `input` into `output`, reporting progress through `outer`.
/// Returns false (with the inner filter's errors already reported) when the
/// inner filter failed.
inline bool RunInnerFilter(vtkAlgorithm* outer, vtkAlgorithm* inner, vtkPolyData* input,
  vtkPolyData* output)
{
  vtkNew<vtkPolyData> copy;
  copy->ShallowCopy(input);
  inner->SetInputDataObject(0, copy);
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(outer);
  progress->SetCallback([](vtkObject* caller, unsigned long, void* clientData, void*) {
    static_cast<vtkAlgorithm*>(clientData)->UpdateProgress(
      static_cast<vtkAlgorithm*>(caller)->GetProgress());
  });
  const unsigned long tag = inner->AddObserver(vtkCommand::ProgressEvent, progress);
  inner->Update();
  inner->RemoveObserver(tag);
  if (inner->GetErrorCode() != 0)
  {
    return false;
  }
  output->ShallowCopy(inner->GetOutputDataObject(0));
  return true;
}

} // namespace shadinglab::paraview
