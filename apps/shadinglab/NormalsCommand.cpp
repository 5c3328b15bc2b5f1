// SPDX-License-Identifier: BSD-3-Clause
// shadinglab normals: mesh preparation (repair, T-junctions, subdivision,
// weighted normals) from the command line.
#include "Commands.h"
#include "MeshPipeline.h"

#include "MeshIO.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstdio>
#include <stdexcept>
#include <sys/stat.h>
#include <iostream>

namespace shadinglab::cli
{

namespace
{
const char* kNormalsHelp =
  "usage: shadinglab normals INPUT --out OUT.vtp [--weights uniform|area|angle|max]\n"
  "                          [--feature-angle DEG] [--weld [TOL]] [--fix-t-junctions]\n"
  "                          [--subdivide N [--scheme loop|catmull-clark]] [--json]\n"
  "                          [--nonlinear-subdivision N] [--time T | --time-step N]\n"
  "\n"
  "Repairs INPUT (degenerate faces removed, orientation made consistent and outward,\n"
  "non-manifold faces kept on copied vertices), optionally welds coincident points\n"
  "(TOL relative to the bounding-box diagonal, default 1e-6), splits T-junction edges,\n"
  "subdivides N levels with OpenSubdiv (normals then come from the limit surface),\n"
  "and computes vertex normals (default: area weights, creases split at 30 degrees).\n"
  "OUT: .vtp .vtk .ply .obj .stl .off by extension. --json prints one JSON object.\n"
  "--nonlinear-subdivision N: times each quadratic face of INPUT is split (default 1).\n"
  "--time T / --time-step N: the step of a time series (.pvd, Exodus II) to read: the\n"
  "last at or before T, or step N from 0 (default: the first).\n";
} // namespace

int RunNormals(int argc, char** argv)
{
  const Stopwatch total;
  std::vector<std::string> valued = { "out", "weights", "feature-angle", "subdivide", "scheme",
    "time", "time-step" };
  std::vector<std::string> flags = { "help", "json", "fix-t-junctions" };
  AddSettingFlags(valued, flags, render::SettingGroup::Mesh);
  const Arguments args(argc, argv, valued, flags, {}, { "weld" });
  if (args.Has("help"))
  {
    std::cout << kNormalsHelp;
    return 0;
  }
  if (args.Positionals().size() != 1)
  {
    throw UsageError(args.Positionals().empty() ? "missing INPUT mesh" : "more than one INPUT given");
  }
  if (!args.Has("out"))
  {
    throw UsageError("--out OUT is required");
  }
  // Never overwrite the input (the same file under another name included).
  {
    struct stat in{}, out{};
    if (stat(args.Positionals()[0].c_str(), &in) == 0 && stat(args.Get("out").c_str(), &out) == 0 &&
      in.st_dev == out.st_dev && in.st_ino == out.st_ino)
    {
      throw UsageError("--out '" + args.Get("out") + "' is the input file: refusing to overwrite it");
    }
  }
  mesh::PreparationOptions options = MeshPipelineFromArguments(args, true);
  vtkSmartPointer<vtkPolyData> input;
  const Stopwatch reading;
  try
  {
    input.TakeReference(ReadMesh(args.Positionals()[0], ReadOptionsFromArguments(args)));
  }
  catch (const MeshError& e)
  {
    throw UsageError(e.what());
  }
  const double readMs = reading.Milliseconds();
  const double readPeakMB = PeakResidentMB();
  const Stopwatch preparing;
  mesh::PreparationReport report;
  vtkSmartPointer<vtkPolyData> output;
  try
  {
    output = mesh::PrepareMesh(input, options, report);
  }
  catch (const std::invalid_argument& e)
  {
    throw UsageError(e.what());
  }
  const double prepareMs = preparing.Milliseconds();
  const double preparePeakMB = PeakResidentMB();
  const Stopwatch writing;
  try
  {
    WriteMesh(output, args.Get("out"));
  }
  catch (const MeshError& e)
  {
    throw UsageError(e.what());
  }
  const double writeMs = writing.Milliseconds();
  if (args.Has("json"))
  {
    std::printf("{\"points_in\":%lld,\"cells_in\":%lld,\"points_out\":%lld,\"cells_out\":%lld,"
                "\"welded\":%lld,\"t_junctions_fixed\":%lld,\"degenerate_removed\":%lld,"
                "\"nonmanifold_edges\":%lld,\"duplicated_points\":%lld,\"flipped\":%lld,"
                "\"crease_edges\":%lld,\"split_points\":%lld,\"subdivision_levels\":%d,"
                "\"scheme\":\"%s\",\"weights\":\"%s\",\"repair_skipped\":%s,\"read_ms\":%.3f,"
                "\"prepare_ms\":%.3f,\"write_ms\":%.3f,\"total_ms\":%.3f,"
                "\"peak_mb_after_read\":%.1f,\"peak_mb_after_prepare\":%.1f,\"peak_mb\":%.1f}\n",
      static_cast<long long>(input->GetNumberOfPoints()),
      static_cast<long long>(input->GetNumberOfCells()),
      static_cast<long long>(output->GetNumberOfPoints()),
      static_cast<long long>(output->GetNumberOfCells()), static_cast<long long>(report.welded),
      static_cast<long long>(report.tJunctionsFixed),
      static_cast<long long>(report.degenerateRemoved),
      static_cast<long long>(report.nonManifoldEdges),
      static_cast<long long>(report.duplicatedPoints), static_cast<long long>(report.flipped),
      static_cast<long long>(report.creaseEdges), static_cast<long long>(report.splitPoints),
      options.subdivisionLevels, report.scheme.c_str(), report.weights.c_str(),
      report.repairSkipped ? "true" : "false", readMs, prepareMs, writeMs, total.Milliseconds(),
      readPeakMB, preparePeakMB, PeakResidentMB());
  }
  return 0;
}

} // namespace shadinglab::cli
