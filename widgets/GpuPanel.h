// SPDX-License-Identifier: BSD-3-Clause
// A panel drawn on the GPU: a QVTKOpenGLNativeWidget whose renderer draws
// the mesh with vtkShadingLabPolyDataMapper, set up by gl::ConfigureActor
// and gl::ApplyLighting as GpuRenderer is. Its interactor moves the shared
// camera (vtkInteractorStyleTrackballCamera).
#pragma once

#include "ShadingPanel.h"

#include <vtkNew.h>

class QVTKOpenGLNativeWidget;
class vtkActor;
class vtkGenericOpenGLRenderWindow;
class vtkObject;
class vtkRenderer;
class vtkShadingLabPolyDataMapper;

namespace shadinglab::widgets
{

class ProfileOverlay;

class GpuPanel final : public ShadingPanel
{
  Q_OBJECT
public:
  GpuPanel(const PanelSpec& spec, ViewState* view, QWidget* parent);
  ~GpuPanel() override;

  /// Reads the last frame back from VTK's framebuffer (no re-render).
  render::Image Snapshot() override;
  render::Backend Backend() const override { return render::Backend::GPU; }

protected:
  bool RenderView() override;
  void OnSpecChanged() override;
  void OnProfileLineChanged() override;

private:
  /// The view's colour by data on the mapper, when it changed.
  void ConfigureColors();
  void Configure();
  void OnInteraction(vtkObject*, unsigned long, void*);
  void OnRenderEnd(vtkObject*, unsigned long, void*);

  QVTKOpenGLNativeWidget* ViewWidget;
  ProfileOverlay* Overlay;
  vtkNew<vtkGenericOpenGLRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkShadingLabPolyDataMapper> Mapper;
  double StartTime = 0;
  /// The colouring the mapper was set up for (colour by, map, range).
  std::string Coloring;
};

} // namespace shadinglab::widgets
