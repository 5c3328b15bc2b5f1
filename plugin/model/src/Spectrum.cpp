// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/model/Spectrum.h"

#include "shadinglab/model/Fresnel.h"
#include "shadinglab/model/Materials.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <mutex>
#include <sstream>

namespace shadinglab
{

namespace
{

#include "shadinglab/model/SpectralData.inc"

/// sRGB's primaries and D65 white, XYZ to linear RGB (IEC 61966-2-1:1999,
/// the matrix to four decimals as the standard prints it).
constexpr double kXyzToSrgb[3][3] = { { 3.2406, -1.5372, -0.4986 },
  { -0.9689, 1.8758, 0.0415 }, { 0.0557, -0.2040, 1.0570 } };
/// Its inverse (the standard's), linear sRGB to XYZ.
constexpr double kSrgbToXyz[3][3] = { { 0.4124, 0.3576, 0.1805 }, { 0.2126, 0.7152, 0.0722 },
  { 0.0193, 0.1192, 0.9505 } };

struct CieRow
{
  double nm, xbar, ybar, zbar, d65;
};

std::vector<double> Numbers(const std::string& line, char separator)
{
  std::vector<double> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, separator))
  {
    char* end = nullptr;
    const double v = std::strtod(cell.c_str(), &end);
    if (end == cell.c_str())
    {
      return {};
    }
    out.push_back(v);
  }
  return out;
}

/// The CIE 1931 2-degree observer and D65, 380-780 nm every 5 nm.
const std::array<CieRow, kCieRows>& CieTable()
{
  static const std::array<CieRow, kCieRows> table = [] {
    std::array<CieRow, kCieRows> t{};
    std::istringstream cmf(kCie1931Csv), d65(kD65Csv);
    std::string a, b;
    std::getline(cmf, a); // headers
    std::getline(d65, b);
    for (int i = 0; i < kCieRows; ++i)
    {
      std::getline(cmf, a);
      std::getline(d65, b);
      const std::vector<double> x = Numbers(a, ','), s = Numbers(b, ',');
      t[i] = { x.at(0), x.at(1), x.at(2), x.at(3), s.at(1) };
    }
    return t;
  }();
  return table;
}

Vec3<double> Mul(const double m[3][3], const Vec3<double>& v)
{
  return { m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
    m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z, m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z };
}

double Interpolate(const std::vector<double>& x, const std::vector<double>& y, double at)
{
  if (at <= x.front())
  {
    return y.front();
  }
  if (at >= x.back())
  {
    return y.back();
  }
  const size_t i = std::upper_bound(x.begin(), x.end(), at) - x.begin();
  const double f = (at - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + f * (y[i] - y[i - 1]);
}

std::string Trim(const std::string& s)
{
  const size_t a = s.find_first_not_of(" \t\r");
  const size_t b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

/// Rows "wavelength_um value [value]" of a `data: |` block into nm and
/// columns. Returns "" or the problem.
std::string ReadRows(const std::vector<std::string>& rows, int columns, std::vector<double>& nm,
  std::vector<double>& first, std::vector<double>* second)
{
  for (const std::string& row : rows)
  {
    std::istringstream in(row);
    std::vector<double> v;
    std::string word;
    while (in >> word)
    {
      char* end = nullptr;
      const double x = std::strtod(word.c_str(), &end);
      if (end == word.c_str() || *end != '\0' || !std::isfinite(x))
      {
        return "row '" + row + "' is not numbers";
      }
      v.push_back(x);
    }
    if (static_cast<int>(v.size()) != columns)
    {
      std::ostringstream err;
      err << "row '" << row << "' has " << v.size() << " numbers, expected " << columns;
      return err.str();
    }
    const double lambda = v[0] * 1000.0; // um to nm
    if (!nm.empty() && !(lambda > nm.back()))
    {
      return "wavelengths do not increase at row '" + row + "'";
    }
    if (!(lambda > 0.0))
    {
      return "wavelength <= 0 at row '" + row + "'";
    }
    nm.push_back(lambda);
    first.push_back(v[1]);
    if (second)
    {
      second->push_back(v[2]);
    }
  }
  return {};
}

} // namespace

bool Dispersion::Evaluate(double nm, double& nOut, double& kOut) const
{
  if (!(nm >= minNm && nm <= maxNm))
  {
    return false;
  }
  if (sellmeier)
  {
    const double l2 = (nm / 1000.0) * (nm / 1000.0);
    double n2 = 1.0;
    for (int i = 0; i < 3; ++i)
    {
      n2 += coefficients[2 * i] * l2 / (l2 - coefficients[2 * i + 1]);
    }
    nOut = std::sqrt(std::max(n2, 0.0));
  }
  else
  {
    nOut = Interpolate(nmN, n, nm);
  }
  kOut = nmK.empty() ? 0.0 : Interpolate(nmK, k, nm);
  return true;
}

namespace
{

/// One block of a refractiveindex.info file's DATA section.
struct DispersionBlock
{
  std::string type;
  std::vector<std::string> rows;
  std::vector<double> coefficients;
  std::vector<double> range;
};

/// The DATA section's blocks: "- type: ..." starts one; "data: |" is
/// followed by indented rows; "coefficients: ..." and "wavelength_range:
/// a b" are one line.
std::vector<DispersionBlock> ReadDispersionBlocks(const std::string& text)
{
  std::istringstream in(text);
  std::string line;
  std::vector<DispersionBlock> blocks;
  bool inData = false, inDataSection = false;
  size_t dataIndent = 0;
  while (std::getline(in, line))
  {
    const std::string t = Trim(line);
    if (t.empty() || t[0] == '#')
    {
      continue;
    }
    const size_t indent = line.find_first_not_of(' ');
    if (inData && indent >= dataIndent)
    {
      blocks.back().rows.push_back(t);
      continue;
    }
    inData = false;
    if (indent == 0)
    {
      inDataSection = t.rfind("DATA:", 0) == 0;
      continue;
    }
    if (!inDataSection)
    {
      continue;
    }
    std::string item = t;
    if (item.rfind("- ", 0) == 0)
    {
      blocks.emplace_back();
      item = Trim(item.substr(2));
    }
    if (blocks.empty())
    {
      continue;
    }
    const size_t colon = item.find(':');
    if (colon == std::string::npos)
    {
      continue;
    }
    const std::string key = Trim(item.substr(0, colon));
    const std::string value = Trim(item.substr(colon + 1));
    if (key == "type")
    {
      blocks.back().type = value;
    }
    else if (key == "data")
    {
      inData = true;
      dataIndent = indent + 1;
    }
    else if (key == "coefficients" || key == "wavelength_range")
    {
      std::istringstream v(value);
      double x;
      auto& target = key == "coefficients" ? blocks.back().coefficients : blocks.back().range;
      while (v >> x)
      {
        target.push_back(x);
      }
    }
  }
  return blocks;
}

/// The blocks' data into `d`, with its wavelength range: "" or the
/// problem (without the file's name).
std::string FillDispersion(const std::vector<DispersionBlock>& blocks, Dispersion& d)
{
  for (const DispersionBlock& b : blocks)
  {
    std::string problem;
    if (b.type == "tabulated nk")
    {
      problem = ReadRows(b.rows, 3, d.nmN, d.n, &d.k);
      d.nmK = d.nmN;
    }
    else if (b.type == "tabulated n")
    {
      problem = ReadRows(b.rows, 2, d.nmN, d.n, nullptr);
    }
    else if (b.type == "tabulated k")
    {
      problem = ReadRows(b.rows, 2, d.nmK, d.k, nullptr);
    }
    else if (b.type == "formula 2")
    {
      if (b.coefficients.size() != 7 || b.range.size() != 2)
      {
        return "formula 2 needs 7 coefficients (0 B1 C1 B2 C2 B3 C3) and a "
                      "wavelength_range";
      }
      d.sellmeier = true;
      std::copy(b.coefficients.begin() + 1, b.coefficients.end(), d.coefficients);
      d.minNm = b.range[0] * 1000.0;
      d.maxNm = b.range[1] * 1000.0;
    }
    else
    {
      return "data type '" + b.type +
        "' is not supported (tabulated nk, tabulated n, formula 2 are)";
    }
    if (!problem.empty())
    {
      return "" + problem;
    }
  }
  if (!d.sellmeier)
  {
    if (d.nmN.size() < 2)
    {
      return "fewer than two rows of n";
    }
    d.minNm = d.nmN.front();
    d.maxNm = d.nmN.back();
  }
  return {};
}

/// Every n > 0 and k >= 0, and n finite and positive over the visible
/// range (the Sellmeier form has poles): "" or the problem.
std::string CheckDispersion(const Dispersion& d, const std::string& name)
{
  for (double v : d.n)
  {
    if (!(v > 0.0))
    {
      return name + ": n <= 0 in the data";
    }
  }
  for (double v : d.k)
  {
    if (!(v >= 0.0))
    {
      return name + ": k < 0 in the data";
    }
  }
  // The Sellmeier form has poles at l^2 = C_i: check n over the range.
  for (int i = 0; i < kCieRows; ++i)
  {
    double nv = 0, kv = 0;
    const double nm = kVisibleMinNm + 5.0 * i;
    if (!d.Evaluate(nm, nv, kv))
    {
      std::ostringstream err;
      err << name << ": the data cover " << d.minNm << "-" << d.maxNm
          << " nm, not the visible 380-780 nm";
      return err.str();
    }
    if (!(nv > 0.0) || !std::isfinite(nv))
    {
      std::ostringstream err;
      err << name << ": n is not a positive number at " << nm << " nm";
      return err.str();
    }
  }
  return {};
}

} // namespace

std::string ParseDispersion(const std::string& text, const std::string& name, Dispersion& out)
{
  const std::vector<DispersionBlock> blocks = ReadDispersionBlocks(text);
  if (blocks.empty())
  {
    return name + ": no DATA block (not a refractiveindex.info file)";
  }
  Dispersion d;
  d.name = name;
  std::string problem = FillDispersion(blocks, d);
  if (!problem.empty())
  {
    return name + ": " + problem;
  }
  problem = CheckDispersion(d, name);
  if (!problem.empty())
  {
    return problem;
  }
  out = std::move(d);
  return {};
}

const Dispersion* PresetDispersion(const std::string& preset)
{
  static const std::map<std::string, Dispersion> table = [] {
    const std::pair<const char*, const char*> files[] = { { "gold", kGoldYml },
      { "silver", kSilverYml }, { "copper", kCopperYml }, { "aluminium", kAluminiumYml },
      { "glass", kGlassYml }, { "water", kWaterYml } };
    std::map<std::string, Dispersion> t;
    for (const auto& [name, yml] : files)
    {
      Dispersion d;
      if (ParseDispersion(yml, name, d).empty())
      {
        t[name] = std::move(d);
      }
    }
    return t;
  }();
  const auto it = table.find(preset == "aluminum" ? "aluminium" : preset);
  return it == table.end() ? nullptr : &it->second;
}

const std::vector<std::string>& PresetDispersionNames()
{
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const MaterialPreset& preset : MaterialPresets())
    {
      if (PresetDispersion(preset.name))
      {
        out.push_back(preset.name);
      }
    }
    return out;
  }();
  return names;
}

const SpectralBasis& SpectralBasisD65(int count)
{
  static std::mutex mutex;
  static std::map<int, SpectralBasis> cache;
  count = std::clamp(count, 1, kCieRows);
  std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(count);
  if (it != cache.end())
  {
    return it->second;
  }
  const auto& cie = CieTable();
  double norm = 0.0;
  for (const CieRow& r : cie)
  {
    norm += r.d65 * r.ybar;
  }
  SpectralBasis basis;
  for (int g = 0; g < count; ++g)
  {
    // Rows [first, last) of group g: (nearly) equal groups, in order.
    const int first = static_cast<int>(std::lround(double(g) * kCieRows / count));
    const int last = static_cast<int>(std::lround(double(g + 1) * kCieRows / count));
    Vec3<double> xyz;
    double nm = 0.0;
    for (int j = first; j < last; ++j)
    {
      xyz += Vec3<double>(cie[j].xbar, cie[j].ybar, cie[j].zbar) * (cie[j].d65 / norm);
      nm += cie[j].nm;
    }
    basis.wavelength.push_back(nm / (last - first));
    basis.weight.push_back(Mul(kXyzToSrgb, xyz));
  }
  return cache.emplace(count, std::move(basis)).first->second;
}

Vec3<double> SpectrumToLinearSRGB(const std::function<double(double)>& R, int count)
{
  const SpectralBasis& basis = SpectralBasisD65(count);
  Vec3<double> rgb;
  for (size_t i = 0; i < basis.wavelength.size(); ++i)
  {
    rgb += basis.weight[i] * R(basis.wavelength[i]);
  }
  return rgb;
}

Vec3<double> LinearSRGBToXYZ(const Vec3<double>& rgb)
{
  return Mul(kSrgbToXyz, rgb);
}

Vec3<double> XYZToLab(const Vec3<double>& xyz)
{
  // The white: D65 through the same matrix, (0.9505, 1, 1.089).
  const Vec3<double> white = LinearSRGBToXYZ({ 1.0, 1.0, 1.0 });
  // CIE 15: f(t) = t^(1/3) above (6/29)^3, linear below.
  constexpr double delta = 6.0 / 29.0;
  auto f = [&](double t) {
    return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
  };
  const double fx = f(xyz.x / white.x), fy = f(xyz.y / white.y), fz = f(xyz.z / white.z);
  return { 116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz) };
}

double DeltaE2000(const Vec3<double>& rgbA, const Vec3<double>& rgbB)
{
  return DeltaE2000Lab(XYZToLab(LinearSRGBToXYZ(rgbA)), XYZToLab(LinearSRGBToXYZ(rgbB)));
}

double DeltaE2000Lab(const Vec3<double>& lab1, const Vec3<double>& lab2)
{
  // Sharma, Wu & Dalal 2005, eq. 1-22 (kL = kC = kH = 1).
  constexpr double deg = kPi<double> / 180.0;
  const double C1 = std::hypot(lab1.y, lab1.z), C2 = std::hypot(lab2.y, lab2.z);
  const double Cbar7 = std::pow(0.5 * (C1 + C2), 7.0);
  const double G = 0.5 * (1.0 - std::sqrt(Cbar7 / (Cbar7 + std::pow(25.0, 7.0))));
  const double a1 = (1.0 + G) * lab1.y, a2 = (1.0 + G) * lab2.y;
  const double C1p = std::hypot(a1, lab1.z), C2p = std::hypot(a2, lab2.z);
  auto hue = [&](double b, double a) {
    if (a == 0.0 && b == 0.0)
    {
      return 0.0;
    }
    const double h = std::atan2(b, a) / deg;
    return h < 0.0 ? h + 360.0 : h;
  };
  const double h1 = hue(lab1.z, a1), h2 = hue(lab2.z, a2);
  const double dL = lab2.x - lab1.x, dC = C2p - C1p;
  double dh = 0.0;
  if (C1p * C2p != 0.0)
  {
    dh = h2 - h1;
    dh += dh > 180.0 ? -360.0 : (dh < -180.0 ? 360.0 : 0.0);
  }
  const double dH = 2.0 * std::sqrt(C1p * C2p) * std::sin(0.5 * dh * deg);
  const double Lbar = 0.5 * (lab1.x + lab2.x), Cbarp = 0.5 * (C1p + C2p);
  double hbar = h1 + h2;
  if (C1p * C2p != 0.0)
  {
    hbar = std::abs(h1 - h2) <= 180.0 ? 0.5 * (h1 + h2)
                                      : (h1 + h2 < 360.0 ? 0.5 * (h1 + h2 + 360.0)
                                                         : 0.5 * (h1 + h2 - 360.0));
  }
  const double T = 1.0 - 0.17 * std::cos((hbar - 30.0) * deg) + 0.24 * std::cos(2.0 * hbar * deg) +
    0.32 * std::cos((3.0 * hbar + 6.0) * deg) - 0.20 * std::cos((4.0 * hbar - 63.0) * deg);
  const double dTheta = 30.0 * std::exp(-std::pow((hbar - 275.0) / 25.0, 2.0));
  const double Cbarp7 = std::pow(Cbarp, 7.0);
  const double RC = 2.0 * std::sqrt(Cbarp7 / (Cbarp7 + std::pow(25.0, 7.0)));
  const double L50 = (Lbar - 50.0) * (Lbar - 50.0);
  const double SL = 1.0 + 0.015 * L50 / std::sqrt(20.0 + L50);
  const double SC = 1.0 + 0.045 * Cbarp;
  const double SH = 1.0 + 0.015 * Cbarp * T;
  const double RT = -std::sin(2.0 * dTheta * deg) * RC;
  const double l = dL / SL, c = dC / SC, h = dH / SH;
  return std::sqrt(std::max(0.0, l * l + c * c + h * h + RT * c * h));
}

std::string SetSpectral(Material<double>& material, const Dispersion& dispersion)
{
  const SpectralBasis& basis = SpectralBasisD65(kSpectralSamples);
  for (int i = 0; i < kSpectralSamples; ++i)
  {
    double n = 0, k = 0;
    if (!dispersion.Evaluate(basis.wavelength[i], n, k))
    {
      return dispersion.name + ": no data at " + std::to_string(basis.wavelength[i]) + " nm";
    }
    material.spectralEta[i] = n;
    material.spectralK[i] = k;
    material.spectralWeight[i] = basis.weight[i];
  }
  material.spectralCount = kSpectralSamples;
  return {};
}

void RgbFromDispersion(
  const Dispersion& dispersion, RgbChoice choice, Vec3<double>& eta, Vec3<double>& k)
{
  const double sampled[3] = { 650.0, 550.0, 450.0 };
  const double lower[3] = { 590.0, 490.0, 380.0 };
  const double upper[3] = { 780.0, 590.0, 490.0 };
  for (int c = 0; c < 3; ++c)
  {
    double n = 0, kv = 0;
    if (choice == RgbChoice::Band)
    {
      // Mean over the band's 5 nm rows.
      int rows = 0;
      double sn = 0, sk = 0;
      for (double nm = lower[c]; nm <= upper[c] + 1e-9; nm += 5.0)
      {
        dispersion.Evaluate(nm, n, kv);
        sn += n;
        sk += kv;
        ++rows;
      }
      eta[c] = sn / rows;
      k[c] = sk / rows;
      continue;
    }
    dispersion.Evaluate(sampled[c], n, kv);
    eta[c] = n;
    k[c] = kv;
  }
  if (choice != RgbChoice::Fitted)
  {
    return;
  }
  // Fitted: per channel, the (n, k) whose F is closest (least squares over
  // incidence 0-85 degrees) to that channel of the spectral colour. A grid
  // search, refined twice around the best cell.
  Material<double> spectral;
  SetSpectral(spectral, dispersion);
  constexpr int kAngles = 18;
  double target[kAngles][3];
  for (int a = 0; a < kAngles; ++a)
  {
    const double cosTheta = std::cos(a * 5.0 * kPi<double> / 180.0);
    Vec3<double> rgb;
    for (int i = 0; i < kSpectralSamples; ++i)
    {
      rgb += spectral.spectralWeight[i] *
        F_Conductor(cosTheta, spectral.spectralEta[i], spectral.spectralK[i]);
    }
    for (int c = 0; c < 3; ++c)
    {
      target[a][c] = rgb[c];
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    double bestN = eta[c], bestK = k[c];
    double spanN = std::max(1.0, bestN), spanK = std::max(2.0, bestK);
    for (int round = 0; round < 3; ++round)
    {
      double best = 1e300;
      const double n0 = bestN, k0 = bestK;
      for (int i = -20; i <= 20; ++i)
      {
        for (int j = -20; j <= 20; ++j)
        {
          const double n = n0 + spanN * i / 20.0, kv = k0 + spanK * j / 20.0;
          if (n <= 0.01 || kv < 0.0)
          {
            continue;
          }
          double e = 0.0;
          for (int a = 0; a < kAngles; ++a)
          {
            const double d =
              F_Conductor(std::cos(a * 5.0 * kPi<double> / 180.0), n, kv) - target[a][c];
            e += d * d;
          }
          if (e < best)
          {
            best = e;
            bestN = n;
            bestK = kv;
          }
        }
      }
      spanN /= 10.0;
      spanK /= 10.0;
    }
    eta[c] = bestN;
    k[c] = bestK;
  }
}

} // namespace shadinglab
