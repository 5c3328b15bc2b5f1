// SPDX-License-Identifier: BSD-3-Clause
#include "BrdfPlot.h"

#include "ChartStyle.h"

#include "shadinglab/render/Image.h"

#include <QtCharts/QCategoryAxis>
#include <QtCharts/QChartView>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QPolarChart>
#include <QtCharts/QValueAxis>

#include <QVBoxLayout>

#include <cmath>

using namespace QtCharts;

namespace shadinglab::widgets
{

double BrdfInPlane(const Material<double>& material, double thetaL, double thetaV)
{
  const double l = thetaL * kPi<double> / 180.0, v = thetaV * kPi<double> / 180.0;
  // Light on the -x side, viewer on the +x side for thetaV > 0.
  const Vec3<double> L(-std::sin(l), 0.0, std::cos(l));
  const Vec3<double> V(std::sin(v), 0.0, std::cos(v));
  const Vec3<double> N(0.0, 0.0, 1.0);
  return render::Luminance(EvaluateBrdf(material, material.diffuseColor, N, L, V));
}

std::vector<BrdfLobe> DefaultLobes(double shininess, double roughness)
{
  std::vector<BrdfLobe> lobes;
  Material<double> base;
  base.kd = 0.3;
  base.ks = 0.7;
  base.shininess = shininess;
  Material<double> phong = base;
  phong.model = ReflectanceModel::Phong;
  lobes.push_back({ "Phong (R.V)^n", phong, QColor(0, 114, 178) });
  Material<double> blinn = base;
  blinn.model = ReflectanceModel::BlinnPhong;
  lobes.push_back({ "Blinn-Phong (N.H)^n", blinn, QColor(213, 94, 0) });
  Material<double> ct = base;
  ct.model = ReflectanceModel::CookTorrance;
  ct.lobeCount = 1;
  ct.lobes[0] = { 1.0, roughness };
  lobes.push_back({ "Cook-Torrance 1982", ct, QColor(0, 158, 115) });
  Material<double> walter = ct;
  walter.variant = SpecularVariant::Walter2007;
  lobes.push_back({ "Cook-Torrance, Walter 2007", walter, QColor(204, 121, 167) });
  Material<double> mixture = ct;
  mixture.lobeCount = 2;
  mixture.lobes[0] = { 0.4, roughness };
  mixture.lobes[1] = { 0.6, std::min(1.0, 2.5 * roughness) };
  lobes.push_back({ "Beckmann mixture 0.4 m + 0.6 (2.5 m)", mixture, QColor(230, 159, 0) });
  return lobes;
}

BrdfPlot::BrdfPlot(QWidget* parent)
  : QWidget(parent)
  , View(new QChartView(this))
{
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  this->View->setRenderHint(QPainter::Antialiasing);
  this->View->setMinimumSize(300, 300);
  layout->addWidget(this->View);
  this->Redraw();
}

void BrdfPlot::SetLobes(const std::vector<BrdfLobe>& lobes, double thetaL)
{
  this->Lobes = lobes;
  this->ThetaL = thetaL;
  this->Redraw();
}

void BrdfPlot::SetSpecularOnly(bool on)
{
  this->SpecularOnly = on;
  this->Redraw();
}

namespace
{
/// The log scale's span: four decades below the largest peak, where the
/// broadest lobe's tails (and a Lambert term, 1/pi) already show.
constexpr double kLogDecades = 4.0;
} // namespace

void BrdfPlot::SetScale(BrdfScale scale)
{
  this->Scale = scale;
  this->Redraw();
}

void BrdfPlot::Redraw()
{
  auto* chart = new QPolarChart;
  const char* scaleNote = this->Scale == BrdfScale::PerLobe ? "each lobe to its peak"
    : this->Scale == BrdfScale::Log                         ? "log scale"
                                                            : "linear";
  StyleChart(chart,
    QString("BRDF lobes in the plane of incidence, light at %1 deg (%2%3)")
      .arg(this->ThetaL, 0, 'f', 0)
      .arg(this->SpecularOnly ? "ks f_s, " : "")
      .arg(scaleNote));
  // The angular axis runs clockwise from the top: the normal is up, angles
  // from the normal read -90 (left) .. 90 (right).
  auto* angular = new QCategoryAxis;
  angular->setRange(0, 360);
  angular->setLabelsPosition(QCategoryAxis::AxisLabelsPositionOnValue);
  for (int a = 0; a < 360; a += 30)
  {
    const int fromNormal = a <= 180 ? a : a - 360;
    angular->append(QString("%1%2").arg(fromNormal).arg(QChar(0x00B0)), a);
  }
  angular->setTitleText("viewing angle from the normal");
  auto* radial = MakeAxis(this->Scale == BrdfScale::PerLobe ? "f_r / its peak"
      : this->Scale == BrdfScale::Log                      ? "log10 f_r (1/sr)"
                                                           : "f_r (1/sr)");
  chart->addAxis(angular, QPolarChart::PolarOrientationAngular);
  chart->addAxis(radial, QPolarChart::PolarOrientationRadial);
  // Every lobe's values first: the scales need the peaks.
  std::vector<std::vector<double>> values;
  double maxValue = 1e-3;
  for (const BrdfLobe& lobe : this->Lobes)
  {
    Material<double> material = lobe.material;
    if (this->SpecularOnly)
    {
      material.kd = 0.0;
    }
    values.emplace_back();
    for (int i = 0; i <= 180; ++i)
    {
      values.back().push_back(BrdfInPlane(material, this->ThetaL, -90.0 + i));
      maxValue = std::max(maxValue, values.back().back());
    }
  }
  const double logFloor = std::log10(maxValue) - kLogDecades;
  this->Peaks.clear();
  double radialMax = 1e-3;
  for (size_t l = 0; l < this->Lobes.size(); ++l)
  {
    const BrdfLobe& lobe = this->Lobes[l];
    const double peak = *std::max_element(values[l].begin(), values[l].end());
    auto radius = [&](double f) {
      switch (this->Scale)
      {
        case BrdfScale::PerLobe:
          return peak > 0 ? f / peak : 0.0;
        case BrdfScale::Log:
          return f > 0 ? std::max(0.0, std::log10(f) - logFloor) : 0.0;
        case BrdfScale::Absolute:
          break;
      }
      return f;
    };
    // Two series per lobe, split at the normal (angle 0 = 360 on the axis).
    auto* right = new QLineSeries;
    auto* left = new QLineSeries;
    double drawnPeak = 0.0;
    for (int i = 0; i <= 180; ++i)
    {
      const double thetaV = -90.0 + i;
      const double r = radius(values[l][static_cast<size_t>(i)]);
      drawnPeak = std::max(drawnPeak, r);
      if (thetaV >= 0)
      {
        right->append(thetaV, r);
      }
      if (thetaV <= 0)
      {
        left->append(360.0 + thetaV, r);
      }
    }
    this->Peaks.push_back(drawnPeak);
    radialMax = std::max(radialMax, drawnPeak);
    QPen pen(lobe.color, 2);
    // The legend gives each lobe's peak: the per-lobe scale hides it.
    const QString name = QString("%1 (peak %2/sr)")
                           .arg(QString::fromStdString(lobe.name))
                           .arg(peak, 0, 'g', 2);
    for (QLineSeries* s : { left, right })
    {
      s->setPen(pen);
      s->setName(name);
      chart->addSeries(s);
      s->attachAxis(angular);
      s->attachAxis(radial);
    }
    chart->legend()->markers(left).front()->setVisible(false);
  }
  radial->setRange(0, radialMax * 1.05);
  radial->applyNiceNumbers(); // ticks at round values (0, 1, 2, ...) not 0.99
  if (this->Scale == BrdfScale::Log)
  {
    // Ticks in decades: the axis counts decades above the floor.
    radial->setLabelFormat(QString("%.0f"));
    radial->setTitleText(QString("decades above %1/sr").arg(std::pow(10.0, logFloor), 0, 'g', 1));
  }
  this->RadialEnd = radial->max();
  // The lobes' names are long ("Cook-Torrance 1982, m = 0.3"): beside the
  // polar plot, which is square, they fit whole; below it they were cut.
  chart->legend()->setAlignment(Qt::AlignRight);
  // The incident direction and its mirror direction.
  auto* incident = new QLineSeries;
  incident->setName(QString("light (%1 deg)").arg(this->ThetaL, 0, 'f', 0));
  incident->setPen(QPen(Qt::black, 2, Qt::DashLine));
  incident->append(360.0 - this->ThetaL, 0.0);
  incident->append(360.0 - this->ThetaL, radial->max());
  chart->addSeries(incident);
  incident->attachAxis(angular);
  incident->attachAxis(radial);
  auto* mirror = new QLineSeries;
  mirror->setName("mirror direction");
  mirror->setPen(QPen(Qt::gray, 1, Qt::DotLine));
  mirror->append(this->ThetaL, 0.0);
  mirror->append(this->ThetaL, radial->max());
  chart->addSeries(mirror);
  mirror->attachAxis(angular);
  mirror->attachAxis(radial);
  QChart* old = this->View->chart();
  this->View->setChart(chart);
  delete old;
}

} // namespace shadinglab::widgets
