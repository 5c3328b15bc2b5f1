// SPDX-License-Identifier: BSD-3-Clause
// shadinglab accuracy: the time-against-error study (AccuracyStudy.h),
// written as a CSV, a Markdown table and a log-log plot.
#include "AccuracyStudy.h"
#include "Commands.h"

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

std::string Fmt(double v, int digits = 3)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

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
  std::cout << "wrote " << rows.size() << " configurations to " << dir.string() << "\n";
  return 0;
}

} // namespace shadinglab::cli
