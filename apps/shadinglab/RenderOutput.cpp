// SPDX-License-Identifier: BSD-3-Clause
#include "RenderOutput.h"

#include "CliArgs.h"

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
  const std::string& text)
{
  vtkNew<vtkTextProperty> property;
  property->SetFontSize(15);
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


} // namespace shadinglab::cli
