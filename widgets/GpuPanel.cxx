// SPDX-License-Identifier: BSD-3-Clause
#include "GpuPanel.h"

#include "shadinglab/render/Display.h"
#include "PolyDataMesh.h"

#include "ViewInteraction.h"

#include "GpuScene.h"
#include "VtkCamera.h"
#include "vtkShadingLabPolyDataMapper.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkCellData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkPolyData.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include <chrono>

namespace shadinglab::widgets
{

namespace
{
double Now()
{
  return std::chrono::duration<double, std::milli>(
    std::chrono::steady_clock::now().time_since_epoch())
    .count();
}
} // namespace

GpuPanel::GpuPanel(const PanelSpec& spec, ViewState* view, QWidget* parent)
  : ShadingPanel(spec, view, parent)
  , ViewWidget(new QVTKOpenGLNativeWidget(this))
  , Overlay(nullptr)
{
  this->ViewWidget->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
  this->ViewWidget->setRenderWindow(this->Window);
  this->Window->SetMultiSamples(0);
  this->Window->AddRenderer(this->Renderer);
  this->Renderer->SetActiveCamera(view->camera);
  this->Actor->SetMapper(this->Mapper);
  this->Renderer->AddActor(this->Actor);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  this->Window->GetInteractor()->SetInteractorStyle(style);
  style->AddObserver(vtkCommand::InteractionEvent, this, &GpuPanel::OnInteraction);
  style->AddObserver(vtkCommand::EndInteractionEvent, this, &GpuPanel::OnInteraction);
  this->Renderer->AddObserver(vtkCommand::StartEvent, this, &GpuPanel::OnRenderEnd);
  this->Renderer->AddObserver(vtkCommand::EndEvent, this, &GpuPanel::OnRenderEnd);
  this->Overlay = this->InstallOverlay(this->ViewWidget);
  this->Configure();
  this->SetViewWidget(this->ViewWidget);
}

GpuPanel::~GpuPanel() = default;

void GpuPanel::Configure()
{
  this->Mapper->SetInputData(this->SpecValue.mesh);
  const render::RenderOptions options = PanelOptions(this->SpecValue, *this->View, 1, 1);
  gl::ConfigureActor(options, this->SpecValue.material, this->Mapper, this->Actor);
  // Colour by data drops the highlights (render::MaterialForData): the
  // mapper applies it, knowing whether VTK mapped colours this frame.
  render::Settings settings = this->Mapper->GetSettings();
  settings.highlights = this->View->highlights;
  this->Mapper->SetSettings(settings);
}

void GpuPanel::OnSpecChanged()
{
  this->Configure();
  this->Coloring.clear(); // Configure set direct colours again
  this->ConfigureColors();
}

void GpuPanel::ConfigureColors()
{
  const ViewState& view = *this->View;
  const std::string key = view.colorBy + "|" + view.colorMap.label + "|" +
    std::to_string(view.colorMap.rangeMin) + "|" + std::to_string(view.colorMap.rangeMax);
  if (key == this->Coloring)
  {
    return;
  }
  this->Coloring = key;
  render::ScalarField field;
  vtkPolyData* mesh = this->SpecValue.mesh;
  if (view.colorBy.empty() || !mesh || !render::ParseScalarField(view.colorBy, field).empty())
  {
    gl::ConfigureColoring(nullptr, {}, false, -1, this->Mapper);
    return;
  }
  // Point data first, as the CPU panels (and ParaView) look a name up.
  using A = render::ScalarField::Association;
  const bool points = field.association != A::Cells && mesh->GetPointData()->GetArray(field.name.c_str());
  const bool cells = !points && field.association != A::Points &&
    mesh->GetCellData()->GetArray(field.name.c_str());
  gl::ConfigureColoring(points || cells ? &view.colorMap : nullptr, field.name, cells,
    field.component, this->Mapper);
}

void GpuPanel::OnProfileLineChanged()
{
  this->Overlay->SetLine(this->Line);
}

void GpuPanel::OnInteraction(vtkObject*, unsigned long, void*)
{
  emit this->cameraMoved(this);
}

void GpuPanel::OnRenderEnd(vtkObject*, unsigned long event, void*)
{
  if (event == vtkCommand::StartEvent)
  {
    // The light follows the camera (which any panel may have moved) and
    // the clipping range fits this panel's mesh.
    const render::Camera camera = render::CameraFromVtk(this->View->camera);
    gl::ApplyLighting(ViewLighting(*this->View, camera), this->Renderer);
    // The view's display transform may have changed since Configure.
    if (this->Mapper->GetSettings().render.display != this->View->display ||
      this->Mapper->GetSettings().highlights != this->View->highlights)
    {
      render::Settings settings = this->Mapper->GetSettings();
      settings.render.display = this->View->display;
      settings.highlights = this->View->highlights;
      this->Mapper->SetSettings(settings);
    }
    this->ConfigureColors();
    // The shader writes display values: the background is given as one.
    const Vec3<float> background = render::ApplyDisplay(this->View->display, this->View->background);
    this->Renderer->SetBackground(background.x, background.y, background.z);
    this->Renderer->ResetCameraClippingRange();
    this->StartTime = Now();
    return;
  }
  this->CountRender(Now() - this->StartTime);
  this->NoteDrawnMode(static_cast<render::ShadingMode>(this->Mapper->GetDrawnMode()),
    this->Mapper->GetAutoChoice());
}

bool GpuPanel::RenderView()
{
  if (!this->SpecValue.mesh || this->Mapper->GetFailedSubstitutionCount() > 0)
  {
    if (this->Mapper->GetFailedSubstitutionCount() > 0)
    {
      this->Error = "GPU shader substitution failed";
    }
    return false;
  }
  const int before = this->RenderCount();
  this->Window->Render();
  return this->RenderCount() > before;
}

render::Image GpuPanel::Snapshot()
{
  render::Image image;
  const int* size = this->Window->GetSize();
  const int W = size[0], H = size[1];
  if (this->RenderCount() == 0 || W < 1 || H < 1)
  {
    return image;
  }
  this->Window->MakeCurrent();
  if (!gl::ReadFrame(this->Window, W, H, image.rgb, image.covered))
  {
    return render::Image();
  }
  image.width = W;
  image.height = H;
  image.displayApplied = true; // the shader applied the view's transform
  image.appliedDisplay = this->View->display;
  return image;
}

} // namespace shadinglab::widgets
