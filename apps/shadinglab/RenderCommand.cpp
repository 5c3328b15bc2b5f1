// SPDX-License-Identifier: BSD-3-Clause
// shadinglab render: one image of a mesh in one shading mode.
#include "Commands.h"
#include "PolarizationOutput.h"
#include "RenderOutput.h"
#include "SceneArguments.h"

#include "shadinglab/cpu/SoftwareRenderer.h"
#include "shadinglab/model/Materials.h"
#include "shadinglab/render/Fidelity.h"

#include <cstdio>
#include <iostream>

namespace shadinglab::cli
{

namespace
{

const char* kRenderOptionsHelp =
  "  --size WxH          image size (default 1024x768)\n"
  "  --out FILE.png      output image (default out.png)\n"
  "  --stats             print one JSON line of timings and counts\n"
  "  --time T            a time series (.pvd, Exodus II): the last step at or before T\n"
  "  --time-step N       ... or step N (from 0); the first step without either\n"
  "  --output KIND       intensity (default: the picture), or what a polarization camera\n"
  "                      measures through analysers at 0/45/90/135 degrees (docs/model.md\n"
  "                      eq. 8.5; CPU renderer): dolp or aop (false colour PNG with a legend),\n"
  "                      s0, s1, s2 or s3 (a .vti of that Stokes component per channel),\n"
  "                      stokes (a .vti of S0..S3 per channel and DoLP, AoP)\n"
  "With --color-by the PNG carries a colour legend at its right edge.\n";

std::string RenderHelp()
{
  return "usage: shadinglab render INPUT [--backend auto|cpu|gpu] [--mode MODE] [--size WxH]\n"
         "                         [--out OUT.png] [options]\n"
         "\n"
         "INPUT: " + ReadableExtensionsText() + "\n" + kRenderOptionsHelp;
}

/// Covered pixels with a channel at 255: where the display transform
/// clipped (or the surface is exactly white).
long long CountClipped(const render::Image& image, const std::vector<uint8_t>& rgb8)
{
  long long n = 0;
  for (size_t i = 0; i < image.covered.size(); ++i)
  {
    n += image.covered[i] && (rgb8[3 * i] == 255 || rgb8[3 * i + 1] == 255 || rgb8[3 * i + 2] == 255);
  }
  return n;
}

} // namespace

int RunRender(int argc, char** argv)
{
  const Stopwatch total;
  const auto request = SceneFromArguments(argc, argv, RenderHelp(), { "output" });
  if (request->helpShown)
  {
    return 0;
  }
  const Arguments& args = request->args;
  const render::RenderOptions& options = request->settings.render;
  const std::string output = args.Get("output", "intensity");
  const bool polarization = IsPolarizationOutput(output);
  if (polarization && options.polarizer >= 0)
  {
    throw UsageError("--output " + output + " turns its own analysers: drop --polarizer");
  }
  std::string autoNotice;
  const auto renderer = MakeRenderer(*request,
    polarization ? "--output " + output + " is measured on the CPU renderer's linear frames" : "",
    "render", autoNotice);
  if (polarization)
  {
    const std::string path = args.Get("out", output == "dolp" || output == "aop" ? "out.png" : output + ".vti");
    const double meanDolp =
      WritePolarizationOutput(*renderer, request->scene, options, output, path);
    if (args.Has("stats"))
    {
      std::printf("{\"output\": \"%s\", \"mean_dolp\": %.6g}\n", output.c_str(), meanDolp);
    }
    return 0;
  }
  render::RenderStats stats;
  const render::Image& image = RenderOrExplain(*renderer, request->scene, options, &stats, "");
  const std::string out = args.Get("out", "out.png");
  const Stopwatch writing;
  std::vector<uint8_t> rgb8 = image.ToRGB8(options.display);
  const long long clipped = args.Has("stats") ? CountClipped(image, rgb8) : 0; // --stats only
  if (request->scene.colorMap)
  {
    DrawColorLegend(rgb8, image.width, image.height, *request->scene.colorMap, request->colorTitle);
  }
  WritePng(image.width, image.height, rgb8, out);
  const double writeMs = writing.Milliseconds();
  // Notices come after success, so that an error stays one line.
  std::cerr << autoNotice;
  if (!request->notices.empty())
  {
    std::cerr << "shadinglab render: notice: '" << request->input << "': " << request->notices << "\n";
  }

  if (stats.pixelsCovered == 0)
  {
    std::cerr << "shadinglab render: notice: the picture is empty: no polygon covers a pixel ("
              << static_cast<long long>(stats.culled) << " culled, "
              << static_cast<long long>(stats.clipped) << " clipped by the view, "
              << static_cast<long long>(stats.degenerate)
              << " edge-on or degenerate); try another --azimuth/--elevation or --zoom\n";
  }
  if (stats.fastPhongAsPhong)
  {
    std::cerr << "shadinglab render: notice: fast-phong drew exact Phong: the triangles average "
              << static_cast<long long>(stats.pixelsPerTriangle + 0.5)
              << " pixels, too few for its quadratics to pay (--fast-phong-as-is keeps them)\n";
  }
  std::string fidelity;
  if (args.Has("stats") && request->scene.colorMap)
  {
    // docs/model.md eq. 9.3, on the CPU renderer's linear frames.
    cpu::SoftwareRenderer reference;
    const render::FidelityResult f =
      render::MeasureColorFidelity(reference, request->scene, options);
    char text[160];
    std::snprintf(text, sizeof text,
      ",\"color_fidelity\":{\"covered\":%lld,\"unfaithful\":%lld,\"fraction\":%.6f}",
      static_cast<long long>(f.covered), static_cast<long long>(f.unfaithful), f.Fraction());
    fidelity = text;
  }
  if (args.Has("stats"))
  {
    std::printf("{\"backend\":\"%s\",\"mode\":\"%s\",\"model\":\"%s\",\"width\":%d,\"height\":%d,\"ssaa\":%d,"
                "\"milliseconds\":%.3f,\"polygons\":%lld,\"triangles\":%lld,\"rasterized\":%lld,"
                "\"clipped\":%lld,\"binned\":%lld,\"degenerate\":%lld,\"vertices_drawn\":%lld,\"skipped\":%lld,\"culled\":%lld,"
                "\"hidden_back_faces_culled\":%s,\"pixels_covered\":%lld,"
                "\"pixels_at_255\":%lld,\"pixels_shaded\":%lld,\"overdraw\":%.3f,\"fast_phong_exact\":%lld,"
                "\"fast_phong_as_phong\":%s,\"threads\":%d,"
                "\"shader_builds\":%d,\"normals_computed\":%s,\"read_ms\":%.3f,"
                "\"prepare_ms\":%.3f,\"render_ms\":%.3f,\"write_ms\":%.3f,\"total_ms\":%.3f,"
                "\"peak_rss_read_mb\":%.1f,\"peak_rss_prepare_mb\":%.1f,\"peak_rss_mb\":%.1f%s%s}\n",
      render::BackendName(renderer->GetBackend()), render::ShadingModeName(stats.drawnMode),
      ReflectanceModelName(request->scene.material.model), options.width, options.height, options.ssaa,
      stats.milliseconds, static_cast<long long>(stats.polygons),
      static_cast<long long>(stats.triangles), static_cast<long long>(stats.rasterized),
      static_cast<long long>(stats.clipped), static_cast<long long>(stats.binned),
      static_cast<long long>(stats.degenerate), static_cast<long long>(stats.verticesDrawn),
      static_cast<long long>(stats.skipped), static_cast<long long>(stats.culled),
      stats.hiddenBackFacesCulled ? "true" : "false", static_cast<long long>(stats.pixelsCovered),
      clipped,
      static_cast<long long>(stats.pixelsShaded),
      // Shading evaluations per covered pixel (0 when nothing is covered).
      stats.pixelsCovered ? double(stats.pixelsShaded) / stats.pixelsCovered : 0.0,
      static_cast<long long>(stats.fastPhongExact), stats.fastPhongAsPhong ? "true" : "false",
      stats.threads, stats.shaderBuilds,
      stats.normalsComputed || request->normalsMade ? "true" : "false", request->readMs,
      request->prepareMs,
      stats.milliseconds, writeMs, total.Milliseconds(), request->readPeakMb, request->preparePeakMb,
      PeakRssMb(), stats.autoChoice.empty() ? "" : (",\"auto\":\"" + stats.autoChoice + "\"").c_str(),
      fidelity.c_str());
  }
  return 0;
}

} // namespace shadinglab::cli
