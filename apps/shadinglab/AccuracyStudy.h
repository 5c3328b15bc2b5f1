// SPDX-License-Identifier: BSD-3-Clause
// The time-against-error study behind `shadinglab accuracy`: analytic
// surfaces tessellated at several levels, rendered in every shading mode and
// reflectance model on each backend, with several vertex normals, against
// the surface ray-cast with its exact normal (plugin/reference).
#pragma once

#include "shadinglab/render/AutoMode.h"
#include "shadinglab/render/Renderer.h"

#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace shadinglab::cli
{

struct StudyOptions
{
  bool quick = false;        ///< a subset that runs in well under a minute
  int width = 320, height = 240;
  int frames = 5;            ///< frames timed per configuration (median)
  int threads = 0;           ///< CPU renderer threads (0: all)
  bool gpu = false;          ///< also the GPU backend (a display answered)
};

/// One configuration and what it measured (one CSV row).
struct StudyRow
{
  std::string shape;
  int level = 0;             ///< tessellation parameter (slices, or grid size)
  long long triangles = 0;
  std::string backend, mode, model, normals;
  int width = 0, height = 0, threads = 0;
  double prepareMs = 0;      ///< normals or subdivision (median of 3)
  double frameMs = 0;        ///< one frame, median of `frames`, steady state
  /// |I - I_ref| per pixel (largest channel) over pixels both cover:
  double meanLinear = 0, rmseLinear = 0, p99Linear = 0, maxLinear = 0; ///< linear intensity
  double mean255 = 0, rmse255 = 0, p99_255 = 0, max255 = 0;            ///< 8-bit display values
  double coverageMismatch = 0; ///< fraction of covered pixels covered by one image only
  /// The auto mode's predictors (render/AutoMode.h), known before rendering:
  double normalSpreadDeg = 0, trianglePixels = 0, sharpness = 0, peak = 0, frontPixels = 0;
  /// The auto mode's estimates of flat's and Gouraud's distance from Phong
  /// (1/255, render::EstimateModeDifferences).
  double diffFlat = 0, diffGouraud = 0, diffNormals = 0;
  int view = 0; ///< 0: azimuth 25, elevation 20 (the plot's); 1, 2: the fit's other views
  bool pareto = false;         ///< on the time-error Pareto front (mean 1/255)
};

/// The CSV header, in StudyRow's order; documented in docs/accuracy.md.
const char* StudyCsvHeader();
std::string StudyCsvRow(const StudyRow& row);

/// Runs the study; `progress` gets one line per configuration.
std::vector<StudyRow> RunStudy(
  const StudyOptions& options, const std::function<void(const StudyRow&)>& progress);

/// One held-out case of the auto mode: a mesh, material and view not in
/// the study, and an error budget.
struct AutoCase
{
  std::string mesh, material;
  double maxError = 0;        ///< E (1/255)
  std::string chosen;         ///< auto's mode
  double predicted = 0;       ///< its predicted (conservative) error
  double chosenError = 0, chosenMs = 0;
  std::string cheapest;       ///< the cheapest mode that met E ("" if none)
  double cheapestMs = 0;
  bool met = false;           ///< chosenError <= E
  /// Every mode as measured (flat, Gouraud, Phong): mean error (1/255) and
  /// median frame time (ms), and the predictors the choice read.
  double modeError[3] = { 0, 0, 0 }, modeMs[3] = { 0, 0, 0 };
  render::ModeChoice choice;
};

/// Renders held-out meshes (a thin torus, a flattened ellipsoid, icospheres,
/// metaballs at other sizes; another view; other materials) in flat,
/// Gouraud and Phong, and asks ChooseMode for each budget E.
std::vector<AutoCase> ValidateAutoMode(
  const StudyOptions& options, const std::function<void(const AutoCase&)>& progress);

/// Marks the rows no other row of the same shape and backend beats in both
/// frame time and mean error (1/255).
void MarkParetoFront(std::vector<StudyRow>& rows);

/// A number with `digits` significant digits, for tables.
inline std::string Fmt(double v, int digits = 3)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

/// Three-sample RGB metals against their spectra (SpectralStudy.cpp):
/// spectral.csv, a section of accuracy.md, spectral.png (with Qt); returns
/// the summary line.
std::string WriteSpectralStudy(const std::filesystem::path& dir);

} // namespace shadinglab::cli
