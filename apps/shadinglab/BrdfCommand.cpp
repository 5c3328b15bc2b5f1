// SPDX-License-Identifier: BSD-3-Clause
// shadinglab brdf: tabulates a reflectance model or one of its terms.
#include "Commands.h"

#include "shadinglab/model/Brdf.h"
#include "shadinglab/model/Fresnel.h"
#include "shadinglab/model/Shading.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace shadinglab::cli
{

namespace
{

/// Rows are capped so a mistyped range (0:90:1e-9) fails fast instead of
/// printing gigabytes. 1e7 rows is ~0.5 GB of CSV, beyond any plot.
constexpr size_t kMaxRows = 10000000;

const char* kBrdfHelp =
  "usage: shadinglab brdf [--model cook-torrance|lambert|phong|blinn-phong] [material options]\n"
  "                       --theta-l ANGLES [--theta-v ANGLES] [--phi ANGLES]\n"
  "                       [--term brdf|F|D|G|Fs|Fp|dolp]\n"
  "\n"
  "Prints CSV 'theta_l,theta_v,phi,r,g,b', one row per angle combination.\n"
  "Angles in degrees: theta_l, theta_v from the normal (0..90), phi the azimuth of V\n"
  "relative to L's plane of incidence (180: V in L's plane on the mirror side).\n"
  "ANGLES is a value, a comma list, or START:STOP:STEP (inclusive).\n"
  "Defaults: --theta-v 30 --phi 180 --term brdf.\n"
  "  --term brdf   kd Rd + ks Rs per channel (1/sr)\n"
  "  --term F      Fresnel reflectance at cos(theta_i) = L.H (cook-torrance)\n"
  "  --term D      Beckmann D (mixture), without the 1/pi, at alpha = acos(N.H)\n"
  "  --term G      geometric attenuation min(1, Gs, Gm)\n"
  "  --term Fs     s-polarized reflectance Rs at cos(theta_i) = L.H (docs/model.md eq. 8.1)\n"
  "  --term Fp     p-polarized reflectance Rp there (0 at Brewster's angle of a dielectric)\n"
  "  --term dolp   degree of linear polarization of the specular reflection of unpolarized\n"
  "                light, |Rs - Rp| / (Rs + Rp) (eq. 8.2)\n"
  "  With --spectral, F, Fs and Fp are per wavelength, reduced to linear sRGB (eq. 7.3),\n"
  "  and dolp is |B| / A of those colours.\n"
  "\n";

enum class Term
{
  Brdf,
  F,
  D,
  G,
  Fs,
  Fp,
  DoLP
};

/// --term's spellings.
const std::pair<const char*, Term> kTerms[] = { { "brdf", Term::Brdf }, { "F", Term::F },
  { "D", Term::D }, { "G", Term::G }, { "Fs", Term::Fs }, { "Fp", Term::Fp },
  { "dolp", Term::DoLP } };

Vec3<double> DirectionFromAngles(double thetaDeg, double phiDeg)
{
  const double theta = thetaDeg * kPi<double> / 180.0;
  const double phi = phiDeg * kPi<double> / 180.0;
  return { std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta) };
}

std::vector<double> ParseAngles(const Arguments& args, const std::string& name,
  const std::string& fallback, bool polar)
{
  const auto values = ParseRange(args.Get(name, fallback), "--" + name, kMaxRows);
  if (polar)
  {
    for (double v : values)
    {
      if (v < 0.0 || v > 90.0)
      {
        throw UsageError("--" + name + ": polar angles must be in [0, 90] degrees (got " +
          std::to_string(v) + ")");
      }
    }
  }
  return values;
}

} // namespace

int RunBrdf(int argc, char** argv)
{
  std::vector<std::string> valued = { "theta-l", "theta-v", "phi", "term" };
  std::vector<std::string> flags = { "help" };
  AddSettingFlags(valued, flags, render::SettingGroup::Material);
  const Arguments args(argc, argv, valued, flags);
  if (args.Has("help"))
  {
    std::cout << kBrdfHelp << MaterialHelp();
    return 0;
  }
  if (!args.Positionals().empty())
  {
    throw UsageError("unexpected argument '" + args.Positionals().front() + "'");
  }
  if (!args.Has("theta-l"))
  {
    throw UsageError("--theta-l is required");
  }
  const Material<double> material = MaterialFromArguments(args);

  const std::string termName = args.Get("term", "brdf");
  const auto found = std::find_if(std::begin(kTerms), std::end(kTerms),
    [&](const std::pair<const char*, Term>& t) { return termName == t.first; });
  if (found == std::end(kTerms))
  {
    std::string names;
    for (const auto& t : kTerms)
    {
      names += (names.empty() ? "" : ", ") + std::string(t.first);
    }
    throw UsageError("unknown --term '" + termName + "' (expected " + names + ")");
  }
  const Term term = found->second;
  if (term != Term::Brdf && material.model != ReflectanceModel::CookTorrance)
  {
    throw UsageError("--term " + termName + " is a Cook-Torrance term: use --model cook-torrance");
  }

  const auto thetaL = ParseAngles(args, "theta-l", "", true);
  const auto thetaV = ParseAngles(args, "theta-v", "30", true);
  const auto phis = ParseAngles(args, "phi", "180", false);
  if (static_cast<double>(thetaL.size()) * thetaV.size() * phis.size() > kMaxRows)
  {
    throw UsageError("the angle ranges give more than " + std::to_string(kMaxRows) + " rows");
  }

  const Vec3<double> N(0, 0, 1);
  std::printf("theta_l,theta_v,phi,r,g,b\n");
  for (double tl : thetaL)
  {
    const Vec3<double> L = DirectionFromAngles(tl, 0.0);
    for (double tv : thetaV)
    {
      for (double phi : phis)
      {
        const Vec3<double> V = DirectionFromAngles(tv, phi);
        const Vec3<double> H = HalfVector(L, V, N);
        const double NoH = Dot(N, H), NoL = Dot(N, L), NoV = Dot(N, V);
        const double VoH = std::max(Dot(V, H), 0.0);
        Vec3<double> value;
        switch (term)
        {
          case Term::Brdf:
            value = EvaluateBrdf(material, material.diffuseColor, N, L, V);
            break;
          case Term::F:
            value = material.Fresnel(VoH);
            break;
          case Term::D:
          {
            const double D = D_BeckmannMixture(NoH, material.lobes, material.lobeCount);
            value = { D, D, D };
            break;
          }
          case Term::G:
          {
            const double G = G_CookTorrance(NoH, NoV, NoL, VoH);
            value = { G, G, G };
            break;
          }
          case Term::Fs:
          case Term::Fp:
          case Term::DoLP:
          {
            // A = (Rs + Rp) / 2, B = (Rs - Rp) / 2 (eq. 8.2).
            Vec3<double> A, B;
            material.FresnelSP(VoH, A, B);
            for (int c = 0; c < 3; ++c)
            {
              value[c] = term == Term::Fs ? A[c] + B[c]
                : term == Term::Fp        ? A[c] - B[c]
                : A[c] > 0.0              ? std::abs(B[c]) / A[c]
                                          : 0.0;
            }
            break;
          }
        }
        std::printf("%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n", tl, tv, phi, value.x, value.y,
          value.z);
      }
    }
  }
  return 0;
}

} // namespace shadinglab::cli
