// SPDX-License-Identifier: BSD-3-Clause
// shadinglab accuracy: the time-against-error study (AccuracyStudy.h),
// written as a CSV, a Markdown table and a log-log plot.
#include "AccuracyStudy.h"
#include "Commands.h"

#include "shadinglab/cpu/ScanStudy.h"
#include "shadinglab/gl/GpuRenderer.h"
#ifdef SHADINGLAB_HAVE_QT
#include "AccuracyPlot.h"
#endif

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <algorithm>
#include <map>
#include <sstream>

namespace shadinglab::cli
{

namespace
{

const char* kAccuracyHelp =
  "usage: shadinglab accuracy --out DIR [--quick] [--size WxH] [--frames N] [--threads N]\n"
  "                           [--backend cpu|all]\n"
  "\n"
  "Renders analytic surfaces (sphere, torus, ellipsoid, metaball isosurface) tessellated\n"
  "from a few dozen to ~1M triangles in every shading mode and reflectance model, with\n"
  "uniform, area, angle, Max and OpenSubdiv limit normals, and compares each frame with\n"
  "the surface ray-cast with its exact normal. Writes DIR/accuracy.csv (one row per\n"
  "configuration; columns in docs/accuracy.md), DIR/accuracy.md (the Pareto front and\n"
  "every row) and DIR/accuracy.png (frame time against mean error, log-log).\n"
  "Then the lecture's incremental scan (forward differences, docs/model.md eq. 2.11)\n"
  "against exact interpolation over spans of 16 to 8192 pixels, in float and double:\n"
  "DIR/scan.csv, a section of DIR/accuracy.md and DIR/scan.png.\n"
  "Then three-sample RGB metals against their spectra (CIEDE2000 over incidence angle,\n"
  "docs/model.md section 7): DIR/spectral.csv, a section of DIR/accuracy.md, DIR/spectral.png.\n"
  "  --quick        a subset (sphere, torus; 3 and 2 levels) for CI: well under a minute\n"
  "  --size WxH     image size (default 320x240)\n"
  "  --frames N     frames timed per configuration, median reported (default 5)\n"
  "  --threads N    CPU renderer threads (default 0: all)\n"
  "  --backend B    cpu, or all (cpu + gpu when a display with OpenGL 3.2 answers; default)\n";

/// Frames per configuration: 1 is a measurement; beyond 51 the median
/// does not move and the study only gets slower.
constexpr int kMaxFrames = 51;
/// Study image sides: up to 1920x1080, the size of the README's speed tables.
constexpr int kMaxStudySide = 1920;

void WriteTable(const std::vector<StudyRow>& rows, const std::string& path)
{
  std::ofstream md(path);
  md << "# Time against error\n\n"
     << "Mean, p99 and max: |I - I_ref| of the largest channel, in 1/255 after display "
        "(clamp), over the pixels both images cover; frame: median, "
     << (rows.empty() ? 0 : rows.front().width) << "x" << (rows.empty() ? 0 : rows.front().height)
     << "; view 0 (azimuth 25, elevation 20; the CSV has every view).\n\n"
     << "## Pareto front (per shape and backend)\n\n";
  const char* header = "| shape | level | triangles | backend | mode | model | normals | "
                       "prepare ms | frame ms | mean | p99 | max |\n"
                       "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  auto line = [&](const StudyRow& r) {
    md << "| " << r.shape << " | " << r.level << " | " << r.triangles << " | " << r.backend
       << " | " << r.mode << " | " << r.model << " | " << r.normals << " | "
       << Fmt(r.prepareMs) << " | " << Fmt(r.frameMs) << " | " << Fmt(r.mean255) << " | "
       << Fmt(r.p99_255) << " | " << Fmt(r.max255) << " |\n";
  };
  md << header;
  for (const StudyRow& r : rows)
  {
    if (r.pareto && r.view == 0)
    {
      line(r);
    }
  }
  md << "\n## Every configuration\n\n" << header;
  for (const StudyRow& r : rows)
  {
    if (r.view == 0)
    {
      line(r);
    }
  }
}

/// The study's options from the command line, and its output directory
/// (made here).
StudyOptions StudyOptionsFromArguments(const Arguments& args, std::filesystem::path& dir)
{
  StudyOptions options;
  options.quick = args.Has("quick");
  const std::string size = args.Get("size", "320x240");
  char x = 0, rest = 0;
  if (std::sscanf(size.c_str(), "%d%c%d%c", &options.width, &x, &options.height, &rest) != 3 ||
    x != 'x' || options.width < 16 || options.height < 16 || options.width > kMaxStudySide ||
    options.height > kMaxStudySide)
  {
    throw UsageError("--size must be WxH with sides in [16, 1920] (got '" + size + "')");
  }
  options.frames = args.GetInt("frames", 5);
  if (options.frames < 1 || options.frames > kMaxFrames)
  {
    throw UsageError("--frames must be in [1, 51]");
  }
  options.threads = args.GetInt("threads", 0);
  if (options.threads < 0 || options.threads > 256)
  {
    throw UsageError("--threads must be in [0, 256]");
  }
  const std::string backend = args.Get("backend", "all");
  if (backend != "cpu" && backend != "all")
  {
    throw UsageError("--backend must be cpu or all (got '" + backend + "')");
  }
  dir = args.Get("out");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
  {
    throw UsageError("cannot create directory " + dir.string());
  }
  return options;
}

/// Writes auto.csv (one row per held-out case) and returns the summary:
/// how often the choice met E, and at what cost against the cheapest mode
/// that did.
std::string WriteAutoCases(const std::vector<AutoCase>& cases, const std::filesystem::path& dir)
{
  std::ofstream autoCsv(dir / "auto.csv");
  autoCsv << "mesh,material,max_error,chosen,predicted,chosen_error,chosen_ms,cheapest,"
             "cheapest_ms,met,flat_error,gouraud_error,phong_error,flat_ms,gouraud_ms,phong_ms,"
             "spread,sharpness,peak,triangles,front_pixels,triangle_pixels,diff_flat,diff_gouraud,"
             "diff_normals,"
             "predicted_flat,predicted_gouraud,predicted_phong,predicted_flat_ms,"
             "predicted_gouraud_ms,predicted_phong_ms\n";
  int feasible = 0, met = 0, withinCost = 0;
  std::vector<double> ratios;
  for (const AutoCase& c : cases)
  {
    autoCsv << c.mesh << ',' << c.material << ',' << c.maxError << ',' << c.chosen << ','
            << c.predicted << ',' << c.chosenError << ',' << c.chosenMs << ',' << c.cheapest << ','
            << c.cheapestMs << ',' << (c.met ? 1 : 0);
    for (double e : c.modeError)
    {
      autoCsv << ',' << e;
    }
    for (double ms : c.modeMs)
    {
      autoCsv << ',' << ms;
    }
    autoCsv << ',' << c.choice.view.normalSpread << ',' << c.choice.sharpness << ','
            << c.choice.peak << ',' << c.choice.view.triangles << ',' << c.choice.view.frontPixels
            << ',' << c.choice.view.trianglePixels << ',' << c.choice.difference.flat << ','
            << c.choice.difference.gouraud << ',' << c.choice.difference.normals;
    for (double e : c.choice.modeError)
    {
      autoCsv << ',' << e;
    }
    for (double ms : c.choice.modeMs)
    {
      autoCsv << ',' << ms;
    }
    autoCsv << '\n';
    if (c.cheapest.empty())
    {
      continue; // no mode meets E on this mesh: nothing to choose
    }
    ++feasible;
    met += c.met;
    const double ratio = c.chosenMs / c.cheapestMs;
    ratios.push_back(ratio);
    withinCost += c.met && ratio <= 1.2;
  }
  std::sort(ratios.begin(), ratios.end());
  std::ostringstream summary;
  summary << "auto mode on " << cases.size() << " held-out cases (" << feasible
          << " where some mode meets E): meets E in " << Fmt(100.0 * met / std::max(1, feasible))
          << "%; meets E at <= 1.2x the cheapest mode meeting it in "
          << Fmt(100.0 * withinCost / std::max(1, feasible)) << "%; cost ratio median "
          << Fmt(ratios.empty() ? 0 : ratios[ratios.size() / 2]) << ", max "
          << Fmt(ratios.empty() ? 0 : ratios.back());
  return summary.str();
}

/// The time-against-error plot of the first view (accuracy.png).
void WritePlot(const std::vector<StudyRow>& rows, const StudyOptions& options,
  const std::filesystem::path& dir)
{
#ifdef SHADINGLAB_HAVE_QT
  std::vector<std::string> groups;
  std::vector<std::vector<widgets::AccuracyPoint>> points;
  std::map<std::string, size_t> index;
  for (const StudyRow& r : rows)
  {
    if (r.view != 0)
    {
      continue; // the plot shows the first view; the CSV has every view
    }
    const std::string group = r.shape + " (" + r.backend + ")";
    if (!index.count(group))
    {
      index[group] = groups.size();
      groups.push_back(group);
      points.emplace_back();
    }
    points[index[group]].push_back({ r.mode, r.frameMs, r.mean255, r.pareto });
  }
  const std::string title = "Frame time against mean error, " + std::to_string(options.width) +
    "x" + std::to_string(options.height) + (options.quick ? " (quick)" : "");
  const std::string error =
    widgets::WriteAccuracyPlot(groups, points, title, (dir / "accuracy.png").string());
  if (!error.empty())
  {
    throw UsageError(error);
  }
#else
  (void)rows;
  (void)options;
  (void)dir;
  std::cerr << "shadinglab accuracy: notice: built without Qt Charts; no plot\n";
#endif
}

/// The incremental scan's accumulated error (ScanStudy.h): scan.csv, a
/// section of accuracy.md, scan.png; returns the summary line.
std::string WriteScanStudy(const std::filesystem::path& dir)
{
  const cpu::ScanStudyOptions options;
  const std::vector<cpu::ScanErrorRow> rows = cpu::IncrementalScanErrors(options);
  std::ofstream csv(dir / "scan.csv");
  csv << "quantity,precision,unit,length,mean,worst,last_mean,bound,bound_ratio\n";
  std::ofstream md(dir / "accuracy.md", std::ios::app);
  md << "\n## Incremental scan: forward differences against exact interpolation\n\n"
     << options.spansPerWidth << " random spans per width; gouraud steps the intensity (ends in "
     << "[0, 1]), phong the normal (ends within 45 degrees of the view axis) lit as (N.H)^"
     << options.shininess << " with H between them, errors in 1/255; edge steps the crossing x "
     << "down as many rows in a " << options.imageWidth << "-pixel-wide image, errors in pixels. "
     << "Bound: docs/model.md eq. 2.12 (phong eq. 2.13), the largest over the spans.\n\n"
     << "| quantity | precision | length (px) | unit | mean | worst | mean at the end | bound |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  std::map<std::string, int> firstVisible;
  for (const cpu::ScanErrorRow& r : rows)
  {
    csv << r.quantity << ',' << r.precision << ',' << r.unit << ',' << r.width << ',' << r.mean
        << ',' << r.worst << ',' << r.last << ',' << r.bound << ',' << r.boundRatio << '\n';
    md << "| " << r.quantity << " | " << r.precision << " | " << r.width << " | " << r.unit
       << " | " << Fmt(r.mean) << " | " << Fmt(r.worst) << " | " << Fmt(r.last) << " | "
       << Fmt(r.bound) << " |\n";
    const std::string key = r.quantity + " " + r.precision;
    // Visible: a display step (1/255), or half a pixel of an edge (a
    // pixel centre changes sides).
    if (r.worst >= (r.unit == "px" ? 0.5 : 1.0) && !firstVisible.count(key))
    {
      firstVisible[key] = r.width;
    }
  }
  std::ostringstream summary;
  summary << "incremental scan, worst error over " << options.maxWidth << " steps:";
  for (const cpu::ScanErrorRow& r : rows)
  {
    if (r.width == options.maxWidth)
    {
      summary << " " << r.quantity << "/" << r.precision << " " << Fmt(r.worst) << " "
              << r.unit;
    }
  }
  summary << "; first length with a visible error (1/255, or 0.5 px for an edge):";
  for (const char* key : { "gouraud float", "phong float", "edge float" })
  {
    summary << " " << key << " "
            << (firstVisible.count(key) ? std::to_string(firstVisible[key]) + " px"
                                        : "none up to " + std::to_string(options.maxWidth));
  }
  md << "\n" << summary.str() << ".\n";
#ifdef SHADINGLAB_HAVE_QT
  std::vector<widgets::LogLogPanel> panels(3);
  const char* quantities[] = { "gouraud", "phong", "edge" };
  panels[0].title = "Gouraud span: intensity stepped";
  panels[1].title = "Phong span: normal stepped, (N.H)^" + Fmt(options.shininess);
  panels[2].title = "Edge: crossing x stepped, " + Fmt(options.imageWidth, 6) + " px wide image";
  for (int q = 0; q < 3; ++q)
  {
    panels[q].xTitle = q == 2 ? "edge length (rows, log)" : "span length (pixels, log)";
    panels[q].yTitle = q == 2 ? "x error (pixels, log)" : "error (1/255, log)";
    panels[q].referenceY = q == 2 ? 0.5 : 1.0;
    panels[q].referenceName = q == 2 ? "half a pixel: a pixel centre changes sides"
                                     : "1/255: one display step";
    int color = 0;
    for (const char* precision : { "float", "double" })
    {
      widgets::LogLogLine worst{ std::string(precision) + " worst", {}, {}, color, false };
      widgets::LogLogLine mean{ std::string(precision) + " mean", {}, {}, color + 1, false };
      widgets::LogLogLine bound{ std::string(precision) + " bound (eq. 2." +
          (q == 1 ? "13" : "12") + ")", {}, {}, color, true };
      for (const cpu::ScanErrorRow& r : rows)
      {
        if (r.quantity == quantities[q] && r.precision == precision)
        {
          worst.x.push_back(r.width);
          worst.y.push_back(r.worst);
          mean.x.push_back(r.width);
          mean.y.push_back(r.mean);
          bound.x.push_back(r.width);
          bound.y.push_back(r.bound);
        }
      }
      panels[q].lines.push_back(worst);
      panels[q].lines.push_back(mean);
      panels[q].lines.push_back(bound);
      color += 2;
    }
  }
  const std::string error = widgets::WriteLogLogPlot(panels,
    "Incremental scan (forward differences): accumulated error against span length",
    (dir / "scan.png").string());
  if (!error.empty())
  {
    throw UsageError(error);
  }
#endif
  return summary.str();
}

} // namespace

int RunAccuracy(int argc, char** argv)
{
  Arguments args(argc, argv, { "out", "size", "frames", "threads", "backend" }, { "quick", "help" });
  if (args.Has("help"))
  {
    std::cout << kAccuracyHelp;
    return 0;
  }
  if (!args.Positionals().empty())
  {
    throw UsageError("accuracy takes no INPUT (it makes its own meshes)");
  }
  if (!args.Has("out") || args.Get("out").empty())
  {
    throw UsageError("--out DIR is required");
  }
  std::filesystem::path dir;
  StudyOptions options = StudyOptionsFromArguments(args, dir);
  const std::string backend = args.Get("backend", "all");
  std::string why;
  options.gpu = backend == "all" && gl::GpuAvailable(why);
  if (backend == "all" && !options.gpu)
  {
    std::cerr << "shadinglab accuracy: notice: CPU only (" << why << ")\n";
  }
  std::vector<StudyRow> rows = RunStudy(options, [](const StudyRow& r) {
    std::cerr << r.shape << " " << r.level << " (" << r.triangles << " tri) " << r.backend << " "
              << r.mode << "/" << r.model << "/" << r.normals << ": " << Fmt(r.frameMs)
              << " ms, mean " << Fmt(r.mean255) << "/255\n";
  });
  std::ofstream csv(dir / "accuracy.csv");
  csv << StudyCsvHeader() << "\n";
  for (const StudyRow& r : rows)
  {
    csv << StudyCsvRow(r) << "\n";
  }
  if (!csv)
  {
    throw UsageError("cannot write " + (dir / "accuracy.csv").string());
  }
  WriteTable(rows, (dir / "accuracy.md").string());
  // The auto mode on held-out meshes: the two figures.
  const std::vector<AutoCase> cases = ValidateAutoMode(options, [](const AutoCase& c) {
    std::cerr << "auto: " << c.mesh << ", " << c.material << ", E " << c.maxError << ": "
              << c.chosen << " (" << Fmt(c.chosenError) << "/255, " << Fmt(c.chosenMs)
              << " ms); cheapest meeting E: " << (c.cheapest.empty() ? "none" : c.cheapest)
              << "\n";
  });
  const std::string summary = WriteAutoCases(cases, dir);
  std::ofstream(dir / "accuracy.md", std::ios::app) << "\n## Auto mode, held out\n\n"
                                                    << summary << ".\n";
  std::cout << summary << "\n";
  WritePlot(rows, options, dir);
  std::cout << WriteScanStudy(dir) << "\n";
  std::cout << WriteSpectralStudy(dir) << "\n";
  std::cout << "wrote " << rows.size() << " configurations to " << dir.string() << "\n";
  return 0;
}

} // namespace shadinglab::cli
