// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/cpu/ScanStudy.h"

#include "IncrementalScan.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace shadinglab::cpu
{

namespace
{

/// Slack on the first-order bounds (eq. 2.12-2.13) for the terms of order
/// u^2 p they leave out: p u <= 8192 x 2^-24 = 4.9e-4 in float, so 1e-3
/// covers them with room.
constexpr double kSecondOrderSlack = 1e-3;
/// The exact lobe is itself computed (in long double): its cosine is off by
/// a few units in the last place (a dot product, a square root and a
/// division), which the lobe multiplies by up to the shininess. 16 ulps
/// cover them; in double the study's smallest errors (~1e-17) are of this
/// size.
constexpr double kReferenceCosineUlps = 16;
/// Phong: normals within this angle of the view axis (radians, 45
/// degrees): both ends face the viewer and the span's normal never
/// shortens below cos(45 degrees) = 0.71.
constexpr double kMaxNormalTilt = 0.7853981633974483;

/// A portable uniform generator (SplitMix64): the study's spans are the
/// same on every standard library.
struct Uniform
{
  uint64_t state;
  double operator()()
  {
    uint64_t z = (this->state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
  }
};

struct Accumulator
{
  double sum = 0, worst = 0, lastSum = 0, ratio = 0, worstBound = 0;
  int64_t count = 0, spans = 0;
  double last = 0; ///< the current span's (edge's) latest error

  /// One pixel (row): its error and its bound.
  void Add(double error, double bound)
  {
    this->sum += error;
    this->worst = std::max(this->worst, error);
    this->ratio = bound > 0 ? std::max(this->ratio, error / bound) : this->ratio;
    this->worstBound = std::max(this->worstBound, bound);
    ++this->count;
    this->last = error;
  }
  /// The end of a span (edge): its last error counts towards `lastSum`.
  void EndSpan()
  {
    this->lastSum += this->last;
    this->last = 0;
    ++this->spans;
  }
};

/// A unit normal within kMaxNormalTilt of +z.
void RandomNormal(Uniform& rnd, double n[3])
{
  const double tilt = kMaxNormalTilt * std::sqrt(rnd()), phi = 2 * 3.141592653589793 * rnd();
  n[0] = std::sin(tilt) * std::cos(phi);
  n[1] = std::sin(tilt) * std::sin(phi);
  n[2] = std::cos(tilt);
}

/// Blinn-Phong's lobe of a (not normalized) normal.
long double Lobe(const long double n[3], const double H[3], double shininess)
{
  const long double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const long double c = (n[0] * H[0] + n[1] * H[1] + n[2] * H[2]) / len;
  return c > 0 ? std::pow(c, static_cast<long double>(shininess)) : 0.0L;
}

/// One span of `width` pixels in arithmetic T: Gouraud's intensity or
/// Phong's normal stepped by StepSpan, each pixel against the exact
/// interpolation of the same end values (long double).
template<typename T>
void MeasureSpan(bool phong, int width, const ScanStudyOptions& options, Uniform& rnd,
  Accumulator& acc)
{
  const double shininess = options.shininess;
  const double u = std::is_same_v<T, float> ? 0x1.0p-24 : 0x1.0p-53;
  const T xl = static_cast<T>(rnd() * (options.imageWidth - width - 2));
  const T xr = static_cast<T>(static_cast<double>(xl) + width + rnd() * 0.999);
  const int na = phong ? 3 : 1;
  T al[3], ar[3];
  double H[3] = { 0, 0, 1 };
  if (phong)
  {
    double n4[3], n5[3];
    RandomNormal(rnd, n4);
    RandomNormal(rnd, n5);
    // The highlight inside the span: H halfway between the end normals.
    const double h[3] = { n4[0] + n5[0], n4[1] + n5[1], n4[2] + n5[2] };
    const double len = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    for (int k = 0; k < 3; ++k)
    {
      al[k] = static_cast<T>(n4[k]);
      ar[k] = static_cast<T>(n5[k]);
      H[k] = h[k] / len;
    }
  }
  else
  {
    al[0] = static_cast<T>(rnd());
    ar[0] = static_cast<T>(rnd());
  }
  const long double lx = xl, rx = xr;
  double M[3], D[3];
  for (int k = 0; k < na; ++k)
  {
    M[k] = std::max(std::abs(static_cast<double>(al[k])), std::abs(static_cast<double>(ar[k])));
    D[k] = std::abs(static_cast<double>(ar[k]) - static_cast<double>(al[k]));
  }
  int p = 0;
  raster::StepSpan<T>(static_cast<int>(options.imageWidth), na, xl, al, xr, ar,
    [&](int i, const T* value)
    {
      const long double t = (static_cast<long double>(i) + 0.5L - lx) / (rx - lx);
      long double exact[3], stepped[3];
      double componentBound2 = 0;
      for (int k = 0; k < na; ++k)
      {
        exact[k] = al[k] + t * (static_cast<long double>(ar[k]) - al[k]);
        stepped[k] = value[k];
        // eq. 2.12: u ((p + 1) M + 6 |I_5 - I_4|).
        const double b = u * ((p + 1) * M[k] + 6 * D[k]) * (1 + kSecondOrderSlack);
        componentBound2 += b * b;
      }
      double error = 0, bound = 0;
      if (phong)
      {
        error = static_cast<double>(
          std::abs(Lobe(stepped, H, shininess) - Lobe(exact, H, shininess)));
        // eq. 2.13: r = |dN| / (|N| - |dN|), dc = (sin theta + r) r,
        // |dI| <= s (max(c, 0) + dc)^(s - 1) dc.
        const double len = static_cast<double>(
          std::sqrt(exact[0] * exact[0] + exact[1] * exact[1] + exact[2] * exact[2]));
        const double c = static_cast<double>(
          (exact[0] * H[0] + exact[1] * H[1] + exact[2] * H[2]) / len);
        const double dn = std::sqrt(componentBound2);
        const double r = dn / (len - dn);
        const double dc = (std::sqrt(std::max(0.0, 1 - c * c)) + r) * r * (1 + kSecondOrderSlack);
        bound = shininess * std::pow(std::min(1.0, std::max(c, 0.0) + dc), shininess - 1) * dc +
          shininess * kReferenceCosineUlps * std::numeric_limits<long double>::epsilon();
      }
      else
      {
        error = static_cast<double>(std::abs(stepped[0] - exact[0]));
        bound = std::sqrt(componentBound2);
      }
      acc.Add(error, bound);
      ++p;
    });
  acc.EndSpan();
}

/// One edge of `rows` rows in arithmetic T: EdgeDda's crossing x at every
/// row against the exact crossing of the same end points (long double), in
/// pixels; eq. 2.12 with M the larger |x| of its ends.
template<typename T>
void MeasureEdge(int rows, const ScanStudyOptions& options, Uniform& rnd, Accumulator& acc)
{
  const double u = std::is_same_v<T, float> ? 0x1.0p-24 : 0x1.0p-53;
  raster::ScreenVertex p{}, q{};
  p.x = static_cast<float>(rnd() * (options.imageWidth - 1));
  q.x = static_cast<float>(rnd() * (options.imageWidth - 1));
  p.y = static_cast<float>(rnd());
  q.y = static_cast<float>(static_cast<double>(p.y) + rows + rnd() * 0.999);
  raster::EdgeDda<T> edge;
  if (!edge.Start(p, q, 0))
  {
    return;
  }
  const double M = std::max(std::abs(p.x), std::abs(q.x));
  const double D = std::abs(static_cast<double>(q.x) - p.x);
  for (int j = edge.jFirst, step = 0; j < edge.jEnd; ++j, ++step)
  {
    if (j > edge.jFirst)
    {
      edge.Step(0);
    }
    const long double t = (static_cast<long double>(j) + 0.5L - p.y) /
      (static_cast<long double>(q.y) - p.y);
    const long double exact = p.x + t * (static_cast<long double>(q.x) - p.x);
    const double error = static_cast<double>(std::abs(static_cast<long double>(edge.x) - exact));
    const double bound = u * ((step + 1) * M + 6 * D) * (1 + kSecondOrderSlack);
    acc.Add(error, bound);
  }
  acc.EndSpan();
}

} // namespace

double ScanUnitRoundoff(const std::string& precision)
{
  return precision == "double" ? 0x1.0p-53 : 0x1.0p-24;
}

double GouraudVisibleSpan(const std::string& precision, double maxIntensity)
{
  // eq. 2.12 with |I_5 - I_4| <= M: 255 u (p + 7) M = 1.
  return 1.0 / (255.0 * ScanUnitRoundoff(precision) * maxIntensity) - 7.0;
}

std::vector<ScanErrorRow> IncrementalScanErrors(const ScanStudyOptions& options)
{
  std::vector<ScanErrorRow> rows;
  for (const char* quantity : { "gouraud", "phong", "edge" })
  {
    const bool phong = quantity[0] == 'p', edge = quantity[0] == 'e';
    const double scale = edge ? 1.0 : 255.0; // pixels, or 1/255 of the display range
    for (const char* precision : { "float", "double" })
    {
      const bool single = precision[0] == 'f';
      for (int width = options.minWidth; width <= options.maxWidth; width *= 2)
      {
        // The same spans for both precisions: a seed per quantity and width.
        Uniform rnd{ static_cast<uint64_t>(width) * 4 + (phong ? 1 : 0) + (edge ? 2 : 0) };
        Accumulator acc;
        for (int s = 0; s < options.spansPerWidth; ++s)
        {
          if (edge)
          {
            single ? MeasureEdge<float>(width, options, rnd, acc)
                   : MeasureEdge<double>(width, options, rnd, acc);
          }
          else
          {
            single ? MeasureSpan<float>(phong, width, options, rnd, acc)
                   : MeasureSpan<double>(phong, width, options, rnd, acc);
          }
        }
        ScanErrorRow row;
        row.quantity = quantity;
        row.precision = precision;
        row.unit = edge ? "px" : "1/255";
        row.width = width;
        row.mean = scale * acc.sum / std::max<int64_t>(1, acc.count);
        row.worst = scale * acc.worst;
        row.last = scale * acc.lastSum / std::max<int64_t>(1, acc.spans);
        row.boundRatio = acc.ratio;
        row.bound = scale * acc.worstBound;
        rows.push_back(row);
      }
    }
  }
  return rows;
}

} // namespace shadinglab::cpu
