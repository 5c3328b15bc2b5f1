// SPDX-License-Identifier: BSD-3-Clause
// A mesh point's pixel coordinates in a camera's view (y down), as the
// renderers place it: what the auto mode's predictors (AutoMode.cpp,
// ModeDifference.cpp) read of a view.
#pragma once

#include "shadinglab/render/Scene.h"

#include <cmath>

namespace shadinglab::render
{

class ScreenProjection
{
public:
  ScreenProjection(const Camera& camera, int width, int height)
    : Cam(camera)
    , Basis(BasisOf(camera))
    , Width(width)
    , Height(height)
    , Aspect(static_cast<double>(width) / height)
    , TanHalf(std::tan(0.5 * camera.viewAngle * kPi<double> / 180.0))
  {
  }

  /// Pixel coordinates (x, y) of world point p; false behind the camera.
  bool operator()(const Vec3<double>& p, double& x, double& y) const
  {
    const Vec3<double> d = p - this->Cam.position;
    const double z = Dot(d, this->Basis.forward);
    double sx = Dot(d, this->Basis.right), sy = Dot(d, this->Basis.up);
    if (this->Cam.parallel)
    {
      sx /= this->Cam.parallelScale * this->Aspect;
      sy /= this->Cam.parallelScale;
    }
    else
    {
      if (!(z > this->Cam.nearClip))
      {
        return false;
      }
      sx /= z * this->TanHalf * this->Aspect;
      sy /= z * this->TanHalf;
    }
    x = (sx + 1) * 0.5 * this->Width;
    y = (1 - sy) * 0.5 * this->Height;
    return true;
  }

  /// Unit direction from p to the viewer (the view direction V).
  Vec3<double> ToViewer(const Vec3<double>& p) const
  {
    if (this->Cam.parallel)
    {
      return -this->Basis.forward;
    }
    return NormalizeOr(this->Cam.position - p, -this->Basis.forward);
  }

  /// Whether (x, y) lies on the image.
  bool OnImage(double x, double y) const
  {
    return x >= 0 && y >= 0 && x <= this->Width && y <= this->Height;
  }

  const CameraBasis& Axes() const { return this->Basis; }

private:
  Camera Cam;
  CameraBasis Basis;
  int Width, Height;
  double Aspect, TanHalf;
};

} // namespace shadinglab::render
