// SPDX-License-Identifier: BSD-3-Clause
// What the lecture's forward differences cost in accuracy: the incremental
// span (docs/model.md eq. 2.11, the renderer's own StepSpan) against the
// exact interpolation at every pixel, for spans of 16 to 8192 pixels, in
// float and in double, for Gouraud's intensity and for Phong's normal (then
// through a Blinn-Phong lobe); and the edge walk (eq. 2.10, the renderer's
// EdgeDda) over as many rows: its crossing x drifts. `shadinglab accuracy`
// writes the table and the plot; eq. 2.12-2.13 are the bounds the test
// holds them to.
#pragma once

#include <string>
#include <vector>

namespace shadinglab::cpu
{

struct ScanStudyOptions
{
  int spansPerWidth = 64; ///< random spans per width (a fixed seed)
  int minWidth = 16;      ///< span widths minWidth, 2 minWidth, ... maxWidth pixels
  int maxWidth = 8192;
  /// Edges: the image's width, where crossings lie (their x's own rounding
  /// grows with it).
  double imageWidth = 16384;
  /// Phong: the lobe (N.H)^shininess the stepped normal is lit with; the
  /// normal error is amplified about shininess times (eq. 2.13).
  double shininess = 100;
};

struct ScanErrorRow
{
  /// "gouraud" (a span's intensity stepped), "phong" (a span's normal,
  /// then lit) or "edge" (an edge's crossing x stepped row to row).
  std::string quantity;
  std::string precision; ///< "float" or "double"
  std::string unit;      ///< "1/255" (gouraud, phong) or "px" (edge)
  int width = 0;         ///< span length in pixels (edge: rows)
  double mean = 0;       ///< mean |incremental - exact| over every pixel (row), in `unit`
  double worst = 0;      ///< the largest, in `unit`
  double last = 0;       ///< mean at each span's last pixel (where error has accumulated)
  /// The largest ratio of a pixel's error to its bound (eq. 2.12; phong
  /// eq. 2.13): <= 1 when the bound holds.
  double boundRatio = 0;
  double bound = 0;      ///< the largest bound (at a last pixel), in `unit`
};

/// Every width x precision x quantity. Deterministic.
std::vector<ScanErrorRow> IncrementalScanErrors(const ScanStudyOptions& options = {});

/// Unit roundoff of the scan arithmetic: 2^-24 (float), 2^-53 (double).
double ScanUnitRoundoff(const std::string& precision);

/// The span length at which eq. 2.12 first allows a 1/255 error for
/// intensities up to `maxIntensity` (Gouraud), in pixels.
double GouraudVisibleSpan(const std::string& precision, double maxIntensity);

} // namespace shadinglab::cpu
