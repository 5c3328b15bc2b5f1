// SPDX-License-Identifier: BSD-3-Clause
#include "ComparisonWidget.h"

#include "ShadingPanel.h"

#include "PolyDataMesh.h"
#include "VtkCamera.h"

#include <vtkCamera.h>
#include <vtkPolyData.h>

#include <QGridLayout>
#include <QTimer>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace shadinglab::widgets
{

QColor PanelColor(int index)
{
  static const QColor colors[ComparisonWidget::kMaxPanels] = { QColor(0, 114, 178),
    QColor(213, 94, 0), QColor(0, 158, 115), QColor(204, 121, 167), QColor(230, 159, 0),
    QColor(86, 180, 233) };
  return colors[index % ComparisonWidget::kMaxPanels];
}

ComparisonWidget::ComparisonWidget(QWidget* parent)
  : QWidget(parent)
  , Grid(new QGridLayout(this))
{
  this->State.camera = vtkSmartPointer<vtkCamera>::New();
  this->Grid->setContentsMargins(0, 0, 0, 0);
  this->Grid->setSpacing(4);
}

ComparisonWidget::~ComparisonWidget() = default;

void ComparisonWidget::SetPanels(const std::vector<PanelSpec>& specs)
{
  if (specs.size() > static_cast<size_t>(kMaxPanels))
  {
    throw std::invalid_argument("a comparison has at most 6 panels");
  }
  for (ShadingPanel* panel : this->Panels)
  {
    delete panel;
  }
  this->Panels.clear();
  // One row up to 4 panels, else rows of 3.
  const int columns = specs.size() <= 4 ? std::max<int>(1, specs.size()) : 3;
  for (size_t i = 0; i < specs.size(); ++i)
  {
    ShadingPanel* panel = ShadingPanel::Create(specs[i], &this->State, this);
    panel->SetCurveColor(PanelColor(static_cast<int>(i)));
    panel->SetProfileLine(this->Line);
    this->Grid->addWidget(panel, static_cast<int>(i) / columns, static_cast<int>(i) % columns);
    connect(panel, &ShadingPanel::cameraMoved, this, &ComparisonWidget::OnCameraMoved);
    connect(panel, &ShadingPanel::profileLineEdited, this,
      [this](const ProfileLine& line) { this->SetProfileLine(line); });
    connect(panel, &ShadingPanel::activated, this, [this](ShadingPanel* source) {
      for (size_t j = 0; j < this->Panels.size(); ++j)
      {
        if (this->Panels[j] == source)
        {
          this->SetCurrentPanel(static_cast<int>(j));
        }
      }
    });
    this->Panels.push_back(panel);
  }
  for (ShadingPanel* panel : this->Panels)
  {
    const int ref = panel->Spec().errorReference;
    panel->SetReference(ref >= 0 && ref < this->PanelCount() ? this->Panels[ref] : nullptr);
  }
  this->Current = 0;
  this->SetCurrentPanel(0);
}

void ComparisonWidget::SetCurrentPanel(int index)
{
  if (index < 0 || index >= this->PanelCount())
  {
    return;
  }
  this->Current = index;
  for (int i = 0; i < this->PanelCount(); ++i)
  {
    this->Panels[i]->SetSelected(i == index && this->PanelCount() > 1);
  }
  emit this->currentPanelChanged(index);
}

void ComparisonWidget::SetPanelSpec(int index, const PanelSpec& spec)
{
  ShadingPanel* panel = this->Panels.at(index);
  PanelSpec copy = spec;
  copy.errorReference = panel->Spec().errorReference;
  panel->SetSpec(copy); // renders this panel
  for (int i = 0; i < this->PanelCount(); ++i)
  {
    if (this->Panels[i]->GetReference() == panel)
    {
      this->Panels[i]->Render();
    }
  }
  emit this->rendered();
}

void ComparisonWidget::ResetCamera(double azimuth, double elevation, double zoom, bool parallel)
{
  this->Fit = { azimuth, elevation, zoom, parallel, true };
  this->FitRetries = 0;
  this->FitCamera();
}

void ComparisonWidget::SetCamera(const render::Camera& camera)
{
  this->Fit.pending = false;
  render::ApplyToVtkCamera(camera, this->State.camera);
}

bool ComparisonWidget::FitCamera()
{
  const double azimuth = this->Fit.azimuth, elevation = this->Fit.elevation;
  const double zoom = this->Fit.zoom;
  const bool parallel = this->Fit.parallel;
  // Empty bounds to start from (a start of [1, -1] would stretch the box of
  // a mesh far from the origin back to it, and the mesh would sit small in
  // a corner of the view).
  constexpr double kHuge = std::numeric_limits<double>::max();
  double bounds[6] = { kHuge, -kHuge, kHuge, -kHuge, kHuge, -kHuge };
  for (ShadingPanel* panel : this->Panels)
  {
    if (!panel->Spec().mesh)
    {
      continue;
    }
    const double* b = panel->Spec().mesh->GetBounds();
    for (int a = 0; a < 3; ++a)
    {
      bounds[2 * a] = std::min(bounds[2 * a], b[2 * a]);
      bounds[2 * a + 1] = std::max(bounds[2 * a + 1], b[2 * a + 1]);
    }
  }
  if (bounds[0] > bounds[1])
  {
    bounds[0] = bounds[2] = bounds[4] = -1;
    bounds[1] = bounds[3] = bounds[5] = 1;
  }
  // The panels' aspect, once they are laid out (a new panel is not yet).
  double aspect = 1.0;
  const bool laidOut = !this->Panels.empty() && this->Panels[0]->isVisible() &&
    this->Panels[0]->height() > 2 * this->Panels[0]->minimumHeight() / 3;
  if (laidOut)
  {
    aspect = static_cast<double>(this->Panels[0]->width()) / this->Panels[0]->height();
  }
  render::Camera camera = render::FitCamera(bounds, azimuth, elevation, zoom, aspect, parallel);
  if (parallel && aspect < 1.0)
  {
    // FitCamera fits the height; a tall panel must fit the width.
    camera.parallelScale /= aspect;
  }
  render::ApplyToVtkCamera(camera, this->State.camera);
  this->Fit.pending = !laidOut;
  return laidOut;
}

void ComparisonWidget::SetLight(double azimuth, double elevation)
{
  this->State.lightAzimuth = azimuth;
  this->State.lightElevation = elevation;
  this->RenderAll();
}

void ComparisonWidget::SetLightIntensity(double intensity)
{
  this->State.lightIntensity = intensity;
  this->RenderAll();
}

void ComparisonWidget::SetLightSolidAngle(double solidAngle)
{
  this->State.lightSolidAngle = solidAngle;
  this->RenderAll();
}

std::string ComparisonWidget::SetColorBy(const std::string& colorBy, const std::string& mapName)
{
  render::ColorMap map;
  if (!render::FindColorMap(mapName, map))
  {
    return "unknown colour map '" + mapName + "'";
  }
  if (!colorBy.empty())
  {
    render::ScalarField field;
    std::string error = render::ParseScalarField(colorBy, field);
    if (error.empty() && (this->Panels.empty() || !this->Panels[0]->Spec().mesh))
    {
      error = "no mesh to colour";
    }
    if (!error.empty())
    {
      return error;
    }
    double range[2];
    render::WorldFrame frame;
    try
    {
      render::MeshFromPolyData(this->Panels[0]->Spec().mesh, frame, field, range);
    }
    catch (const std::invalid_argument& e)
    {
      return e.what();
    }
    map.rangeMin = range[0];
    map.rangeMax = range[1];
  }
  this->State.colorBy = colorBy;
  this->State.colorMap = map;
  this->RenderAll();
  return {};
}

void ComparisonWidget::RenderAll()
{
  if (this->Fit.pending && !this->FitCamera() && this->FitRetries < kMaxFitRetries)
  {
    // New panels are shown by Qt's next event loop pass: draw again then.
    ++this->FitRetries;
    QTimer::singleShot(0, this, &ComparisonWidget::RenderAll);
  }
  this->RenderPanels(nullptr);
}

void ComparisonWidget::RenderPanels(const ShadingPanel* alreadyDrawn)
{
  // References first, then the heat maps that read them.
  for (ShadingPanel* panel : this->Panels)
  {
    if (panel != alreadyDrawn && !panel->GetReference())
    {
      panel->Render();
    }
  }
  for (ShadingPanel* panel : this->Panels)
  {
    if (panel->GetReference())
    {
      panel->Render();
    }
  }
  emit this->rendered();
}

void ComparisonWidget::OnCameraMoved(ShadingPanel* source)
{
  // A GPU source has drawn itself (its interactor renders as it moves).
  this->RenderPanels(source->Backend() == render::Backend::GPU ? source : nullptr);
}

void ComparisonWidget::SetProfileLine(const ProfileLine& line)
{
  this->Line = line;
  for (ShadingPanel* panel : this->Panels)
  {
    panel->SetProfileLine(line);
  }
  emit this->profileLineChanged();
}

std::vector<int> ComparisonWidget::ProfilePanels() const
{
  std::vector<int> indices;
  for (int i = 0; i < this->PanelCount(); ++i)
  {
    if (this->Panels[i]->Spec().errorReference < 0)
    {
      indices.push_back(i);
    }
  }
  return indices;
}

std::vector<Profile> ComparisonWidget::Profiles() const
{
  std::vector<Profile> profiles;
  for (int i : this->ProfilePanels())
  {
    profiles.push_back(SampleProfile(this->Panels[i]->Snapshot(), this->Line));
  }
  return profiles;
}

} // namespace shadinglab::widgets
