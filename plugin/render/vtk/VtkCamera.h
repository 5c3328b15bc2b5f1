// SPDX-License-Identifier: BSD-3-Clause
// render::Camera <-> vtkCamera: how a front end that keeps a vtkCamera (the
// explorer's shared camera, GpuRenderer's window) talks to both backends.
#pragma once

#include "shadinglab/render/Scene.h"

class vtkCamera;

namespace shadinglab::render
{

/// The vtkCamera's position, focal point, view up, view angle, projection,
/// parallel scale and clipping range.
Camera CameraFromVtk(vtkCamera* camera);

/// The inverse: sets all of the above on `camera`.
void ApplyToVtkCamera(const Camera& in, vtkCamera* camera);

} // namespace shadinglab::render
