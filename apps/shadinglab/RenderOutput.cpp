// SPDX-License-Identifier: BSD-3-Clause
#include "RenderOutput.h"

#include "CliArgs.h"

#include <algorithm>
#include <cstdio>
#include <vtkFreeTypeTools.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>
#include <fstream>

namespace shadinglab::cli
{

void WritePng(int width, int height, const std::vector<uint8_t>& rgb8, const std::string& path)
{
  vtkNew<vtkImageData> vtkImage;
  vtkImage->SetDimensions(width, height, 1);
  vtkNew<vtkUnsignedCharArray> pixels;
  pixels->SetNumberOfComponents(3);
  pixels->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  // VTK images start at the bottom row.
  for (int y = 0; y < height; ++y)
  {
    const int src = height - 1 - y;
    for (int x = 0; x < width; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        pixels->SetTypedComponent(static_cast<vtkIdType>(y) * width + x, c,
          rgb8[(static_cast<size_t>(src) * width + x) * 3 + c]);
      }
    }
  }
  vtkImage->GetPointData()->SetScalars(pixels);
  // Encode in memory and write the bytes ourselves: when vtkPNGWriter
  // opens a file that cannot be created it leaks libpng's write struct
  // (LeakSanitizer, scripts/sanitize) and logs several lines.
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(vtkImage);
  writer->WriteToMemoryOn();
  writer->Write();
  vtkUnsignedCharArray* png = writer->GetResult();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!png || !out ||
    !out.write(reinterpret_cast<const char*>(png->GetPointer(0)),
      static_cast<std::streamsize>(png->GetNumberOfValues())) ||
    !out.flush())
  {
    throw UsageError("cannot write '" + path + "' (missing directory, no permission or disk full?)");
  }
}

void DrawLabel(std::vector<uint8_t>& canvas, int canvasWidth, int canvasHeight, int x, int y,
  const std::string& text, int fontSize)
{
  vtkNew<vtkTextProperty> property;
  property->SetFontSize(fontSize);
  property->SetColor(1.0, 1.0, 1.0);
  property->SetFontFamilyToArial();
  property->BoldOn();
  vtkNew<vtkImageData> label;
  if (!vtkFreeTypeTools::GetInstance()->RenderString(property, text, 72, label))
  {
    return; // no font: the panel stays unlabelled rather than failing
  }
  int dims[3];
  label->GetDimensions(dims);
  for (int ly = 0; ly < dims[1]; ++ly)
  {
    for (int lx = 0; lx < dims[0]; ++lx)
    {
      // VTK images start at the bottom row.
      const int cx = x + lx, cy = y + (dims[1] - 1 - ly);
      if (cx < 0 || cy < 0 || cx >= canvasWidth || cy >= canvasHeight)
      {
        continue;
      }
      const auto* px = static_cast<unsigned char*>(label->GetScalarPointer(lx, ly, 0));
      const float alpha = px[3] / 255.0f;
      for (int c = 0; c < 3; ++c)
      {
        uint8_t& dst = canvas[(static_cast<size_t>(cy) * canvasWidth + cx) * 3 + c];
        dst = static_cast<uint8_t>(std::lround(dst * (1 - alpha) + px[c] * alpha));
      }
    }
  }
}


void DrawColorLegend(std::vector<uint8_t>& canvas, int canvasWidth, int canvasHeight,
  const render::ColorMap& map, const std::string& title)
{
  const int W = canvasWidth, H = canvasHeight;
  const int font = std::max(9, H / 50);
  const int barW = std::max(8, H / 40), barH = std::max(20, H / 2);
  const int labelW = 5 * font; // "-1.23e+04" at ~0.55 em per glyph
  const int x0 = std::max(0, W - barW - labelW - 12), y0 = std::max(2 * font + 8, (H - barH) / 2);
  auto pixel = [&](int x, int y) -> uint8_t* {
    return (x >= 0 && y >= 0 && x < W && y < H) ? &canvas[(static_cast<size_t>(y) * W + x) * 3]
                                                : nullptr;
  };
  // A darkened box behind the legend, so it reads over any surface.
  const int titleW = static_cast<int>(title.size()) * font * 6 / 10;
  const int boxX = std::max(0, std::min(x0 - 8, W - titleW - 8));
  for (int y = y0 - 2 * font - 8; y < y0 + barH + font; ++y)
  {
    for (int x = boxX; x < W; ++x)
    {
      if (uint8_t* p = pixel(x, y))
      {
        for (int c = 0; c < 3; ++c)
        {
          p[c] = static_cast<uint8_t>(p[c] / 3);
        }
      }
    }
  }
  DrawLabel(canvas, W, H, boxX + 4, y0 - 2 * font - 4, title, font);
  // The bar: the maximum at the top (a constant field: its one colour).
  for (int y = 0; y < barH; ++y)
  {
    const Vec3<float> c = map.LegendColor(1.0 - (y + 0.5) / barH);
    for (int x = x0; x < x0 + barW; ++x)
    {
      if (uint8_t* p = pixel(x, y0 + y))
      {
        p[0] = static_cast<uint8_t>(std::lround(255 * c.x));
        p[1] = static_cast<uint8_t>(std::lround(255 * c.y));
        p[2] = static_cast<uint8_t>(std::lround(255 * c.z));
      }
    }
  }
  // Five ticks with their values (one, at the middle, for a constant).
  for (int k = 0; k <= 4; ++k)
  {
    if (map.IsConstant() && k != 2)
    {
      continue;
    }
    const int y = y0 + (barH - 1) * (4 - k) / 4;
    for (int x = x0 + barW; x < x0 + barW + 5; ++x)
    {
      if (uint8_t* p = pixel(x, y))
      {
        p[0] = p[1] = p[2] = 255;
      }
    }
    char value[32];
    std::snprintf(value, sizeof value, "%.4g", map.LegendTick(k, 4));
    DrawLabel(canvas, W, H, x0 + barW + 7, y - font / 2 - 2, value, font);
  }
}

} // namespace shadinglab::cli
