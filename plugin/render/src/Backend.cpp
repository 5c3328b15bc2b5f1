// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/render/Backend.h"

#include "shadinglab/render/Settings.h"

#include <algorithm>
#include <cctype>

namespace shadinglab::render
{

const char* BackendName(Backend backend)
{
  switch (backend)
  {
    case Backend::GPU:
      return "gpu";
    case Backend::CPU:
      return "cpu";
    case Backend::Auto:
      break;
  }
  return "auto";
}

std::string ParseBackend(const std::string& text, Backend& backend)
{
  Settings settings;
  const std::string problem = ApplySettingText(settings, "backend", text, "--");
  if (problem.empty())
  {
    backend = settings.backend;
  }
  return problem;
}

bool IsSoftwareRasterizer(const std::string& glRenderer)
{
  std::string lower = glRenderer;
  std::transform(lower.begin(), lower.end(), lower.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* name : { "llvmpipe", "softpipe", "swr" })
  {
    if (lower.find(name) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

std::string GlRendererFromReport(const char* report)
{
  const std::string text = report ? report : "";
  const std::string key = "OpenGL renderer string:";
  const size_t at = text.find(key);
  if (at == std::string::npos)
  {
    return {};
  }
  const size_t begin = text.find_first_not_of(' ', at + key.size());
  const size_t end = text.find('\n', at);
  return begin == std::string::npos || begin >= end ? std::string() : text.substr(begin, end - begin);
}

BackendChoice ChooseBackend(Backend requested, const BackendFacts& facts)
{
  BackendChoice choice;
  // The CPU for `reason`: a conflict when the GPU was asked for.
  auto onCpu = [&](const std::string& reason) {
    choice.backend = Backend::CPU;
    choice.why = "cpu: " + reason;
    if (requested == Backend::GPU)
    {
      choice.conflict = reason;
    }
    return choice;
  };
  if (!facts.cpuOnly.empty())
  {
    return onCpu(facts.cpuOnly);
  }
  if (requested == Backend::CPU)
  {
    choice.backend = Backend::CPU;
    choice.why = "cpu";
    return choice;
  }
  if (!facts.glUsable)
  {
    return onCpu(facts.glProblem);
  }
  if (requested == Backend::GPU)
  {
    choice.why = "gpu";
    return choice;
  }
  const bool software = IsSoftwareRasterizer(facts.glRenderer);
  const bool cpu = software && facts.polygons >= kAutoCpuMinPolygons;
  choice.backend = cpu ? Backend::CPU : Backend::GPU;
  choice.why = std::string(cpu ? "cpu" : "gpu") + ": OpenGL renderer '" + facts.glRenderer + "' is " +
    (software ? "a software rasterizer" : "hardware") + ", " + std::to_string(facts.polygons) +
    " polygons";
  if (software)
  {
    choice.why += (cpu ? " >= " : " < ") + std::to_string(kAutoCpuMinPolygons);
  }
  return choice;
}

} // namespace shadinglab::render
