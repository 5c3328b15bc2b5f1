// SPDX-License-Identifier: BSD-3-Clause
#include "PolarizationOutput.h"

#include "CliArgs.h"
#include "RenderOutput.h"
#include "SceneArguments.h"

#include "shadinglab/render/ColorMap.h"
#include "shadinglab/render/Image.h"
#include "shadinglab/render/Stokes.h"

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataWriter.h>

#include <cmath>

namespace shadinglab::cli
{

namespace
{

/// s0 .. s3: one Stokes component, a .vti of its own.
bool IsStokesComponent(const std::string& kind)
{
  return kind.size() == 2 && kind[0] == 's' && kind[1] >= '0' && kind[1] <= '3';
}

} // namespace

bool IsPolarizationOutput(const std::string& kind)
{
  if (kind == "intensity")
  {
    return false;
  }
  if (kind == "dolp" || kind == "aop" || kind == "stokes" || IsStokesComponent(kind))
  {
    return true;
  }
  throw UsageError(
    "--output must be intensity, s0, s1, s2, s3, stokes, dolp or aop (got '" + kind + "')");
}

double WritePolarizationOutput(render::Renderer& renderer, const render::Scene& scene,
  const render::RenderOptions& options, const std::string& kind, const std::string& path)
{
  // The Stokes image from five analysed frames (eq. 8.5, render/Stokes.h).
  const bool numbers = kind == "stokes" || IsStokesComponent(kind);
  const std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : std::string();
  if (numbers != (ext == ".vti"))
  {
    throw UsageError("--output " + kind + " writes " + (numbers ? "a .vti" : "a .png") +
      " file (got --out " + path + ")");
  }
  render::StokesImage stokes;
  try
  {
    stokes = render::MeasureStokes(renderer, scene, options);
  }
  catch (const std::invalid_argument& e)
  {
    throw UsageError("--output " + kind + ": " + e.what() + ", --backend cpu");
  }
  catch (const std::runtime_error& e)
  {
    throw UsageError("--output " + kind + ": " + e.what());
  }
  const int W = stokes.width, H = stokes.height;
  const size_t n = static_cast<size_t>(W) * H;
  const auto& s = stokes.s;
  const auto& dolp = stokes.dolp;
  const auto& aop = stokes.aop;
  if (numbers)
  {
    vtkNew<vtkImageData> image;
    image->SetDimensions(W, H, 1);
    auto add = [&](const char* name, const std::vector<float>& values, int components) {
      vtkNew<vtkFloatArray> array;
      array->SetName(name);
      array->SetNumberOfComponents(components);
      array->SetNumberOfTuples(static_cast<vtkIdType>(n));
      // VTK's image rows go up; ours go down.
      for (int y = 0; y < H; ++y)
      {
        for (int x = 0; x < W; ++x)
        {
          const size_t from = static_cast<size_t>(y) * W + x;
          const vtkIdType to = static_cast<vtkIdType>(H - 1 - y) * W + x;
          for (int c = 0; c < components; ++c)
          {
            array->SetComponent(to, c, values[components * from + c]);
          }
        }
      }
      image->GetPointData()->AddArray(array);
    };
    const char* names[4] = { "S0", "S1", "S2", "S3" };
    if (kind == "stokes")
    {
      for (int k = 0; k < 4; ++k)
      {
        add(names[k], s[k], 3);
      }
      add("DoLP", dolp, 1);
      add("AoP", aop, 1);
    }
    else
    {
      const int k = kind[1] - '0';
      add(names[k], s[k], 3);
      image->GetPointData()->SetActiveScalars(names[k]);
    }
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputData(image);
    if (writer->Write() != 1)
    {
      throw UsageError("cannot write " + path);
    }
    return stokes.meanDolp;
  }
  const render::ColorMap map =
    kind == "dolp" ? render::DolpColorMap() : render::AopColorMap();
  const std::string title = kind == "dolp" ? "DoLP" : "AoP (deg from x)";
  const std::vector<float> rgb = render::FalseColour(stokes,
    kind == "dolp" ? render::StokesQuantity::Dolp : render::StokesQuantity::Aop, options.background);
  std::vector<uint8_t> rgb8(rgb.size());
  for (size_t k = 0; k < rgb.size(); ++k)
  {
    rgb8[k] = static_cast<uint8_t>(std::lround(255.0f * std::clamp(rgb[k], 0.0f, 1.0f)));
  }
  DrawColorLegend(rgb8, W, H, map, title);
  WritePng(W, H, rgb8, path);
  return stokes.meanDolp;
}

} // namespace shadinglab::cli
