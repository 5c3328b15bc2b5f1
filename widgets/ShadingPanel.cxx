// SPDX-License-Identifier: BSD-3-Clause
#include "ShadingPanel.h"

#include <vtkPolyData.h>

#include "CpuPanel.h"
#include "GpuPanel.h"
#include "ViewInteraction.h"

#include "shadinglab/gl/GpuRenderer.h"

#include <QLabel>
#include <QVBoxLayout>

namespace shadinglab::widgets
{

namespace
{

/// Asked once per process: creating a GL window to ask is not free. Fills
/// the chooser's OpenGL facts (usable, why not, GL_RENDERER).
void GpuFacts(render::BackendFacts& facts)
{
  static std::string reason, renderer;
  static const bool available = gl::GpuAvailable(reason, &renderer);
  facts.glUsable = available;
  facts.glProblem = reason;
  facts.glRenderer = renderer;
}

} // namespace

Lighting<double> ViewLighting(const ViewState& view, const render::Camera& camera)
{
  Lighting<double> lighting;
  if (view.lightKit)
  {
    lighting = render::LightKit(camera, view.lightIntensity, view.lightAzimuth, view.lightElevation);
    for (int k = 0; k < lighting.lightCount; ++k)
    {
      lighting.lights[k].solidAngle = view.lightSolidAngle;
    }
    return lighting;
  }
  lighting.lightCount = 1;
  lighting.lights[0] =
    render::CameraLight(camera, view.lightAzimuth, view.lightElevation, view.lightIntensity);
  lighting.lights[0].solidAngle = view.lightSolidAngle;
  if (view.lightDistance > 0)
  {
    Light<double>& light = lighting.lights[0];
    light.type = LightType::Point;
    light.vector = camera.focalPoint + light.vector * view.lightDistance;
  }
  return lighting;
}

ShadingPanel* ShadingPanel::Create(const PanelSpec& spec, ViewState* view, QWidget* parent)
{
  // Who draws: render::ChooseBackend, as for every front end. An error
  // map and a DoLP image are computed from the CPU renderer's linear frames.
  render::BackendFacts facts;
  if (spec.errorReference >= 0)
  {
    facts.cpuOnly = "an error map is computed from the CPU renderer's linear frames";
  }
  else if (spec.dolpImage)
  {
    facts.cpuOnly = "a DoLP image is measured on the CPU renderer's linear frames";
  }
  facts.polygons = spec.mesh ? static_cast<long long>(spec.mesh->GetNumberOfPolys()) : 0;
  if (spec.backend != render::Backend::CPU && facts.cpuOnly.empty())
  {
    GpuFacts(facts);
  }
  const render::BackendChoice choice = render::ChooseBackend(spec.backend, facts);
  if (choice.backend == render::Backend::GPU)
  {
    return new GpuPanel(spec, view, parent);
  }
  auto* panel = new CpuPanel(spec, view, parent);
  if (spec.backend != render::Backend::CPU && facts.cpuOnly.empty())
  {
    panel->Note = facts.glUsable ? "CPU: auto" : "CPU: no OpenGL 3.2";
    panel->setToolTip(QString("%1 asked for, CPU drawn: %2")
                        .arg(render::BackendName(spec.backend))
                        .arg(QString::fromStdString(choice.why)));
    panel->UpdateTitle();
  }
  return panel;
}

ShadingPanel::ShadingPanel(const PanelSpec& spec, ViewState* view, QWidget* parent)
  : QWidget(parent)
  , SpecValue(spec)
  , View(view)
  , TitleLabel(new QLabel(this))
  , Drawn(spec.mode)
{
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->setSpacing(2);
  this->TitleLabel->setWordWrap(true);
  QFont font = this->TitleLabel->font();
  font.setPointSizeF(font.pointSizeF() * 0.9);
  this->TitleLabel->setFont(font);
  this->TitleLabel->setAlignment(Qt::AlignCenter);
  this->TitleLabel->setTextFormat(Qt::RichText);
  // Two lines for every title, so panels of one row have views of one size
  // (the shared camera then frames them alike).
  this->TitleLabel->setFixedHeight(2 * this->TitleLabel->fontMetrics().lineSpacing() + 4);
  layout->addWidget(this->TitleLabel);
  this->setMinimumSize(120, 120);
}

ProfileOverlay* ShadingPanel::InstallOverlay(QWidget* view)
{
  auto* overlay = new ProfileOverlay(view);
  overlay->DrawsLine = [this](Qt::KeyboardModifiers modifiers) {
    return this->View->profileTool || (modifiers & Qt::ControlModifier);
  };
  overlay->LineEdited = [this](const ProfileLine& line) {
    this->Line = line;
    emit this->profileLineEdited(line);
  };
  overlay->Pressed = [this]() { emit this->activated(this); };
  return overlay;
}

void ShadingPanel::SetViewWidget(QWidget* viewWidget)
{
  static_cast<QVBoxLayout*>(this->layout())->addWidget(viewWidget, 1);
  this->UpdateTitle();
}

QString ShadingPanel::Title() const
{
  QString backend = this->Note.isEmpty()
    ? QString(render::BackendName(this->Backend())).toUpper()
    : this->Note;
  QString title = QString::fromStdString(this->SpecValue.title) + " [" + backend + "]";
  if (!this->AutoNote.isEmpty())
  {
    title += " " + this->AutoNote;
  }
  if (!this->Error.isEmpty())
  {
    title += " - error: " + this->Error;
  }
  return title;
}

void ShadingPanel::SetCurveColor(const QColor& color)
{
  this->CurveColor = color;
  this->UpdateTitle();
}

void ShadingPanel::UpdateTitle()
{
  QString swatch;
  if (this->CurveColor.isValid())
  {
    swatch = QString("<span style='color:%1'>&#9632;</span> ").arg(this->CurveColor.name());
  }
  QString text = swatch + "<b>" + this->Title().toHtmlEscaped() + "</b>";
  this->TitleLabel->setText(text);
  this->TitleLabel->setStyleSheet(
    this->Selected ? "background:#ffe9a8; color:#000;" : "color:#000;");
}

void ShadingPanel::NoteDrawnMode(render::ShadingMode drawn, const std::string& why)
{
  this->Drawn = drawn;
  if (this->SpecValue.mode == render::ShadingMode::Auto)
  {
    this->AutoNote = QString("(auto: %1)").arg(render::ShadingModeName(drawn));
    this->TitleLabel->setToolTip(QString("Auto mode, max error %1/255: %2")
                                   .arg(this->SpecValue.maxError)
                                   .arg(QString::fromStdString(why)));
  }
  else if (!this->AutoNote.isEmpty())
  {
    this->AutoNote.clear();
    this->TitleLabel->setToolTip(QString());
  }
}

void ShadingPanel::SetSpec(const PanelSpec& spec)
{
  this->SpecValue = spec;
  this->OnSpecChanged();
  this->UpdateTitle();
  this->Render();
}

void ShadingPanel::Render()
{
  this->Error.clear();
  this->RenderView();
  this->UpdateTitle();
}

void ShadingPanel::CountRender(double milliseconds)
{
  ++this->Renders;
  this->LastMilliseconds = milliseconds;
}

void ShadingPanel::SetProfileLine(const ProfileLine& line)
{
  this->Line = line;
  this->OnProfileLineChanged();
}

void ShadingPanel::SetSelected(bool selected)
{
  this->Selected = selected;
  this->UpdateTitle();
}

render::RenderOptions PanelOptions(const PanelSpec& spec, const ViewState& view, int width,
  int height)
{
  render::RenderOptions options;
  options.mode = spec.mode;
  options.maxError = spec.maxError;
  options.interpolation = spec.interpolation;
  options.polygons = spec.polygons;
  options.scan = spec.scan;
  options.scanPrecision = spec.scanPrecision;
  options.polarizer = spec.polarizer;
  options.lightPolarizer = spec.lightPolarizer;
  options.width = width;
  options.height = height;
  options.background = view.background;
  options.display = view.display;
  // The explorer shows fast Phong as Bishop & Weimer drew it, whatever the
  // triangle size (its artifacts are what the panel is for).
  options.fastPhongFallback = false;
  return options;
}

} // namespace shadinglab::widgets
