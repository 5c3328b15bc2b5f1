// SPDX-License-Identifier: BSD-3-Clause
#include "ScanlineInspector.h"

#include "shadinglab/cpu/SoftwareRenderer.h"
#include "shadinglab/render/Renderer.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QVBoxLayout>

#include <cmath>
#include <limits>
#include <sstream>

namespace shadinglab::widgets
{

namespace
{

/// The triangle in pixel coordinates (x right, y down) and its vertex
/// normals: a highlight inside, a darker corner, so every pixel differs.
constexpr double kVertex[3][2] = { { 1.3, 0.8 }, { 13.2, 3.6 }, { 4.6, 8.6 } };
constexpr double kNormal[3][3] = { { -0.55, 0.45, 0.70 }, { 0.65, 0.15, 0.74 },
  { -0.15, -0.65, 0.74 } };
/// Cells smaller than this (screen pixels) get no numbers written in.
constexpr int kMinLabelledCell = 34;

QString Num(double v, int digits = 4)
{
  return QString::number(v, 'f', digits);
}

QString Vec(const std::vector<float>& a, int slot)
{
  return QString("(%1, %2, %3)").arg(Num(a[slot], 3)).arg(Num(a[slot + 1], 3)).arg(Num(a[slot + 2], 3));
}

} // namespace

struct ScanlineInspector::Result
{
  cpu::SoftwareRenderer renderer;
  render::Image image;
  render::RenderStats stats;
};

/// The magnified grid: paints the incremental image's pixels as squares,
/// the triangle, the scan line, its crossings and the row's values.
class ScanlineInspector::Canvas : public QWidget
{
public:
  explicit Canvas(ScanlineInspector* owner)
    : Owner(owner)
  {
    this->setMinimumSize(kColumns * 8, kRows * 8);
    this->setCursor(Qt::CrossCursor);
  }

protected:
  double Cell() const
  {
    return std::min(this->width() / double(kColumns), this->height() / double(kRows));
  }
  void paintEvent(QPaintEvent*) override
  {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const double s = this->Cell();
    const render::Image& image = this->Owner->Rendered(true);
    for (int j = 0; j < kRows; ++j)
    {
      for (int i = 0; i < kColumns; ++i)
      {
        const float* c = &image.rgb[3 * (static_cast<size_t>(j) * kColumns + i)];
        auto byte = [](float v) { return static_cast<int>(std::lround(255 * std::clamp(v, 0.0f, 1.0f))); };
        p.fillRect(QRectF(i * s, j * s, s, s), QColor(byte(c[0]), byte(c[1]), byte(c[2])));
      }
    }
    p.setPen(QPen(QColor(255, 255, 255, 40), 1));
    for (int i = 0; i <= kColumns; ++i)
      p.drawLine(QPointF(i * s, 0), QPointF(i * s, kRows * s));
    for (int j = 0; j <= kRows; ++j)
      p.drawLine(QPointF(0, j * s), QPointF(kColumns * s, j * s));
    p.setPen(QPen(QColor(120, 200, 255), 2));
    for (int k = 0; k < 3; ++k)
    {
      const double* a = kVertex[k];
      const double* b = kVertex[(k + 1) % 3];
      p.drawLine(QPointF(a[0] * s, a[1] * s), QPointF(b[0] * s, b[1] * s));
    }
    const int row = this->Owner->Row();
    const double yc = (row + 0.5) * s;
    p.setPen(QPen(QColor(255, 220, 0), 2, Qt::DashLine));
    p.drawLine(QPointF(0, yc), QPointF(kColumns * s, yc));
    const render::ScanTrace& trace = this->Owner->Trace(true);
    const bool phong = this->Owner->Mode() == render::ShadingMode::Phong;
    // Arrows scaled to the row's longest screen part: directions and
    // relative sizes read at any tilt.
    double longest = 1e-6;
    for (const render::TracedPixel& px : trace.pixels)
    {
      if (phong && trace.normalSlot >= 0)
      {
        const float* n = &px.attributes[trace.normalSlot];
        longest = std::max(longest, std::hypot(double(n[0]), double(n[1])));
      }
    }
    QFont font = p.font();
    font.setPointSizeF(std::max(6.0, s / 5.0));
    p.setFont(font);
    for (const render::TracedPixel& px : trace.pixels)
    {
      const QRectF cell(px.i * s, row * s, s, s);
      if (phong && trace.normalSlot >= 0)
      {
        // The interpolated normal's screen part, as an arrow (y up in the world).
        // From the upper third of the cell, clear of the scan line.
        const float* n = &px.attributes[trace.normalSlot];
        const QPointF c(cell.center().x(), cell.top() + 0.3 * s);
        const QPointF tip = c + QPointF(n[0], -n[1]) * (0.4 * s / longest);
        p.setPen(QPen(QColor(0, 90, 220), 3));
        p.drawLine(c, tip);
        p.setBrush(QColor(0, 90, 220));
        p.drawEllipse(tip, 3, 3);
        p.setBrush(Qt::NoBrush);
      }
      if (s >= kMinLabelledCell)
      {
        p.setPen(Qt::black);
        p.drawText(cell.adjusted(1, 1, -1, -1), Qt::AlignBottom | Qt::AlignHCenter,
          Num(this->Owner->ValueOf(true, px), 2));
      }
    }
    p.setPen(QPen(Qt::white, 2));
    for (const render::TracedSpan& span : trace.spans)
    {
      p.setBrush(QColor(255, 80, 80));
      p.drawEllipse(QPointF(span.xLeft * s, yc), 5, 5);
      p.drawEllipse(QPointF(span.xRight * s, yc), 5, 5);
      p.setBrush(Qt::NoBrush);
      p.drawText(QPointF(span.xLeft * s - 2.2 * s, yc - 0.6 * s), "x4 = " + Num(span.xLeft, 2));
      p.drawText(QPointF(span.xRight * s + 6, yc - 0.6 * s), "x5 = " + Num(span.xRight, 2));
    }
    p.setPen(QPen(QColor(255, 40, 40), 3));
    p.drawRect(QRectF(this->Owner->Column() * s, row * s, s, s));
  }
  void mousePressEvent(QMouseEvent* e) override { this->Pick(e->pos()); }
  void mouseMoveEvent(QMouseEvent* e) override { this->Pick(e->pos()); }

private:
  void Pick(const QPoint& at)
  {
    const double s = this->Cell();
    this->Owner->Select(static_cast<int>(at.y() / s), static_cast<int>(at.x() / s));
  }
  ScanlineInspector* Owner;
};

ScanlineInspector::ScanlineInspector(QWidget* parent)
  : QWidget(parent)
  , Exact(new Result)
  , Incremental(new Result)
  , Grid(new Canvas(this))
  , Text(new QLabel)
  , ModeChoice(new QComboBox)
  , PrecisionChoice(new QComboBox)
{
  for (int k = 0; k < 3; ++k)
  {
    // World x = pixel x, world y = rows - pixel y (the view looks down -z).
    this->Triangle.points.insert(this->Triangle.points.end(),
      { static_cast<float>(kVertex[k][0]), static_cast<float>(kRows - kVertex[k][1]), 0.0f });
    const double* n = kNormal[k];
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    this->Triangle.normals.insert(this->Triangle.normals.end(),
      { static_cast<float>(n[0] / len), static_cast<float>(n[1] / len), static_cast<float>(n[2] / len) });
    this->Triangle.connectivity.push_back(k);
  }
  this->Triangle.offsets = { 0, 3 };
  this->ModeChoice->addItem("Gouraud: I stepped", static_cast<int>(render::ShadingMode::Gouraud));
  this->ModeChoice->addItem("Phong: N stepped", static_cast<int>(render::ShadingMode::Phong));
  this->PrecisionChoice->addItem("float", static_cast<int>(render::ScanPrecision::Float));
  this->PrecisionChoice->addItem("double", static_cast<int>(render::ScanPrecision::Double));
  this->ModeChoice->setCurrentIndex(this->ModeChoice->findData(static_cast<int>(this->ShadingMode)));
  this->Text->setWordWrap(true);
  this->Text->setTextFormat(Qt::RichText);
  this->Text->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  this->Text->setTextInteractionFlags(Qt::TextSelectableByMouse);
  // The grid on top (as wide as the window allows: the cells are square),
  // the choices and the equations under it.
  auto* choices = new QHBoxLayout;
  choices->addWidget(new QLabel("Mode"));
  choices->addWidget(this->ModeChoice);
  choices->addWidget(new QLabel("Incremental scan in"));
  choices->addWidget(this->PrecisionChoice);
  choices->addStretch(1);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(this->Grid, 3);
  layout->addLayout(choices);
  layout->addWidget(this->Text, 2);
  connect(this->ModeChoice, QOverload<int>::of(&QComboBox::activated), this, [this] {
    this->SetMode(static_cast<render::ShadingMode>(this->ModeChoice->currentData().toInt()));
  });
  connect(this->PrecisionChoice, QOverload<int>::of(&QComboBox::activated), this, [this] {
    this->SetPrecision(
      static_cast<render::ScanPrecision>(this->PrecisionChoice->currentData().toInt()));
  });
  // A page of the explorer's plot stack, whose minimum is its largest
  // page's: this one takes what it is given, and the other scenes keep
  // their layout.
  this->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Ignored);
  this->Rerender();
}

ScanlineInspector::~ScanlineInspector() = default;

void ScanlineInspector::SetMode(render::ShadingMode mode)
{
  this->ShadingMode = mode == render::ShadingMode::Phong ? mode : render::ShadingMode::Gouraud;
  this->ModeChoice->setCurrentIndex(this->ModeChoice->findData(static_cast<int>(this->ShadingMode)));
  this->Rerender();
}

void ScanlineInspector::SetPrecision(render::ScanPrecision precision)
{
  this->Precision = precision;
  this->PrecisionChoice->setCurrentIndex(this->PrecisionChoice->findData(static_cast<int>(precision)));
  this->Rerender();
}

void ScanlineInspector::Select(int row, int column)
{
  row = std::clamp(row, 0, kRows - 1);
  column = std::clamp(column, 0, kColumns - 1);
  if (row == this->SelectedRow && column == this->SelectedColumn)
  {
    return;
  }
  const bool newRow = row != this->SelectedRow;
  this->SelectedRow = row;
  this->SelectedColumn = column;
  if (newRow)
  {
    this->Rerender(); // the trace is of one row
    return;
  }
  this->UpdateText();
  this->Grid->update();
  emit this->selectionChanged();
}

void ScanlineInspector::Rerender()
{
  render::Camera camera;
  camera.parallel = true;
  camera.parallelScale = kRows / 2.0;
  camera.focalPoint = Vec3<double>(kColumns / 2.0, kRows / 2.0, 0);
  camera.position = Vec3<double>(kColumns / 2.0, kRows / 2.0, 10);
  Lighting<double> lighting;
  lighting.lightCount = 1;
  lighting.lights[0].vector = NormalizeOr(Vec3<double>(0.25, 0.2, 1.0), Vec3<double>(0, 0, 1));
  Material<double> material;
  material.model = ReflectanceModel::BlinnPhong;
  // Peaks just under 1: nothing clips under the Clamp display.
  material.kd = 0.45;
  material.ks = 0.2;
  material.shininess = 12;
  material.diffuseColor = { 1, 1, 1 };
  material.ambient = { 0.05, 0.05, 0.05 };
  const render::Scene scene{ &this->Triangle, camera, lighting, material };
  render::RenderOptions options;
  options.width = kColumns;
  options.height = kRows;
  options.threads = 1;
  options.mode = this->ShadingMode;
  options.display = render::DisplayTransform::Clamp;
  options.background = { 0.15f, 0.15f, 0.18f };
  options.traceRow = this->SelectedRow;
  options.interpolation = render::InterpolationSpace::Screen; // as the slides
  options.twoSidedLighting = false; // the normals as given, whichever way the triangle winds
  for (Result* r : { this->Exact.get(), this->Incremental.get() })
  {
    options.scan = r == this->Exact.get() ? render::ScanConversion::Plane
                                          : render::ScanConversion::Incremental;
    options.scanPrecision = this->Precision;
    r->image = r->renderer.Render(scene, options, &r->stats);
  }
  this->UpdateText();
  this->Grid->update();
  emit this->selectionChanged();
}

const render::ScanTrace& ScanlineInspector::Trace(bool incremental) const
{
  return (incremental ? this->Incremental : this->Exact)->stats.trace;
}

const render::Image& ScanlineInspector::Rendered(bool incremental) const
{
  return (incremental ? this->Incremental : this->Exact)->image;
}

const render::TracedPixel* ScanlineInspector::PixelAt(bool incremental, int i) const
{
  for (const render::TracedPixel& p : this->Trace(incremental).pixels)
  {
    if (p.i == i)
    {
      return &p;
    }
  }
  return nullptr;
}

double ScanlineInspector::ValueOf(bool incremental, const render::TracedPixel& p) const
{
  const render::ScanTrace& trace = this->Trace(incremental);
  if (trace.intensitySlot >= 0)
  {
    return p.attributes[trace.intensitySlot];
  }
  const render::Image& image = this->Rendered(incremental);
  return image.rgb[3 * (static_cast<size_t>(trace.row) * kColumns + p.i)];
}

double ScanlineInspector::SelectedValue(bool incremental) const
{
  const render::TracedPixel* p = this->PixelAt(incremental, this->SelectedColumn);
  return p ? this->ValueOf(incremental, *p) : std::numeric_limits<double>::quiet_NaN();
}

void ScanlineInspector::UpdateText()
{
  this->Text->setText(this->Equations());
}

QString ScanlineInspector::Equations() const
{
  const render::ScanTrace& exact = this->Trace(false);
  const render::ScanTrace& incremental = this->Trace(true);
  const int j = this->SelectedRow, i = this->SelectedColumn;
  QString html = QString("<b>Scan line</b> j = %1 (y<sub>s</sub> = %2), pixel p = %3 "
                         "(x<sub>p</sub> = %4)<br>")
                   .arg(j).arg(Num(j + 0.5, 1)).arg(i).arg(Num(i + 0.5, 1));
  if (exact.spans.empty() || incremental.spans.empty())
  {
    return html + "The scan line misses the triangle: drag it over.";
  }
  const render::TracedSpan& span = exact.spans.front();
  const render::TracedSpan& dda = incremental.spans.front();
  const bool phong = this->ShadingMode == render::ShadingMode::Phong;
  const int slot = phong ? exact.normalSlot : exact.intensitySlot;
  auto at = [&](const std::vector<float>& a) { return phong ? Vec(a, slot) : Num(a[slot]); };
  const QString q = phong ? "N" : "I";
  html += QString("Edge crossings (eq. 2.3): x<sub>4</sub> = %1, %2<sub>4</sub> = %3; "
                  "x<sub>5</sub> = %4, %2<sub>5</sub> = %5<br>")
            .arg(Num(span.xLeft)).arg(q).arg(at(span.left)).arg(Num(span.xRight)).arg(at(span.right));
  html += QString("Stepped down the edges (eq. 2.10, %1): x<sub>4</sub> = %2, "
                  "%3<sub>4</sub> = %4; x<sub>5</sub> = %5, %3<sub>5</sub> = %6<br><br>")
            .arg(this->Precision == render::ScanPrecision::Float ? "float" : "double")
            .arg(Num(dda.xLeft)).arg(q).arg(at(dda.left)).arg(Num(dda.xRight)).arg(at(dda.right));
  const render::TracedPixel* pe = this->PixelAt(false, i);
  const render::TracedPixel* pi = this->PixelAt(true, i);
  if (!pe || !pi)
  {
    return html + "Pixel p is outside the span [x<sub>4</sub>, x<sub>5</sub>): pick one inside.";
  }
  const double x4 = span.xLeft, x5 = span.xRight, xp = i + 0.5;
  html += QString("<b>Slide 5, eq. 2.4:</b> %1<sub>p</sub> = (x<sub>5</sub> - x<sub>p</sub>)/"
                  "(x<sub>5</sub> - x<sub>4</sub>) %1<sub>4</sub> + (x<sub>p</sub> - x<sub>4</sub>)/"
                  "(x<sub>5</sub> - x<sub>4</sub>) %1<sub>5</sub><br>"
                  "&nbsp;= %2 %1<sub>4</sub> + %3 %1<sub>5</sub> = <b>%4</b> (per-row scan)<br>")
            .arg(q).arg(Num((x5 - xp) / (x5 - x4))).arg(Num((xp - x4) / (x5 - x4)))
            .arg(at(pe->attributes));
  html += QString("<b>Incremental, eq. 2.11:</b> %1<sub>p+1</sub> = %1<sub>p</sub> + "
                  "(%1<sub>5</sub> - %1<sub>4</sub>)/(x<sub>5</sub> - x<sub>4</sub>)<br>"
                  "&nbsp;%1<sub>p</sub> = <b>%2</b> after %3 steps<br>")
            .arg(q).arg(at(pi->attributes)).arg(i - incremental.pixels.front().i);
  if (phong)
  {
    html += QString("<br>Phong renormalizes N<sub>p</sub> and lights it: I = <b>%1</b> "
                    "(incremental: %2)").arg(Num(this->SelectedValue(false))).arg(Num(this->SelectedValue(true)));
  }
  const double diff = this->SelectedValue(true) - this->SelectedValue(false);
  html += QString("<br>Incremental - per row: %1 (%2/255)")
            .arg(QString::number(diff, 'g', 3)).arg(QString::number(255 * diff, 'g', 3));
  return html;
}

std::string ScanlineInspector::ToCsv() const
{
  std::ostringstream csv;
  csv.precision(9);
  csv << "row,pixel,per_row,incremental\n";
  for (const render::TracedPixel& p : this->Trace(false).pixels)
  {
    const render::TracedPixel* q = this->PixelAt(true, p.i);
    csv << this->SelectedRow << ',' << p.i << ',' << this->ValueOf(false, p) << ','
        << (q ? this->ValueOf(true, *q) : std::numeric_limits<double>::quiet_NaN()) << '\n';
  }
  return csv.str();
}

} // namespace shadinglab::widgets
