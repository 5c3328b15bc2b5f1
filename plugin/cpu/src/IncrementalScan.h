// SPDX-License-Identifier: BSD-3-Clause
// The lecture's scan conversion as written (RenderOptions::scan =
// Incremental): a digital differential analyser. Every edge steps its
// crossing and its attributes from one scanline to the next (docs/model.md
// eq. 2.10), every span steps its attributes from one pixel to the next
// (eq. 2.11), in the arithmetic T (float or double). Nothing is recomputed
// from the vertices after an edge's first row and a span's first pixel, so
// rounding error accumulates along both; eq. 2.12 bounds it, and the
// accuracy study (ScanStudy.h) measures it.
//
// The attributes are interpolated linearly in screen space, as on the
// slides: the renderer pins 1/w to 1 for this scan (SoftwareRenderer.cpp).
#pragma once

#include "Raster.h"

#include <cmath>
#include <type_traits>

namespace shadinglab::cpu::raster
{

/// ceil(x) as an int for the pixel-centre rules, in the scan's arithmetic:
/// clamped to +-1e9 pixels first as CeilToInt(float).
inline int CeilToIntIn(double x)
{
  x = x < -1e9 ? -1e9 : (x > 1e9 ? 1e9 : x);
  const int i = static_cast<int>(x);
  return i + (x > static_cast<double>(i) ? 1 : 0);
}

/**
 * One span of eq. 2.11: the pixels i with xl <= i + 1/2 < xr of a width-
 * pixel row, clipped to [0, width). The first pixel's value is interpolated
 * from the span's ends (eq. 2.4), every next one is
 * I_{p+1} = I_p + (I_5 - I_4)/(x_5 - x_4), for `na` attributes at once, in
 * T. pixel(i, value) is called with the T values.
 */
template<typename T, typename PixelFn>
void StepSpan(int width, int na, T xl, const T* al, T xr, const T* ar, PixelFn&& pixel)
{
  const int i0 = std::max(0, CeilToIntIn(static_cast<double>(xl - T(0.5))));
  const int i1 = std::min(width, CeilToIntIn(static_cast<double>(xr - T(0.5))));
  if (i1 <= i0)
  {
    return;
  }
  T value[kMaxAttributes], delta[kMaxAttributes];
  const T invSpan = T(1) / (xr - xl);
  const T start = static_cast<T>(i0) + T(0.5) - xl;
  for (int k = 0; k < na; ++k)
  {
    delta[k] = (ar[k] - al[k]) * invSpan;
    value[k] = al[k] + start * delta[k];
  }
  for (int i = i0; i < i1; ++i)
  {
    pixel(i, static_cast<const T*>(value));
    for (int k = 0; k < na; ++k)
    {
      value[k] += delta[k];
    }
  }
}

/**
 * One edge of eq. 2.10, from its upper end p to its lower end q (p.y <=
 * q.y): the rows [jFirst, jEnd) whose pixel centres it crosses, its
 * crossing x and attributes at the current row, and their steps per row.
 */
template<typename T>
struct EdgeDda
{
  int jFirst = 0, jEnd = 0;
  T x = 0, dx = 0;     ///< crossing and its step per row (1/m)
  T a[kMaxAttributes]; ///< attributes at the crossing
  T da[kMaxAttributes]; ///< and their steps per row

  /// The first row's crossing (eq. 2.3 once); false when the edge crosses
  /// no pixel-centre row in the image. An edge that starts above the image
  /// starts at row 0 (its rows above are never drawn, and a vertex near the
  /// eye plane can lie a billion rows up).
  bool Start(const ScreenVertex& p, const ScreenVertex& q, int na)
  {
    this->jFirst = std::max(0, CeilToInt(p.y - 0.5f));
    this->jEnd = CeilToInt(q.y - 0.5f);
    if (this->jEnd <= this->jFirst)
    {
      return false; // horizontal, between two pixel-centre rows, or above the image
    }
    const T invDy = T(1) / (static_cast<T>(q.y) - static_cast<T>(p.y));
    const T dy0 = static_cast<T>(this->jFirst) + T(0.5) - static_cast<T>(p.y);
    this->dx = (static_cast<T>(q.x) - static_cast<T>(p.x)) * invDy;
    this->x = static_cast<T>(p.x) + dy0 * this->dx;
    for (int i = 0; i < na; ++i)
    {
      this->da[i] = (static_cast<T>(q.a[i]) - static_cast<T>(p.a[i])) * invDy;
      this->a[i] = static_cast<T>(p.a[i]) + dy0 * this->da[i];
    }
    return true;
  }

  /// eq. 2.10: x_{q+1} = x_q + 1/m, I_{q+1} = I_q + (I_1 - I_2)/(y_1 - y_2).
  void Step(int na)
  {
    this->x += this->dx;
    for (int i = 0; i < na; ++i)
    {
      this->a[i] += this->da[i];
    }
  }
};

/**
 * Scan-converts a polygon of n screen vertices into rows [rowBegin, rowEnd)
 * by eq. 2.10-2.11: beginSpan(j, i0) at every span's start, pixel(j, i,
 * attributes) at every pixel centre inside (attributes as float, in the
 * slots of ScreenVertex::a). Edges are walked from their first row in the
 * image even when that row is above rowBegin, so a row's values do not
 * depend on the band it is drawn in (the image is the same for any thread
 * count).
 */
template<typename T, typename PixelFn, typename SpanFn>
void ScanIncremental(int width,
  int numAttributes,
  const ScreenVertex* const* verts,
  int n,
  int rowBegin,
  int rowEnd,
  SpanFn&& beginSpan,
  PixelFn&& pixel,
  SpanTrace* trace = nullptr)
{
  const int na = kAttrFirst + numAttributes;
  EdgeDda<T> edges[kMaxPolygonVertices];
  int ne = 0, j0 = rowEnd, j1 = rowBegin;
  for (int k = 0; k < n; ++k)
  {
    const ScreenVertex* p = verts[k];
    const ScreenVertex* q = verts[(k + 1) % n];
    CanonicalEdge(p, q); // neighbours step a shared edge alike: watertight
    EdgeDda<T>& e = edges[ne];
    if (e.Start(*p, *q, na))
    {
      ++ne;
      j0 = std::min(j0, e.jFirst);
      j1 = std::max(j1, e.jEnd);
    }
  }
  j1 = std::min(j1, rowEnd);
  struct Crossing
  {
    T x;
    const T* a;
  };
  float out[kMaxAttributes] = {};
  for (int j = j0; j < j1; ++j)
  {
    Crossing cross[kMaxPolygonVertices];
    int nc = 0;
    for (int k = 0; k < ne; ++k)
    {
      EdgeDda<T>& e = edges[k];
      if (j < e.jFirst || j >= e.jEnd)
      {
        continue;
      }
      if (j > e.jFirst)
      {
        e.Step(na);
      }
      cross[nc++] = { e.x, e.a };
    }
    if (j < rowBegin)
    {
      continue; // stepped, not drawn: another band's row
    }
    SortCrossings(cross, nc);
    for (int s = 0; s + 1 < nc; s += 2)
    {
      if (trace && j == trace->row)
      {
        float al[kMaxAttributes], ar[kMaxAttributes];
        for (int k = 0; k < na; ++k)
        {
          al[k] = static_cast<float>(cross[s].a[k]);
          ar[k] = static_cast<float>(cross[s + 1].a[k]);
        }
        trace->record(static_cast<float>(cross[s].x), al, static_cast<float>(cross[s + 1].x), ar);
      }
      bool begun = false;
      StepSpan<T>(width, na, cross[s].x, cross[s].a, cross[s + 1].x, cross[s + 1].a,
        [&](int i, const T* value)
        {
          if (!begun)
          {
            beginSpan(j, i);
            begun = true;
          }
          if constexpr (std::is_same_v<T, float>)
          {
            pixel(j, i, value);
          }
          else
          {
            for (int k = 0; k < na; ++k)
            {
              out[k] = static_cast<float>(value[k]);
            }
            pixel(j, i, static_cast<const float*>(out));
          }
        });
    }
  }
}

} // namespace shadinglab::cpu::raster
