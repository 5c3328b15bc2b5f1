// SPDX-License-Identifier: BSD-3-Clause
#include "CpuPanel.h"

#include "shadinglab/model/Spectrum.h"

#include "shadinglab/render/ColorMap.h"
#include "shadinglab/render/Display.h"

#include "ViewInteraction.h"

#include "PolyDataMesh.h"
#include "VtkCamera.h"
#include "shadinglab/cpu/SoftwareRenderer.h"

#include <vtkCamera.h>
#include <vtkPolyData.h>

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <chrono>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace shadinglab::widgets
{

/// Shows a QImage 1:1 and turns mouse drags into trackball camera moves.
class ImageView : public QWidget
{
public:
  explicit ImageView(QWidget* parent)
    : QWidget(parent)
  {
    this->setAttribute(Qt::WA_OpaquePaintEvent);
    this->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
  }
  QImage Picture;
  vtkCamera* Camera = nullptr;
  std::function<void()> CameraMoved;
  std::function<void()> Resized;

protected:
  void paintEvent(QPaintEvent*) override
  {
    QPainter painter(this);
    painter.fillRect(this->rect(), QColor(80, 80, 80));
    painter.drawImage(0, 0, this->Picture);
  }
  void resizeEvent(QResizeEvent*) override
  {
    if (this->Resized)
    {
      this->Resized();
    }
  }
  void mousePressEvent(QMouseEvent* event) override { this->LastPos = event->pos(); }
  void mouseMoveEvent(QMouseEvent* event) override
  {
    if (!this->Camera || event->buttons() == Qt::NoButton)
    {
      return;
    }
    const QPoint d = event->pos() - this->LastPos;
    this->LastPos = event->pos();
    if (event->buttons() & Qt::MiddleButton ||
      (event->buttons() & Qt::LeftButton && event->modifiers() & Qt::ShiftModifier))
    {
      PanCamera(this->Camera, d.x(), d.y(), this->height());
    }
    else if (event->buttons() & Qt::RightButton)
    {
      // vtkInteractorStyleTrackballCamera::Dolly: 1.1^(dy / 10 * MotionFactor / 2)
      DollyCamera(this->Camera, std::pow(1.1, -d.y() * 0.5));
    }
    else if (event->buttons() & Qt::LeftButton)
    {
      RotateCamera(this->Camera, d.x(), d.y(), this->width(), this->height());
    }
    this->Moved();
  }
  void wheelEvent(QWheelEvent* event) override
  {
    if (this->Camera)
    {
      DollyCamera(this->Camera, std::pow(1.1, event->angleDelta().y() > 0 ? 1.0 : -1.0));
      this->Moved();
    }
  }

private:
  void Moved()
  {
    if (this->CameraMoved)
    {
      this->CameraMoved();
    }
  }
  QPoint LastPos;
};

const render::Mesh& CpuMeshCache::Get(vtkPolyData* polydata, const std::string& colorBy)
{
  if (this->Source != polydata || this->Time != polydata->GetMTime() || this->ColorBy != colorBy)
  {
    render::ScalarField field;
    double range[2];
    bool colored = false;
    if (!colorBy.empty() && render::ParseScalarField(colorBy, field).empty())
    {
      try
      {
        this->Mesh = render::MeshFromPolyData(polydata, this->Frame, field, range);
        colored = true;
      }
      catch (const std::invalid_argument&)
      {
        // This panel's mesh lacks the array: drawn in its material's colour.
      }
    }
    if (!colored)
    {
      this->Mesh = render::MeshFromPolyData(polydata, this->Frame);
    }
    this->Source = polydata;
    this->Time = polydata->GetMTime();
    this->ColorBy = colorBy;
  }
  return this->Mesh;
}

render::Scene PanelScene(CpuMeshCache& cache, const PanelSpec& spec, const ViewState& view)
{
  render::Scene scene;
  scene.mesh = &cache.Get(spec.mesh, view.colorBy);
  const bool scalars = !scene.mesh->scalars.empty() || !scene.mesh->cellScalars.empty();
  scene.colorMap = scalars ? &view.colorMap : nullptr;
  // Colour by data drops the highlights, as on every front end.
  scene.material = render::MaterialForData(spec.material, view.highlights, scalars);
  scene.camera = render::CameraFromVtk(view.camera);
  scene.lighting = ViewLighting(view, scene.camera);
  render::ToLocal(cache.Frame, scene.camera);
  render::ToLocal(cache.Frame, scene.lighting);
  // The local mesh fits the unit sphere at the origin: clip around it as
  // vtkRenderer::ResetCameraClippingRange does (its 1e-3 near/far ratio).
  const double distance = Length(scene.camera.position);
  scene.camera.nearClip = std::max(distance - 1.01, 1e-3 * (distance + 1.01));
  scene.camera.farClip = distance + 1.01;
  return scene;
}

const render::Image& RenderOnCpu(cpu::SoftwareRenderer& renderer, CpuMeshCache& cache,
  const PanelSpec& spec, const ViewState& view, int width, int height, render::RenderStats* stats)
{
  return renderer.Render(
    PanelScene(cache, spec, view), PanelOptions(spec, view, width, height), stats);
}

CpuPanel::CpuPanel(const PanelSpec& spec, ViewState* view, QWidget* parent)
  : ShadingPanel(spec, view, parent)
  , Renderer(new cpu::SoftwareRenderer)
  , ViewWidget(new ImageView(this))
  , Overlay(nullptr)
{
  this->ViewWidget->Camera = view->camera;
  // The comparison re-renders every panel, this one included.
  this->ViewWidget->CameraMoved = [this]() { emit this->cameraMoved(this); };
  this->ViewWidget->Resized = [this]() { this->Render(); };
  this->Overlay = this->InstallOverlay(this->ViewWidget);
  this->SetViewWidget(this->ViewWidget);
}

CpuPanel::~CpuPanel() = default;

void CpuPanel::OnSpecChanged()
{
  this->Cache.Source = nullptr; // re-convert: the mesh may have been edited in place
  this->ReferenceCache.Source = nullptr;
}

void CpuPanel::OnProfileLineChanged()
{
  this->Overlay->SetLine(this->Line);
}

bool CpuPanel::RenderView()
{
  const int width = this->ViewWidget->width(), height = this->ViewWidget->height();
  if (width < 2 || height < 2 || !this->SpecValue.mesh)
  {
    return false;
  }
  const auto start = std::chrono::steady_clock::now();
  try
  {
    render::RenderStats stats;
    this->Last = RenderOnCpu(
      *this->Renderer, this->Cache, this->SpecValue, *this->View, width, height, &stats);
    this->NoteDrawnMode(stats.drawnMode, stats.autoChoice);
    if (this->SpecValue.dolpImage)
    {
      this->Stokes = render::MeasureStokes(*this->Renderer,
        PanelScene(this->Cache, this->SpecValue, *this->View),
        PanelOptions(this->SpecValue, *this->View, width, height));
    }
  }
  catch (const std::exception& e)
  {
    this->Error = e.what();
    this->ViewWidget->Picture = QImage();
    this->ViewWidget->update();
    return false;
  }
  if (this->SpecValue.errorReference >= 0 && this->Reference)
  {
    this->ViewWidget->Picture = this->HeatMap(this->ReferenceOnCpu(width, height));
  }
  else if (this->SpecValue.dolpImage)
  {
    this->ViewWidget->Picture = this->DolpMap();
  }
  else
  {
    const std::vector<uint8_t> rgb8 = this->Last.ToRGB8(this->View->display);
    this->ViewWidget->Picture =
      QImage(rgb8.data(), width, height, 3 * width, QImage::Format_RGB888).copy();
  }
  this->ViewWidget->update();
  this->CountRender(
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  return true;
}

namespace
{

/// A perceptually ordered dark-to-bright map (black, purple, orange, pale
/// yellow, after matplotlib's "inferno") that prints in grey as a ramp.
QColor Inferno(double t)
{
  static const double stops[5][3] = { { 0, 0, 4 }, { 87, 16, 110 }, { 188, 55, 84 },
    { 249, 142, 9 }, { 252, 255, 164 } };
  t = std::clamp(t, 0.0, 1.0) * 4.0;
  const int i = std::min(3, static_cast<int>(t));
  const double f = t - i;
  return QColor::fromRgbF((stops[i][0] + f * (stops[i + 1][0] - stops[i][0])) / 255.0,
    (stops[i][1] + f * (stops[i + 1][1] - stops[i][1])) / 255.0,
    (stops[i][2] + f * (stops[i + 1][2] - stops[i][2])) / 255.0);
}

/// A vertical colour bar at the image's top right: `colour(1)` at the top
/// (labelled `top`), `colour(0)` at the bottom (labelled "0"), `unit` below.
void DrawColourBar(QImage& image, const std::function<QColor(double)>& colour,
  const QString& top, const QString& unit)
{
  QPainter painter(&image);
  const int width = image.width(), height = image.height();
  const int barW = 10, barH = std::max(20, height / 3), x0 = width - barW - 34, y0 = 8;
  for (int i = 0; i < barH; ++i)
  {
    painter.setPen(colour(1.0 - static_cast<double>(i) / (barH - 1)));
    painter.drawLine(x0, y0 + i, x0 + barW, y0 + i);
  }
  painter.setPen(Qt::white);
  QFont font = painter.font();
  font.setPixelSize(10);
  painter.setFont(font);
  painter.drawText(x0 + barW + 3, y0 + 8, top);
  painter.drawText(x0 + barW + 3, y0 + barH, "0");
  painter.drawText(x0 - 4 * std::max(0, static_cast<int>(unit.size()) - 4), y0 + barH + 12, unit);
}

} // namespace

render::Image CpuPanel::ReferenceOnCpu(int width, int height)
{
  PanelSpec spec = this->Reference->Spec();
  spec.backend = render::Backend::CPU;
  spec.errorReference = -1;
  render::Image image = RenderOnCpu(*this->Renderer, this->ReferenceCache, spec, *this->View, width, height);
  return DisplayValues(std::move(image), this->View->display);
}

render::Image CpuPanel::Snapshot()
{
  return DisplayValues(this->Last, this->View->display);
}

render::Image DisplayValues(render::Image image, render::DisplayTransform display)
{
  const size_t n = image.rgb.size() / 3;
  for (size_t i = 0; i < n; ++i)
  {
    const Vec3<float> c = render::ApplyDisplay(display,
      Vec3<float>(image.rgb[3 * i], image.rgb[3 * i + 1], image.rgb[3 * i + 2]));
    image.rgb[3 * i] = c.x;
    image.rgb[3 * i + 1] = c.y;
    image.rgb[3 * i + 2] = c.z;
  }
  image.displayApplied = true;
  image.appliedDisplay = display;
  return image;
}

QImage CpuPanel::HeatMap(const render::Image& reference)
{
  // Both in display values: what the two panels show.
  const render::Image mine = this->Snapshot();
  const int width = mine.width, height = mine.height;
  QImage image(width, height, QImage::Format_RGB888);
  image.fill(QColor(60, 60, 60));
  // Panels of one comparison may differ by a pixel (the grid's rounding):
  // compare against the reference's nearest pixel.
  const bool comparable = reference.width > 0 && reference.height > 0;
  const double scale = this->SpecValue.errorScale;
  for (int y = 0; comparable && y < height; ++y)
  {
    const int ry = std::min(reference.height - 1, y * reference.height / height);
    for (int x = 0; x < width; ++x)
    {
      const int rx = std::min(reference.width - 1, x * reference.width / width);
      const size_t o = static_cast<size_t>(y) * width + x;
      const size_t r = static_cast<size_t>(ry) * reference.width + rx;
      if (!mine.covered[o] && !reference.covered[r])
      {
        continue;
      }
      const double error = this->SpecValue.colourDifference
        ? DeltaE2000(Vec3<double>(mine.rgb[3 * o], mine.rgb[3 * o + 1], mine.rgb[3 * o + 2]),
            Vec3<double>(reference.rgb[3 * r], reference.rgb[3 * r + 1], reference.rgb[3 * r + 2]))
        : std::abs(Luminance(&mine.rgb[3 * o]) - Luminance(&reference.rgb[3 * r]));
      image.setPixelColor(x, y, Inferno(error / scale));
    }
  }
  // The colour bar: 0 at the bottom, the full scale at the top.
  const bool dE = this->SpecValue.colourDifference;
  DrawColourBar(image, Inferno, QString("%1").arg(dE ? scale : scale * 255.0, 0, 'g', 3),
    dE ? "CIEDE2000" : "/255");
  if (!comparable)
  {
    QPainter painter(&image);
    painter.setPen(Qt::white);
    painter.drawText(8, 16, "reference not rendered yet");
  }
  return image;
}

QImage CpuPanel::DolpMap() const
{
  const render::StokesImage& stokes = this->Stokes;
  // The background as the other panels show it: the picture's own pixels.
  const std::vector<uint8_t> rgb8 = this->Last.ToRGB8(this->View->display);
  QImage image = QImage(rgb8.data(), stokes.width, stokes.height, 3 * stokes.width,
    QImage::Format_RGB888).copy();
  const render::ColorMap viridis = render::DolpColorMap();
  auto colour = [&viridis](double dolp) {
    const Vec3<float> c = viridis.Map(dolp);
    return QColor::fromRgbF(c.x, c.y, c.z);
  };
  const std::vector<float> rgb =
    render::FalseColour(stokes, render::StokesQuantity::Dolp, Vec3<float>(0, 0, 0));
  for (int y = 0; y < stokes.height; ++y)
  {
    for (int x = 0; x < stokes.width; ++x)
    {
      const size_t p = static_cast<size_t>(y) * stokes.width + x;
      if (stokes.covered[p]) // NaN, no light: the map's grey
      {
        image.setPixelColor(x, y, QColor::fromRgbF(rgb[3 * p], rgb[3 * p + 1], rgb[3 * p + 2]));
      }
    }
  }
  DrawColourBar(image, colour, "1", "DoLP");
  return image;
}

} // namespace shadinglab::widgets
