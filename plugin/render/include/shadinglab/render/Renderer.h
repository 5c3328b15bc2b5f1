// SPDX-License-Identifier: BSD-3-Clause
// The one renderer interface. The CPU software renderer (plugin/cpu) and the
// GL renderer (plugin/gl) are siblings that implement it, as OpenSubdiv's CPU
// and GPU evaluators share one signature: a front end (CLI, explorer,
// ParaView) picks one and never sees the difference.
#pragma once

#include "shadinglab/render/Backend.h"
#include "shadinglab/render/Image.h"
#include "shadinglab/render/Options.h"
#include "shadinglab/render/Scene.h"

#include <string>

namespace shadinglab::render
{

class Renderer
{
public:
  virtual ~Renderer() = default;

  virtual Backend GetBackend() const = 0;

  /**
   * Renders `scene` with `options`. The returned image stays valid until the
   * next call. Throws std::invalid_argument with a one-line message for an
   * unusable request (options, camera, material, mode/model combination)
   * and std::runtime_error when the backend itself fails.
   */
  virtual const Image& Render(
    const Scene& scene, const RenderOptions& options, RenderStats* stats = nullptr) = 0;
};

/**
 * The checks every backend makes before drawing: a mesh is given, the
 * options are valid (ValidateOptions), the material is valid
 * (ValidateMaterial), at most kMaxLights lights, a finite camera, and the
 * shading mode can evaluate the material's model (fast Phong has no
 * Cook-Torrance form). Returns "" or a one-line error.
 */
std::string ValidateRequest(const Scene& scene, const RenderOptions& options);

/// True when `mode` can evaluate `model` (all but fast Phong + Cook-Torrance).
bool SupportsModel(ShadingMode mode, ReflectanceModel model);

} // namespace shadinglab::render
