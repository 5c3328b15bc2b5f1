// SPDX-License-Identifier: BSD-3-Clause
#include "ProfilePlot.h"

#include "ChartStyle.h"

#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>

#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <sstream>

using namespace QtCharts;

namespace shadinglab::widgets
{

ProfilePlot::ProfilePlot(QWidget* parent)
  : QWidget(parent)
  , IntensityView(new QChartView(this))
  , DerivativeView(new QChartView(this))
  , Legend(new QLabel(this))
{
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  auto* charts = new QHBoxLayout;
  charts->setSpacing(0);
  for (QChartView* view : { this->IntensityView, this->DerivativeView })
  {
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumSize(260, 180);
    charts->addWidget(view);
  }
  layout->addLayout(charts, 1);
  // One legend under both charts, wrapped: a chart's own legend is a single
  // row that cut five panels' names to "Cub..." (the creases scene).
  this->Legend->setObjectName("profileLegend");
  this->Legend->setWordWrap(true);
  this->Legend->setAlignment(Qt::AlignCenter);
  this->Legend->setTextFormat(Qt::RichText);
  layout->addWidget(this->Legend);
  this->Redraw();
}

void ProfilePlot::SetCurves(const std::vector<ProfileCurve>& curves)
{
  this->Curves = curves;
  this->Redraw();
}

void ProfilePlot::SetShowPerceived(bool show)
{
  this->ShowPerceived = show;
  this->Redraw();
}

namespace
{

/// A line series of the covered samples; gaps (background) break the line
/// into separate series so no segment is drawn across them.
std::vector<QLineSeries*> Segments(
  const Profile& profile, const std::vector<double>& values, const QPen& pen)
{
  std::vector<QLineSeries*> out;
  QLineSeries* current = nullptr;
  for (size_t i = 0; i < values.size(); ++i)
  {
    if (!profile.covered[i])
    {
      current = nullptr;
      continue;
    }
    if (!current)
    {
      current = new QLineSeries;
      current->setPen(pen);
      out.push_back(current);
    }
    current->append(profile.distance[i], values[i]);
  }
  return out;
}

void AddCurve(QChart* chart, QAbstractAxis* x, QAbstractAxis* y, const QString& name,
  const Profile& profile, const std::vector<double>& values, const QPen& pen, double& lo,
  double& hi)
{
  for (QLineSeries* series : Segments(profile, values, pen))
  {
    series->setName(name);
    chart->addSeries(series);
    series->attachAxis(x);
    series->attachAxis(y);
    for (const QPointF& p : series->points())
    {
      lo = std::min(lo, p.y());
      hi = std::max(hi, p.y());
    }
  }
}

} // namespace

namespace
{
/// The bands' axis is sized for the second-largest curve when the largest
/// exceeds it this many times: a flat step's bands (~0.4) would otherwise
/// flatten Gouraud's (~0.03) to a line, the scene's very point.
constexpr double kBandClipRatio = 3.0;
} // namespace

void ProfilePlot::Redraw()
{
  auto* intensity = new QChart;
  StyleChart(intensity, this->ShowPerceived ? "Intensity (dashed: perceived)"
                                            : "Intensity along the line");
  auto* derivative = new QChart;
  const bool bands = this->ShowPerceived;
  StyleChart(derivative, bands ? "Mach bands: perceived - actual" : "Its derivative");
  double maxDistance = 1.0;
  for (const ProfileCurve& curve : this->Curves)
  {
    if (!curve.profile.distance.empty())
    {
      maxDistance = std::max(maxDistance, curve.profile.distance.back());
    }
  }
  QValueAxis* x1 = MakeAxis("distance along the line (px)", "%.0f");
  QValueAxis* y1 = MakeAxis("luminance (linear)");
  QValueAxis* x2 = MakeAxis("distance along the line (px)", "%.0f");
  QValueAxis* y2 = MakeAxis(bands ? "perceived - I (linear)" : "dI/dx (1/px)", "%.3f");
  intensity->addAxis(x1, Qt::AlignBottom);
  intensity->addAxis(y1, Qt::AlignLeft);
  derivative->addAxis(x2, Qt::AlignBottom);
  derivative->addAxis(y2, Qt::AlignLeft);
  double lo1 = 0.0, hi1 = 0.05, lo2 = -0.001, hi2 = 0.001;
  std::vector<double> slopes;
  std::vector<std::pair<double, QString>> bandPeaks; // per curve, with the perceived profile
  for (const ProfileCurve& curve : this->Curves)
  {
    const QString name = QString::fromStdString(curve.name);
    QPen pen(curve.color, 2);
    AddCurve(intensity, x1, y1, name, curve.profile, curve.profile.intensity, pen, lo1, hi1);
    if (this->ShowPerceived)
    {
      QPen dashed(curve.color, 1.5, Qt::DashLine);
      AddCurve(intensity, x1, y1, name + " (perceived)", curve.profile,
        PerceivedProfile(curve.profile), dashed, lo1, hi1);
    }
    std::vector<double> d = Derivative(curve.profile);
    if (bands)
    {
      // What the eye adds (eq. 3.3): zero where the profile is straight,
      // a band either side of each slope change (Gouraud) or step (flat).
      d = PerceivedProfile(curve.profile);
      double peak = 0.0;
      for (size_t i = 0; i < d.size(); ++i)
      {
        d[i] -= curve.profile.intensity[i];
        peak = curve.profile.covered[i] ? std::max(peak, std::abs(d[i])) : peak;
      }
      bandPeaks.push_back({ peak, name });
    }
    AddCurve(derivative, x2, y2, name, curve.profile, d, pen, lo2, hi2);
    for (size_t i = 0; i < d.size(); ++i)
    {
      if (curve.profile.covered[i])
      {
        slopes.push_back(std::abs(d[i]));
      }
    }
  }
  // The derivative axis spans 3x the 95th percentile of |dI/dx|: the slope
  // changes of smooth curves stay readable, a flat step's spike is clipped
  // (and the title says so).
  bool clipped = false;
  if (slopes.size() > 20 && !bands)
  {
    std::nth_element(slopes.begin(), slopes.begin() + slopes.size() * 95 / 100, slopes.end());
    const double limit = 3.0 * slopes[slopes.size() * 95 / 100];
    if (limit > 0 && limit < std::max(std::abs(lo2), std::abs(hi2)))
    {
      lo2 = std::max(lo2, -limit);
      hi2 = std::min(hi2, limit);
      clipped = true;
    }
  }
  if (clipped)
  {
    // The title says so: spikes beyond 3x the 95th percentile are cut.
    derivative->setTitle("Its derivative (spikes clipped)");
  }
  x1->setRange(0, maxDistance);
  x2->setRange(0, maxDistance);
  y1->setRange(std::min(0.0, lo1), hi1 * 1.05);
  double span = std::max(std::abs(lo2), std::abs(hi2)) * 1.1;
  std::sort(bandPeaks.rbegin(), bandPeaks.rend());
  if (bands && bandPeaks.size() > 1 && bandPeaks[1].first > 0 &&
    bandPeaks[0].first > kBandClipRatio * bandPeaks[1].first)
  {
    // A step's bands (flat) dwarf a slope change's (Gouraud): the axis is
    // sized for the second, the first clipped, and the title says so.
    span = 1.3 * bandPeaks[1].first;
    derivative->setTitle(QString("Mach bands (%1 clipped at \u00b1%2)")
                           .arg(bandPeaks[0].second)
                           .arg(bandPeaks[0].first, 0, 'f', 2));
  }
  y2->setRange(-span, span);
  this->SecondSpan = span;
  for (QValueAxis* axis : { x1, x2, y1, y2 })
  {
    axis->applyNiceNumbers(); // ticks at round values
  }
  intensity->legend()->hide();
  derivative->legend()->hide();
  QStringList entries;
  for (const ProfileCurve& curve : this->Curves)
  {
    entries << QString("<span style=\"color:%1\">&#9632;</span>&nbsp;%2")
                 .arg(curve.color.name(), QString::fromStdString(curve.name)
                                           .toHtmlEscaped()
                                           .replace(" ", "&nbsp;")); // wrap between entries
  }
  this->Legend->setText(entries.join(" &nbsp;&nbsp; "));
  this->Legend->setVisible(!entries.isEmpty());
  QChart* oldIntensity = this->IntensityView->chart();
  QChart* oldDerivative = this->DerivativeView->chart();
  this->IntensityView->setChart(intensity);
  this->DerivativeView->setChart(derivative);
  delete oldIntensity;
  delete oldDerivative;
}

std::string ProfilePlot::ToCsv() const
{
  std::ostringstream csv;
  csv << "distance_px";
  size_t rows = 0;
  std::vector<std::vector<double>> derivative, perceived;
  for (const ProfileCurve& curve : this->Curves)
  {
    std::string name = curve.name;
    std::replace(name.begin(), name.end(), ',', ';');
    csv << ",\"" << name << " intensity\",\"" << name << " dI/dx\",\"" << name
        << " perceived\",\"" << name << " covered\"";
    rows = std::max(rows, curve.profile.distance.size());
    derivative.push_back(Derivative(curve.profile));
    perceived.push_back(PerceivedProfile(curve.profile));
  }
  csv << "\n";
  csv.precision(8);
  for (size_t r = 0; r < rows; ++r)
  {
    bool wroteDistance = false;
    for (const ProfileCurve& curve : this->Curves)
    {
      if (r < curve.profile.distance.size())
      {
        csv << curve.profile.distance[r];
        wroteDistance = true;
        break;
      }
    }
    if (!wroteDistance)
    {
      csv << "";
    }
    for (size_t c = 0; c < this->Curves.size(); ++c)
    {
      const Profile& p = this->Curves[c].profile;
      if (r < p.distance.size())
      {
        csv << "," << p.intensity[r] << "," << derivative[c][r] << "," << perceived[c][r] << ","
            << int(p.covered[r]);
      }
      else
      {
        csv << ",,,,";
      }
    }
    csv << "\n";
  }
  return csv.str();
}

QString ProfilePlot::SecondTitle() const
{
  QChart* chart = this->DerivativeView->chart();
  return chart ? chart->title() : QString();
}

} // namespace shadinglab::widgets
