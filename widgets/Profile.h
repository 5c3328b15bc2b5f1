// SPDX-License-Identifier: BSD-3-Clause
// Intensity profiles along a line across an image, and what the eye makes
// of them. No Qt: the explorer's plots and its tests share these numbers.
#pragma once

#include "shadinglab/render/Image.h"

#include <vector>

namespace shadinglab::widgets
{

/// A line in an image, in normalized coordinates (0,0 top-left, 1,1
/// bottom-right): the same line falls on the same place in panels of
/// different sizes.
struct ProfileLine
{
  double x0 = 0.1, y0 = 0.5, x1 = 0.9, y1 = 0.5;
};

struct Profile
{
  std::vector<double> distance;  ///< pixels from the line's start
  std::vector<double> intensity; ///< linear luminance (Rec. 709 weights)
  std::vector<uint8_t> covered;  ///< 1 where a surface was drawn
  std::vector<double> pixelX, pixelY; ///< the pixel each sample reads
};

/// render::Luminance of one pixel of an Image's rgb.
double Luminance(const float* rgb);

/**
 * Samples the image along the line, one sample per pixel of length, each
 * the nearest pixel (no filtering: a staircase stays a staircase).
 */
Profile SampleProfile(const render::Image& image, const ProfileLine& line);

/// dI/dx per pixel: central differences (one-sided at the ends); 0 where a
/// neighbour is uncovered.
std::vector<double> Derivative(const Profile& profile);

/// Standard deviation, in pixels, of the centre-surround blur below: Mach
/// bands are ~5-10 minutes of arc wide (Ratliff 1965), and a pixel of a
/// laptop or class projector seen from a seat is about one minute of arc.
constexpr double kLateralInhibitionSigma = 6.0;
/// Gain of the inhibition term: with 2 the over- and undershoot at a slope
/// discontinuity of a few 1/255 per pixel reaches a few percent, visible at
/// plot scale, while plateaus and ramps are unchanged.
constexpr double kLateralInhibitionGain = 2.0;

/**
 * A model of lateral inhibition (Ratliff 1965, "Mach bands"): the perceived
 * profile p + g (p - G_sigma * p), i.e. the profile plus a
 * difference-of-Gaussians (centre impulse minus surround Gaussian) response.
 * Linear ramps and plateaus pass unchanged; at a slope discontinuity it
 * overshoots on the bright side and undershoots on the dark side, where the
 * eye sees the bright and dark Mach bands. Uncovered samples are skipped.
 */
std::vector<double> PerceivedProfile(const Profile& profile,
  double sigma = kLateralInhibitionSigma, double gain = kLateralInhibitionGain);

} // namespace shadinglab::widgets
