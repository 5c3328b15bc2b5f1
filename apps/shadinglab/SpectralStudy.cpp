// SPDX-License-Identifier: BSD-3-Clause
// The accuracy study's spectral section: how far a three-sample RGB metal is
// from the metal's reflectance spectrum (docs/model.md section 7).
#include "AccuracyStudy.h"
#include "CliArgs.h"

#include "shadinglab/model/Fresnel.h"
#include "shadinglab/model/Spectrum.h"

#ifdef SHADINGLAB_HAVE_QT
#include "AccuracyPlot.h"
#endif

#include <cmath>
#include <fstream>
#include <sstream>

namespace shadinglab::cli
{

std::string WriteSpectralStudy(const std::filesystem::path& dir)
{
  const char* metals[] = { "gold", "copper", "silver", "aluminium" };
  struct Choice
  {
    const char* name;
    RgbChoice choice;
    bool spectral; ///< the 16-sample spectral evaluation itself
  };
  const Choice choices[] = { { "sampled 650/550/450 nm", RgbChoice::Sampled, false },
    { "band-averaged", RgbChoice::Band, false }, { "fitted", RgbChoice::Fitted, false },
    { "spectral, 16 samples", RgbChoice::Sampled, true } };
  constexpr int kMaxDegrees = 89;
  std::ofstream csv(dir / "spectral.csv");
  csv << "metal,choice,theta_deg,delta_e2000,eta_r,eta_g,eta_b,k_r,k_g,k_b\n";
  std::ofstream md(dir / "accuracy.md", std::ios::app);
  md << "\n## Spectral against three-sample RGB metals\n\n"
     << "CIEDE2000 between a metal's Fresnel colour with three RGB samples of n and k and its "
     << "reflectance spectrum under D65 through the CIE 1931 observer (81 rows of 5 nm, "
     << "docs/model.md eq. 7.1), at incidence 0 to " << kMaxDegrees
     << " degrees in steps of 1; 1 is a just-noticeable difference. RGB choices: n, k sampled "
     << "at 650/550/450 nm, averaged over the bands 590-780/490-590/380-490 nm, or fitted per "
     << "channel to the spectral colour over 0-85 degrees.\n\n"
     << "| metal | RGB choice | eta (R, G, B) | k (R, G, B) | dE2000 at 0 deg | mean | worst "
        "(at deg) |\n|---|---|---|---|---|---|---|\n";
  std::ostringstream summary;
  summary << "spectral against RGB metals, worst CIEDE2000 over 0-89 degrees:";
#ifdef SHADINGLAB_HAVE_QT
  std::vector<widgets::LogLogPanel> panels;
#endif
  for (const char* metal : metals)
  {
    const Dispersion& d = *PresetDispersion(metal);
#ifdef SHADINGLAB_HAVE_QT
    widgets::LogLogPanel panel;
    panel.title = metal;
    panel.xTitle = "incidence angle theta_i (degrees)";
    panel.yTitle = "CIEDE2000";
    panel.referenceY = 1.0;
    panel.referenceName = "1: just noticeable";
    panel.linear = true;
#endif
    std::string best;
    double bestWorst = 1e300;
    int color = 0;
    for (const Choice& c : choices)
    {
      Vec3<double> eta, k;
      RgbFromDispersion(d, c.choice, eta, k);
      Material<double> spectral;
      SetSpectral(spectral, d);
      double sum = 0, worst = 0, first = 0;
      int worstAt = 0;
#ifdef SHADINGLAB_HAVE_QT
      widgets::LogLogLine line{ c.name, {}, {}, color++, c.spectral };
#endif
      for (int deg = 0; deg <= kMaxDegrees; ++deg)
      {
        const double cosTheta = std::cos(deg * kPi<double> / 180.0);
        auto R = [&](double nm) {
          double n = 0, kv = 0;
          d.Evaluate(nm, n, kv);
          return F_Conductor(cosTheta, n, kv);
        };
        const Vec3<double> reference = SpectrumToLinearSRGB(R, kCieRows);
        const Vec3<double> rgb = c.spectral ? spectral.Fresnel(cosTheta) : F_RGB(cosTheta, eta, k);
        const double dE = DeltaE2000(reference, rgb);
        csv << metal << ',' << c.name << ',' << deg << ',' << dE << ',' << eta.x << ',' << eta.y
            << ',' << eta.z << ',' << k.x << ',' << k.y << ',' << k.z << '\n';
        sum += dE;
        first = deg == 0 ? dE : first;
        if (dE > worst)
        {
          worst = dE;
          worstAt = deg;
        }
#ifdef SHADINGLAB_HAVE_QT
        line.x.push_back(deg);
        line.y.push_back(dE);
#endif
      }
#ifdef SHADINGLAB_HAVE_QT
      panel.lines.push_back(line);
#endif
      std::ostringstream etaText, kText;
      etaText.precision(3);
      kText.precision(3);
      etaText << eta.x << ", " << eta.y << ", " << eta.z;
      kText << k.x << ", " << k.y << ", " << k.z;
      md << "| " << metal << " | " << c.name << " | " << (c.spectral ? "-" : etaText.str())
         << " | " << (c.spectral ? "-" : kText.str()) << " | " << Fmt(first) << " | "
         << Fmt(sum / (kMaxDegrees + 1)) << " | " << Fmt(worst) << " (" << worstAt << ") |\n";
      if (!c.spectral && worst < bestWorst)
      {
        bestWorst = worst;
        best = c.name;
      }
      if (!c.spectral)
      {
        summary << (c.choice == RgbChoice::Sampled ? std::string(" ") + metal + " " : ", ")
                << c.name << " " << Fmt(worst);
      }
      else
      {
        summary << ", 16 samples " << Fmt(worst) << ";";
      }
    }
    md << "| " << metal << " | closest RGB: **" << best << "** | | | | | " << Fmt(bestWorst)
       << " |\n";
#ifdef SHADINGLAB_HAVE_QT
    panels.push_back(panel);
#endif
  }
  if (!csv)
  {
    throw UsageError("cannot write " + (dir / "spectral.csv").string());
  }
#ifdef SHADINGLAB_HAVE_QT
  const std::string error = widgets::WriteLogLogPlot(panels,
    "RGB metals against their 5 nm spectra: CIEDE2000 over incidence angle",
    (dir / "spectral.png").string(), 2);
  if (!error.empty())
  {
    throw UsageError(error);
  }
#endif
  return summary.str();
}

} // namespace shadinglab::cli
