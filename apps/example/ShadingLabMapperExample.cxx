// SPDX-License-Identifier: BSD-3-Clause
// Using the ShadingLab GPU mapper from a plain VTK program: a sphere shaded
// Gouraud-style by the lecture's model (per-vertex lighting, interpolated
// colours), written to a PNG.
//
//   shadinglab_mapper_example [OUT.png | --version]
#include "vtkShadingLabPolyDataMapper.h"
#include "shadinglab/Version.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkWindowToImageFilter.h>

#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  if (argc > 1 && std::string(argv[1]) == "--version")
  {
    std::cout << "shadinglab_mapper_example " << SHADINGLAB_VERSION << "\n";
    return 0;
  }
  // This VTK needs an X server for any OpenGL window: check before creating one.
  if (!std::getenv("DISPLAY"))
  {
    std::cerr << "shadinglab_mapper_example: error: no DISPLAY (run under an X server or Xvfb)\n";
    return 2;
  }
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(10);

  vtkNew<vtkShadingLabPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  mapper->SetSetting("mode", "gouraud"); // any key of shadinglab/render/Settings.h
  shadinglab::Material<double> material; // Blinn-Phong, kd 0.7, ks 0.3, n 32
  material.shininess = 40;
  mapper->SetMaterial(material);

  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetDiffuseColor(0.9, 0.6, 0.3); // the albedo rho

  vtkNew<vtkRenderer> renderer; // default headlight
  renderer->AddActor(actor);
  renderer->SetBackground(0.32, 0.34, 0.43);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(400, 400);
  window->AddRenderer(renderer);
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(argc > 1 ? argv[1] : "shadinglab_example.png");
  writer->Write();
  return writer->GetErrorCode() == 0 ? 0 : 1;
}
