// SPDX-License-Identifier: BSD-3-Clause
// The fast OFF reader (FastReaders.h): plain "OFF" files (no C, N or other
// prefix), read as MeshIO.cxx's ReadOff reads them: double points, one
// polygon per face line, '#' comments and empty lines skipped, tokens
// after a vertex's three coordinates or a face's indices ignored.
#include "FastReadCommon.h"
#include "MeshIO.h"

#include <vtkDoubleArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace shadinglab
{

namespace
{

/// Largest count the fast path takes: ReadOff's kMaxOffElements (2^31)
/// less one, so that every id fits a 32-bit int as VTK's filters expect.
constexpr long long kMaxCount = (1LL << 31) - 1;

/// Moves to the next line holding a token (past empty and comment lines);
/// false at the end of the file.
bool NextRow(fastread::Text& text)
{
  for (;;)
  {
    while (text.at < text.end && fastread::Text::IsSeparator(*text.at))
    {
      ++text.at;
    }
    if (text.at == text.end)
    {
      return false;
    }
    if (*text.at != '#')
    {
      return true;
    }
    text.NextLine();
  }
}

} // namespace

vtkSmartPointer<vtkPolyData> ReadFastOff(fastread::MappedFile& file)
{
  fastread::Text text{ file.Data(), file.Data() + file.Size() };
  if (!NextRow(text) || !text.Word("OFF"))
  {
    return nullptr;
  }
  if (text.AtLineEnd() && !NextRow(text))
  {
    return nullptr;
  }
  long long nv = 0, nf = 0;
  if (!text.Integer(nv) || !text.Integer(nf) || nv <= 0 || nf <= 0 || nv > kMaxCount || nf > kMaxCount)
  {
    return nullptr;
  }
  text.NextLine();
  // A vertex line holds at least 6 bytes ("0 0 0\n"), a face line 8
  // ("3 0 1 2\n"): counts the rest of the file cannot hold are refused
  // before anything is allocated for them.
  const auto rest = static_cast<unsigned long long>(text.end - text.at);
  if (6ull * static_cast<unsigned long long>(nv) + 8ull * static_cast<unsigned long long>(nf) > rest)
  {
    return nullptr;
  }
  fastread::Polygons out(0, nf, 3 * nf);
  auto points = vtkSmartPointer<vtkDoubleArray>::New();
  points->SetNumberOfComponents(3);
  points->SetNumberOfTuples(nv);
  double* xyz = points->GetPointer(0);
  for (long long i = 0; i < nv; ++i)
  {
    if (!NextRow(text) || !text.Real(xyz[3 * i]) || !text.Real(xyz[3 * i + 1]) || !text.Real(xyz[3 * i + 2]))
    {
      return nullptr;
    }
    if (!std::isfinite(xyz[3 * i]) || !std::isfinite(xyz[3 * i + 1]) || !std::isfinite(xyz[3 * i + 2]))
    {
      return nullptr;
    }
    text.NextLine();
  }
  file.Release(static_cast<size_t>(text.at - file.Data()));
  for (long long f = 0; f < nf; ++f)
  {
    if (!NextRow(text) || !out.AddPolygon(text, nv, nv))
    {
      return nullptr;
    }
    out.offset[f + 1] = out.used;
    text.NextLine();
    if ((f & 0xffff) == 0)
    {
      file.Release(static_cast<size_t>(text.at - file.Data()));
    }
  }
  vtkSmartPointer<vtkPolyData> mesh = out.Finish();
  auto pts = vtkSmartPointer<vtkPoints>::New();
  pts->SetData(points);
  mesh->SetPoints(pts);
  return mesh;
}

} // namespace shadinglab
