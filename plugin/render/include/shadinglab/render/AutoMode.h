// SPDX-License-Identifier: BSD-3-Clause
// `--mode auto --max-error E`: the cheapest shading mode predicted to keep
// the mean error under E (1/255), from what is known before rendering: how
// far apart the vertex normals of the visible triangles are, how sharp the
// material's lobe is, how far flat and Gouraud land from Phong under the
// scene's lights, and how far Phong moves under other vertex normals (a
// quadrature over the triangles, eq. 4.4). The prediction (docs/model.md
// eq. 4.1 and 4.5) is fitted to `shadinglab accuracy`.
#pragma once

#include "shadinglab/render/Options.h"
#include "shadinglab/render/Scene.h"

#include <string>
#include <vector>

namespace shadinglab::render
{

/// What the prediction reads of a mesh in a view (at most 16,384 triangles,
/// in runs spread over the mesh; counts scaled back to the whole).
struct ViewPredictors
{
  /// Screen-area-weighted mean, over front-facing triangles in view, of the
  /// largest angle between two of a triangle's vertex normals (radians).
  double normalSpread = 0;
  /// Mean screen area of those triangles (pixels).
  double trianglePixels = 0;
  long long visibleTriangles = 0;
  /// Screen area of the triangles facing the viewer (pixels): about the
  /// pixels a per-pixel mode shades.
  double frontPixels = 0;
  long long triangles = 0; ///< all triangles (what per-vertex work scales with)
};

/// `normals`: 3 per vertex (the mesh's, or what the renderer would compute).
ViewPredictors PredictorsOf(const Mesh& mesh, const std::vector<float>& normals,
  const Camera& camera, int width, int height);

/// How far flat and Gouraud would land from Phong (eq. 4.4), and Phong from
/// itself with other vertex normals: the screen-area-weighted mean, over
/// the front-facing triangles in view (the back-facing ones when no
/// triangle faces the viewer), of the largest channel difference (1/255,
/// after the clamp to [0, 1]) between the two colours, by the midpoint rule
/// on sub-triangles of about 4 pixels. At most 8,192 triangles (in runs
/// spread over the mesh) and 16,384 points are evaluated.
struct ModeDifferences
{
  double flat = 0;
  double gouraud = 0;
  /// How far Phong moves, at most, when its normals are replaced by the
  /// area-weighted or the Max-weighted ones (recomputed from the mesh): the
  /// uncertainty of the vertex normals themselves, which Phong's error
  /// carries on top of its interpolation's (eq. 4.1).
  double normals = 0;
  long long sampledTriangles = 0;
};
ModeDifferences EstimateModeDifferences(const Mesh& mesh, const std::vector<float>& normals,
  const Camera& camera, const Lighting<double>& lighting, const Material<double>& material,
  int width, int height);

/// The lobe's sharpness as a Blinn-Phong exponent: n for (Blinn-)Phong,
/// 2 / m^2 - 2 for a Beckmann lobe (the width-matched exponent; the mixture's
/// sharpest lobe), 0 without a specular term.
double LobeSharpness(const Material<double>& material);

/// The BRDF's value (luminance, 1/sr) for light and view along the normal:
/// how bright the material's highlight peak is (diffuse included).
double LobePeak(const Material<double>& material);

struct ModeChoice
{
  ShadingMode mode = ShadingMode::Phong;
  double predicted = 0;    ///< predicted mean error of the choice (1/255)
  double predictedMs = 0;  ///< its predicted CPU frame time
  ViewPredictors view;
  double sharpness = 0;
  double peak = 0;
  ModeDifferences difference; ///< under the scene's lights
  /// Every candidate's predicted error (with the margin) and time, in the
  /// order flat, Gouraud, Phong.
  double modeError[3] = { 0, 0, 0 };
  double modeMs[3] = { 0, 0, 0 };
  std::string why;         ///< one line for --stats
};

/**
 * Predicted mean error (1/255) of `mode` for one light of strength 1, with
 * a margin (a percentile of the fit's residuals) when `conservative`:
 * Phong (eq. 4.1)
 *   E_P = exp(a_P) (spread)^b_P (1 + sharpness)^c_P (peak)^d_P,
 * flat and Gouraud (eq. 4.5) their distance D_M from Phong (eq. 4.4, under
 * that light) on top of Phong's own error:
 *   E_M = exp(a_M) (D_M + E_P)^b_M (1 + sharpness)^c_M (spread)^d_M.
 */
double PredictError(ShadingMode mode, const ViewPredictors& view,
  const ModeDifferences& difference, double sharpness, double peak, bool conservative);

/// The lights' strength relative to the study's one light of intensity 1:
/// the sum over lights of the largest channel times dw / pi. Errors scale
/// with it (the model is linear in I_L).
double LightScale(const Lighting<double>& lighting);

/// Predicted CPU frame time (ms) of `mode` (eq. 4.2): a + b T + c A, T the
/// triangles (thousands), A the front-facing screen area (thousands of
/// pixels), per mode and per model class (not Cook-Torrance; Cook-Torrance
/// dielectric; Cook-Torrance conductor).
double PredictCost(ShadingMode mode, const ViewPredictors& view, const Material<double>& material);

/// Of flat, Gouraud and Phong, the one of least predicted cost whose
/// error prediction (with the margin), times LightScale, is <= maxError;
/// Phong (the most accurate) when none is.
ModeChoice ChooseMode(const Mesh& mesh, const std::vector<float>& normals, const Camera& camera,
  const Lighting<double>& lighting, const Material<double>& material, int width, int height,
  double maxError);

} // namespace shadinglab::render
