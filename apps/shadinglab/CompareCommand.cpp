// SPDX-License-Identifier: BSD-3-Clause
// shadinglab compare: one mesh in several shading modes (and reflectance
// models), side by side in one labelled PNG.
#include "Commands.h"
#include "RenderOutput.h"
#include "SceneArguments.h"

#include "shadinglab/model/Materials.h"

#include <iostream>
#include <sstream>

namespace shadinglab::cli
{

namespace
{

const char* kCompareHelp =
  "usage: shadinglab compare INPUT [--modes M,M,..] [--size WxH] [--out OUT.png] [options]\n"
  "\n"
  "Renders INPUT once per panel with the same camera, lights and material, side by side\n"
  "in one labelled PNG. A panel is MODE (flat, gouraud, phong, fast-phong) with the\n"
  "material's model, or MODE/MODEL (e.g. gouraud/cook-torrance: Cook-Torrance evaluated\n"
  "per vertex); cook-torrance alone is phong/cook-torrance.\n"
  "Default: flat,gouraud,phong,fast-phong,cook-torrance.\n"
  "--backend cpu (default for compare) | gpu | auto.\n"
  "--size is the size of one panel (default 400x300). Other options as 'render'.\n"
  "\n";

/// One panel of the strip: where (mode) and what (the material's model).
struct Panel
{
  std::string name;  ///< as given in --modes
  std::string title; ///< panel label
  render::ShadingMode mode = render::ShadingMode::Phong;
  Material<double> material;
};

/// Parses --modes: MODE, MODE/MODEL, or cook-torrance (= phong/cook-torrance).
std::vector<Panel> ParsePanels(const std::string& list, const Material<double>& base)
{
  std::vector<Panel> panels;
  std::stringstream ss(list);
  std::string name;
  while (std::getline(ss, name, ','))
  {
    Panel panel;
    panel.name = name;
    panel.material = base;
    std::string modeName = name, modelName;
    const auto slash = name.find('/');
    if (slash != std::string::npos)
    {
      modeName = name.substr(0, slash);
      modelName = name.substr(slash + 1);
    }
    else if (name == "cook-torrance")
    {
      modeName = "phong";
      modelName = "cook-torrance";
    }
    if (!render::ParseShadingMode(modeName, panel.mode))
    {
      throw UsageError("--modes: unknown mode '" + modeName + "' (expected " +
        render::ShadingModeChoices() + ")");
    }
    if (!modelName.empty() && !ParseReflectanceModel(modelName, panel.material.model))
    {
      throw UsageError("--modes: unknown model '" + modelName +
        "' (expected lambert, phong, blinn-phong or cook-torrance)");
    }
    const std::string problem = ValidateMaterial(panel.material);
    if (!problem.empty())
    {
      throw UsageError("--modes " + name + ": " + problem);
    }
    panel.title = std::string(render::ShadingModeName(panel.mode)) + " / " +
      ReflectanceModelName(panel.material.model);
    panels.push_back(panel);
  }
  if (panels.empty() || panels.size() > 8)
  {
    throw UsageError("--modes takes 1 to 8 panels");
  }
  return panels;
}

} // namespace

int RunCompare(int argc, char** argv)
{
  // Default panel size for a comparison strip.
  bool hasSize = false, hasBackend = false;
  for (int i = 0; i < argc; ++i)
  {
    hasSize |= std::string(argv[i]).rfind("--size", 0) == 0;
    hasBackend |= std::string(argv[i]).rfind("--backend", 0) == 0;
  }
  std::vector<std::string> arguments(argv, argv + argc);
  if (!hasSize)
  {
    arguments.push_back("--size");
    arguments.push_back("400x300");
  }
  if (!hasBackend)
  {
    // The CPU renderer is the reference: comparisons default to it.
    arguments.push_back("--backend");
    arguments.push_back("cpu");
  }
  std::vector<char*> raw;
  for (auto& a : arguments)
  {
    raw.push_back(a.data());
  }
  const auto request =
    SceneFromArguments(static_cast<int>(raw.size()), raw.data(), kCompareHelp, { "modes" });
  if (request->helpShown)
  {
    return 0;
  }
  const std::vector<Panel> panels =
    ParsePanels(request->args.Get("modes", "flat,gouraud,phong,fast-phong,cook-torrance"),
      request->scene.material);
  const int W = request->settings.render.width, H = request->settings.render.height;
  constexpr int kLabelBar = 26; // pixels above each panel for its name
  constexpr int kGap = 4;       // pixels between panels
  const int canvasW = static_cast<int>(panels.size()) * (W + kGap) - kGap;
  const int canvasH = H + kLabelBar;
  std::vector<uint8_t> canvas(static_cast<size_t>(canvasW) * canvasH * 3, 24);
  std::string autoNotice;
  const auto renderer = MakeRenderer(*request, "", "compare", autoNotice);
  const char* backendName = render::BackendName(renderer->GetBackend());
  for (size_t m = 0; m < panels.size(); ++m)
  {
    render::RenderOptions options = request->settings.render;
    options.mode = panels[m].mode;
    options.fastPhongFallback = false; // a comparison shows each mode as such
    render::Scene scene = request->scene;
    scene.material = panels[m].material;
    const render::Image& image = RenderOrExplain(
      *renderer, scene, options, nullptr, " (panel '" + panels[m].name + "'; leave it out with --modes)");
    const auto rgb8 = image.ToRGB8(request->settings.render.display);
    const int x0 = static_cast<int>(m) * (W + kGap);
    for (int y = 0; y < H; ++y)
    {
      std::copy(rgb8.begin() + static_cast<size_t>(y) * W * 3,
        rgb8.begin() + static_cast<size_t>(y + 1) * W * 3,
        canvas.begin() + (static_cast<size_t>(y + kLabelBar) * canvasW + x0) * 3);
    }
    DrawLabel(canvas, canvasW, canvasH, x0 + 8, 4, panels[m].title + " (" + backendName + ")");
  }
  WritePng(canvasW, canvasH, canvas, request->args.Get("out", "compare.png"));
  std::cerr << autoNotice;
  if (!request->notices.empty())
  {
    std::cerr << "shadinglab compare: notice: '" << request->input << "': " << request->notices << "\n";
  }
  return 0;
}

} // namespace shadinglab::cli
