// SPDX-License-Identifier: BSD-3-Clause
// Built against the installed package's CPU component: renders one triangle
// with the CPU renderer and prints its covered pixels and the centre's
// display value; with the VTK component, also the GL mapper (consumer.cxx).
#include "shadinglab/Version.h"
#include "shadinglab/cpu/SoftwareRenderer.h"
#include "shadinglab/render/Display.h"

#include <iostream>

#ifdef SHADINGLAB_CONSUMER_VTK
bool MapperTakesASetting(); // consumer.cxx
#endif

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
  std::cout << "shadinglab " << SHADINGLAB_VERSION << " covered " << covered << " centre "
            << int(rgb8[centre]);
  bool ok = covered > 0;
#ifdef SHADINGLAB_CONSUMER_VTK
  const bool set = MapperTakesASetting();
  std::cout << " mapper " << (set ? "ok" : "refused");
  ok = ok && set;
#endif
  std::cout << "\n";
  return ok ? 0 : 1;
}
