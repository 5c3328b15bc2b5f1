// SPDX-License-Identifier: BSD-3-Clause
// Built against the installed package: renders one triangle with the CPU
// renderer (prints its covered pixels and the centre's display value) and
// configures the GL mapper through its settings (no window needed).
#include "shadinglab/Version.h"
#include "shadinglab/cpu/SoftwareRenderer.h"
#include "shadinglab/render/Display.h"
#include "vtkShadingLabPolyDataMapper.h"

#include <iostream>

int main()
{
  namespace render = shadinglab::render;
  render::Mesh mesh;
  mesh.points = { -1, -1, 0, 1, -1, 0, 0, 1, 0 };
  mesh.offsets = { 0, 3 };
  mesh.connectivity = { 0, 1, 2 };
  render::Scene scene;
  scene.mesh = &mesh;
  scene.lighting.lightCount = 1;
  scene.lighting.lights[0] = render::KeyLight(scene.camera);
  render::RenderOptions options;
  options.width = 64;
  options.height = 48;
  shadinglab::cpu::SoftwareRenderer renderer;
  const render::Image& image = renderer.Render(scene, options);
  long covered = 0;
  for (auto c : image.covered)
  {
    covered += c;
  }
  const auto rgb8 = image.ToRGB8(options.display);
  const size_t centre = (24 * 64 + 32) * 3;
  vtkShadingLabPolyDataMapper* mapper = vtkShadingLabPolyDataMapper::New();
  const bool set = mapper->SetSetting("mode", "gouraud");
  mapper->Delete();
  std::cout << "shadinglab " << SHADINGLAB_VERSION << " covered " << covered << " centre "
            << int(rgb8[centre]) << " mapper " << (set ? "ok" : "refused") << "\n";
  return covered > 0 && set ? 0 : 1;
}
