// SPDX-License-Identifier: BSD-3-Clause
// Vertex-normal speed on ~100k and ~1M triangles: our filter and core loop
// against vtkPolyDataNormals (defaults; splitting and consistency off),
// vtkTriangleMeshPointNormals, a plain area-weighted loop over the raw
// arrays, the cost of building an OpenMesh TriMesh alone, and the
// orientation check every normals computation now runs first (and the fix
// when it finds faces to turn), in one run.
//
//   build/bin/shadinglab_bench_normals --benchmark_repetitions=7
//       --benchmark_report_aggregates_only=true
#include "AnalyticMeshes.h"
#include "MeshArrays.h"
#include "Orientation.h"
#include "VertexNormals.h"
#include "vtkWeightedPolyDataNormals.h"

#include <benchmark/benchmark.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <vtkCellArray.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleMeshPointNormals.h>

#include <map>
#include <memory>

namespace
{

vtkPolyData* Mesh(int which)
{
  static std::map<int, vtkSmartPointer<vtkPolyData>> meshes;
  auto& m = meshes[which];
  if (!m)
  {
    // 100k: torus 316 x 158 x 2 = 99,856 triangles; 1M: 1000 x 500 x 2 = 1,000,000.
    m.TakeReference(which == 0 ? shadinglab::datasets::MakeTorus(1.0, 0.4, 316, 158)
                               : shadinglab::datasets::MakeTorus(1.0, 0.4, 1000, 500));
  }
  return m;
}

void BM_OursFilter(benchmark::State& state)
{
  vtkPolyData* input = Mesh(static_cast<int>(state.range(0)));
  vtkNew<vtkWeightedPolyDataNormals> filter;
  filter->SetInputData(input);
  filter->SetWeighting(static_cast<int>(state.range(1)));
  filter->SetSplitting(state.range(2) != 0);
  for (auto _ : state)
  {
    filter->Modified();
    filter->Update();
  }
  const char* names[] = { "uniform", "area", "angle", "max" };
  state.SetLabel(std::string("ours filter ") + names[state.range(1)] +
    (state.range(2) ? " split30" : " nosplit"));
}

void BM_OursCore(benchmark::State& state)
{
  vtkPolyData* input = Mesh(static_cast<int>(state.range(0)));
  shadinglab::mesh::FlatPolygons flat;
  shadinglab::mesh::FlatPolygonsFromPolyData(input, flat);
  const shadinglab::mesh::MeshView& mesh = flat;
  std::vector<double> normals;
  const auto w = static_cast<shadinglab::mesh::NormalWeighting>(state.range(1));
  for (auto _ : state)
  {
    shadinglab::mesh::ComputeVertexNormalsNoSplit(mesh, w, normals);
    benchmark::DoNotOptimize(normals.data());
  }
  const char* names[] = { "uniform", "area", "angle", "max" };
  state.SetLabel(std::string("ours core ") + names[state.range(1)] + " nosplit");
}

void BM_OrientationCheck(benchmark::State& state)
{
  // What a consistent mesh pays before its normals: the directed-edge test.
  vtkPolyData* input = Mesh(static_cast<int>(state.range(0)));
  shadinglab::mesh::FlatPolygons flat;
  shadinglab::mesh::FlatPolygonsFromPolyData(input, flat);
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(shadinglab::mesh::HasInconsistentOrientation(flat));
  }
  state.SetLabel("consistency check (consistent mesh)");
}

void BM_OrientationFix(benchmark::State& state)
{
  // Every third face reversed: neighbours, breadth-first flips, volume.
  vtkPolyData* input = Mesh(static_cast<int>(state.range(0)));
  shadinglab::mesh::FlatPolygons flat;
  shadinglab::mesh::FlatPolygonsFromPolyData(input, flat);
  std::vector<uint8_t> every3(static_cast<size_t>(flat.numberOfPolygons), 0);
  for (size_t f = 0; f < every3.size(); f += 3)
  {
    every3[f] = 1;
  }
  std::vector<int64_t> scrambled, turned;
  shadinglab::mesh::FlipFaces(flat, every3, scrambled);
  shadinglab::mesh::MeshView mesh = flat;
  mesh.connectivity = scrambled.data();
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(shadinglab::mesh::HasInconsistentOrientation(mesh));
    shadinglab::mesh::FlipFaces(mesh, shadinglab::mesh::ConsistentOrientationFlips(mesh), turned);
  }
  state.SetLabel("check + orient (a third reversed)");
}

void BM_PlainLoop(benchmark::State& state)
{
  // The reference: area-weighted normals as one loop over raw triangle arrays.
  vtkPolyData* input = Mesh(static_cast<int>(state.range(0)));
  shadinglab::mesh::FlatPolygons flat;
  shadinglab::mesh::FlatPolygonsFromPolyData(input, flat);
  std::vector<double> n;
  for (auto _ : state)
  {
    n.assign(static_cast<size_t>(3 * flat.numberOfPoints), 0.0);
    for (int64_t t = 0; t < flat.numberOfPolygons; ++t)
    {
      const int64_t* c = flat.connectivity + flat.offsets[t];
      const double* a = flat.points + 3 * c[0];
      const double* b = flat.points + 3 * c[1];
      const double* d = flat.points + 3 * c[2];
      const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
      const double v[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
      const double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2],
                   z = u[0] * v[1] - u[1] * v[0];
      for (int k = 0; k < 3; ++k)
      {
        n[3 * c[k]] += x;
        n[3 * c[k] + 1] += y;
        n[3 * c[k] + 2] += z;
      }
    }
    for (size_t i = 0; i < n.size(); i += 3)
    {
      const double l = std::sqrt(n[i] * n[i] + n[i + 1] * n[i + 1] + n[i + 2] * n[i + 2]);
      n[i] /= l;
      n[i + 1] /= l;
      n[i + 2] /= l;
    }
    benchmark::DoNotOptimize(n.data());
  }
  state.SetLabel("plain area loop");
}

void BM_VtkPolyDataNormals(benchmark::State& state)
{
  vtkPolyData* input = Mesh(static_cast<int>(state.range(0)));
  vtkNew<vtkPolyDataNormals> filter;
  filter->SetInputData(input);
  const bool defaults = state.range(1) != 0;
  filter->SetSplitting(defaults);
  filter->SetConsistency(defaults);
  for (auto _ : state)
  {
    filter->Modified();
    filter->Update();
  }
  state.SetLabel(defaults ? "vtkPolyDataNormals defaults" : "vtkPolyDataNormals split/consistency off");
}

void BM_VtkTriangleMeshPointNormals(benchmark::State& state)
{
  vtkPolyData* input = Mesh(static_cast<int>(state.range(0)));
  vtkNew<vtkTriangleMeshPointNormals> filter;
  filter->SetInputData(input);
  for (auto _ : state)
  {
    filter->Modified();
    filter->Update();
  }
  state.SetLabel("vtkTriangleMeshPointNormals");
}

void BM_OpenMeshConversion(benchmark::State& state)
{
  vtkPolyData* input = Mesh(static_cast<int>(state.range(0)));
  shadinglab::mesh::FlatPolygons flat;
  shadinglab::mesh::FlatPolygonsFromPolyData(input, flat);
  for (auto _ : state)
  {
    OpenMesh::TriMesh_ArrayKernelT<> mesh;
    std::vector<OpenMesh::VertexHandle> handles(static_cast<size_t>(flat.numberOfPoints));
    for (int64_t i = 0; i < flat.numberOfPoints; ++i)
    {
      const double* p = flat.points + 3 * i;
      handles[i] = mesh.add_vertex(OpenMesh::Vec3f(float(p[0]), float(p[1]), float(p[2])));
    }
    for (int64_t t = 0; t < flat.numberOfPolygons; ++t)
    {
      const int64_t* c = flat.connectivity + flat.offsets[t];
      mesh.add_face(handles[c[0]], handles[c[1]], handles[c[2]]);
    }
    benchmark::DoNotOptimize(mesh.n_faces());
  }
  state.SetLabel("OpenMesh TriMesh build only");
}

} // namespace

BENCHMARK(BM_PlainLoop)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OrientationCheck)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OrientationFix)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OursCore)
  ->ArgsProduct({ { 0, 1 }, { 0, 1, 2, 3 } })
  ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OursFilter)
  ->ArgsProduct({ { 0, 1 }, { 1 }, { 0, 1 } })
  ->Args({ 1, 2, 0 })
  ->Args({ 1, 3, 0 })
  ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VtkPolyDataNormals)->ArgsProduct({ { 0, 1 }, { 0, 1 } })->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VtkTriangleMeshPointNormals)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OpenMeshConversion)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
