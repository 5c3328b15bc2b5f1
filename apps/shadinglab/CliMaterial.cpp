// SPDX-License-Identifier: BSD-3-Clause
#include "Commands.h"

#include "shadinglab/model/Materials.h"

#include <sstream>

namespace shadinglab::cli
{

const std::vector<std::string>& MaterialOptions()
{
  static const std::vector<std::string> options = { "model", "material", "variant", "m", "w",
    "eta", "k", "kd", "ks", "shininess", "albedo", "ambient" };
  return options;
}

std::string MaterialHelp()
{
  std::ostringstream s;
  s << "Material options:\n"
       "  --model NAME        lambert | phong | blinn-phong | cook-torrance\n"
       "                      (default: cook-torrance for brdf, blinn-phong for render)\n"
       "  --material PRESET   start from a preset:";
  for (const auto& p : MaterialPresets())
  {
    s << " " << p.name;
  }
  s << "\n"
       "  --kd X --ks X       diffuse and specular weights, kd + ks <= 1\n"
       "  --albedo R,G,B      diffuse colour rho (Rd = rho/pi), default 1,1,1\n"
       "  --ambient R,G,B     ambient reflectance Ra\n"
       "  --shininess N       Phong (R.V)^N / Blinn-Phong (N.H)^N exponent, 0..1e4 (default 32);\n"
       "                      lobes normalized by (N+2)/2pi and (N+8)/8pi\n"
       "  --m M[,M..]         Cook-Torrance Beckmann RMS slope(s), 1e-3..1e3 (default 0.3)\n"
       "  --w W[,W..]         mixture weights, one per m, summing to 1 (default equal)\n"
       "  --eta E[,E,E]       relative index of refraction, one value or R,G,B (default 1.5)\n"
       "  --k K[,K,K]         extinction coefficient (conductor), one value or R,G,B (default 0)\n"
       "  --variant V         1982 (Cook & Torrance, default) | walter (Walter et al. 2007,\n"
       "                      denominator 4(N.L)(N.V))\n";
  return s.str();
}

namespace
{

Vec3<double> ParseRGB(const std::string& text, const std::string& what)
{
  const auto v = ParseList(text, what);
  if (v.size() == 1)
  {
    return { v[0], v[0], v[0] };
  }
  if (v.size() == 3)
  {
    return { v[0], v[1], v[2] };
  }
  throw UsageError(what + ": expected 1 or 3 values (R,G,B), got " + std::to_string(v.size()));
}

} // namespace

Material<double> MaterialFromArguments(const Arguments& args, bool forRender)
{
  Material<double> m;
  if (forRender)
  {
    m.model = ReflectanceModel::BlinnPhong;
    m.kd = 0.7;
    m.ks = 0.3;
  }
  else
  {
    m.model = ReflectanceModel::CookTorrance;
    m.kd = 0.0;
    m.ks = 1.0;
  }
  if (args.Has("material"))
  {
    const auto* preset = FindMaterialPreset(args.Get("material"));
    if (!preset)
    {
      throw UsageError("unknown --material '" + args.Get("material") + "'");
    }
    m = preset->material;
  }
  if (args.Has("model"))
  {
    const std::string name = args.Get("model");
    if (name == "lambert")
    {
      // Lambert has no specular term: ks is 0 whatever was given.
      m.model = ReflectanceModel::Lambert;
      m.kd = 1.0;
      m.ks = 0.0;
    }
    else if (name == "phong" || name == "blinn-phong")
    {
      m.model = name == "phong" ? ReflectanceModel::Phong : ReflectanceModel::BlinnPhong;
      if (!args.Has("kd") && !args.Has("ks") && !args.Has("material"))
      {
        m.kd = 0.7;
        m.ks = 0.3;
      }
    }
    else if (name == "cook-torrance")
    {
      m.model = ReflectanceModel::CookTorrance;
    }
    else
    {
      throw UsageError("unknown --model '" + name +
        "' (expected lambert, phong, blinn-phong or cook-torrance)");
    }
  }
  m.kd = args.GetDouble("kd", m.kd);
  m.ks = m.model == ReflectanceModel::Lambert ? 0.0 : args.GetDouble("ks", m.ks);
  m.shininess = args.GetDouble("shininess", m.shininess);
  if (args.Has("albedo"))
  {
    m.diffuseColor = ParseRGB(args.Get("albedo"), "--albedo");
  }
  if (args.Has("ambient"))
  {
    m.ambient = ParseRGB(args.Get("ambient"), "--ambient");
  }
  if (args.Has("eta"))
  {
    m.eta = ParseRGB(args.Get("eta"), "--eta");
  }
  if (args.Has("k"))
  {
    m.k = ParseRGB(args.Get("k"), "--k");
  }
  if (args.Has("variant"))
  {
    const std::string v = args.Get("variant");
    if (v == "1982")
    {
      m.variant = SpecularVariant::CookTorrance1982;
    }
    else if (v == "walter")
    {
      m.variant = SpecularVariant::Walter2007;
    }
    else
    {
      throw UsageError("unknown --variant '" + v + "' (expected 1982 or walter)");
    }
  }
  if (args.Has("m"))
  {
    const auto ms = ParseList(args.Get("m"), "--m");
    if (ms.size() > static_cast<size_t>(kMaxLobes))
    {
      throw UsageError("--m: at most " + std::to_string(kMaxLobes) + " lobes");
    }
    std::vector<double> ws(ms.size(), 1.0 / static_cast<double>(ms.size()));
    if (args.Has("w"))
    {
      ws = ParseList(args.Get("w"), "--w");
      if (ws.size() != ms.size())
      {
        throw UsageError("--w needs one weight per --m value (" + std::to_string(ms.size()) +
          "), got " + std::to_string(ws.size()));
      }
    }
    m.lobeCount = static_cast<int>(ms.size());
    for (size_t i = 0; i < ms.size(); ++i)
    {
      m.lobes[i] = { ws[i], ms[i] };
    }
  }
  else if (args.Has("w"))
  {
    throw UsageError("--w needs --m");
  }
  const std::string problem = ValidateMaterial(m);
  if (!problem.empty())
  {
    throw UsageError("invalid material: " + problem);
  }
  return m;
}

} // namespace shadinglab::cli
