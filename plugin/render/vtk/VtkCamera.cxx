// SPDX-License-Identifier: BSD-3-Clause
#include "VtkCamera.h"

#include <vtkCamera.h>

namespace shadinglab::render
{

Camera CameraFromVtk(vtkCamera* camera)
{
  Camera out;
  const double* p = camera->GetPosition();
  const double* f = camera->GetFocalPoint();
  const double* u = camera->GetViewUp();
  out.position = { p[0], p[1], p[2] };
  out.focalPoint = { f[0], f[1], f[2] };
  out.viewUp = { u[0], u[1], u[2] };
  out.viewAngle = camera->GetViewAngle();
  out.parallel = camera->GetParallelProjection() != 0;
  out.parallelScale = camera->GetParallelScale();
  const double* range = camera->GetClippingRange();
  out.nearClip = range[0];
  out.farClip = range[1];
  return out;
}

void ApplyToVtkCamera(const Camera& in, vtkCamera* camera)
{
  camera->SetPosition(in.position.x, in.position.y, in.position.z);
  camera->SetFocalPoint(in.focalPoint.x, in.focalPoint.y, in.focalPoint.z);
  camera->SetViewUp(in.viewUp.x, in.viewUp.y, in.viewUp.z);
  camera->SetViewAngle(in.viewAngle);
  camera->SetParallelProjection(in.parallel);
  camera->SetParallelScale(in.parallelScale);
  camera->SetClippingRange(in.nearClip, in.farClip);
}

} // namespace shadinglab::render
