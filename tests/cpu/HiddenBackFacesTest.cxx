// SPDX-License-Identifier: BSD-3-Clause
// Back faces culled without --cull where none can be seen
// (plugin/cpu/src/HiddenBackFaces.h): the same picture for half the set-up,
// and never where a back face could show.
#include "AnalyticMeshes.h"
#include "PolyDataMesh.h"
#include "RenderTestUtil.h"
#include "WorkerPool.h"
#include "shadinglab/cpu/SoftwareRenderer.h"

#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

namespace sl = shadinglab;
namespace render = shadinglab::render;
using sl::Vec3d;
using sl::Vec3f;

namespace
{

render::Mesh MeshOf(vtkPolyData* raw)
{
  vtkSmartPointer<vtkPolyData> pd;
  pd.TakeReference(raw);
  return render::MeshFromPolyData(pd);
}

render::Camera Looking(const Vec3d& from, const Vec3d& at, bool parallel = false)
{
  render::Camera cam;
  cam.position = from;
  cam.focalPoint = at;
  cam.viewUp = Vec3d(0, 1, 0);
  cam.viewAngle = 40;
  cam.nearClip = 0.05;
  cam.farClip = 100;
  cam.parallel = parallel;
  cam.parallelScale = 1.4;
  return cam;
}

struct Frame
{
  render::Image image;
  render::RenderStats stats;
};

Frame Draw(const render::Mesh& mesh, const render::Camera& cam, render::ShadingMode mode,
  bool cullHidden)
{
  render::RenderOptions opt;
  opt.width = 200;
  opt.height = 150;
  opt.mode = mode;
  opt.threads = 2;
  opt.cullHiddenBackFaces = cullHidden;
  sl::Lighting<float> lights;
  lights.lights[0].vector = Vec3f(0.3f, 0.6f, 0.7f);
  sl::Material<float> material;
  Frame f;
  f.image = sl::test::RenderCpu(mesh, cam, lights, material, opt, &f.stats);
  return f;
}

/// The triangles of `mesh` with their vertex order reversed (facing inward).
render::Mesh Reversed(render::Mesh mesh)
{
  for (int64_t p = 0; p < mesh.NumberOfPolygons(); ++p)
  {
    std::reverse(mesh.connectivity.begin() + mesh.offsets[p],
      mesh.connectivity.begin() + mesh.offsets[p + 1]);
  }
  return mesh;
}

} // namespace

TEST(HiddenBackFacesTest, ClosedMeshSeenFromOutsideGivesTheSamePictureForHalfTheTriangles)
{
  const render::Mesh torus = MeshOf(sl::datasets::MakeTorus(1.0, 0.4, 48, 24));
  const render::Mesh sphere = MeshOf(sl::datasets::MakeIcosphere(3));
  for (const auto* mesh : { &torus, &sphere })
  {
    for (bool parallel : { false, true })
    {
      for (auto mode : { render::ShadingMode::Flat, render::ShadingMode::Gouraud,
             render::ShadingMode::Phong, render::ShadingMode::FastPhong })
      {
        SCOPED_TRACE(std::string(render::ShadingModeName(mode)) + (parallel ? " parallel" : "") +
          (mesh == &torus ? " torus" : " icosphere"));
        const auto cam = Looking(Vec3d(0.5, 2.0, 3.0), Vec3d(0, 0, 0), parallel);
        const Frame culled = Draw(*mesh, cam, mode, true);
        const Frame all = Draw(*mesh, cam, mode, false);
        EXPECT_TRUE(culled.stats.hiddenBackFacesCulled);
        EXPECT_FALSE(all.stats.hiddenBackFacesCulled);
        EXPECT_EQ(all.stats.culled, 0);
        // About half the triangles face away; they are skipped, not drawn.
        EXPECT_GT(culled.stats.culled, culled.stats.polygons * 2 / 5);
        EXPECT_EQ(culled.stats.rasterized + culled.stats.culled,
          all.stats.rasterized);
        EXPECT_LE(culled.stats.pixelsShaded, all.stats.pixelsShaded);
        // Nothing a pixel showed was a back face: the very same picture.
        EXPECT_EQ(culled.image.covered, all.image.covered);
        EXPECT_EQ(culled.image.rgb, all.image.rgb);
      }
    }
  }
}

TEST(HiddenBackFacesTest, BackFacesThatCouldShowAreDrawn)
{
  const render::Mesh torus = MeshOf(sl::datasets::MakeTorus(1.0, 0.4, 48, 24));
  const auto outside = Looking(Vec3d(0.5, 2.0, 3.0), Vec3d(0, 0, 0));
  const render::ShadingMode phong = render::ShadingMode::Phong;
  // Facing inward: its back faces are the ones in front.
  EXPECT_FALSE(Draw(Reversed(torus), outside, phong, true).stats.hiddenBackFacesCulled);
  // Camera inside the bounding box (in the torus's hole, looking through
  // the tube): the near plane may cut the tube open.
  EXPECT_FALSE(
    Draw(torus, Looking(Vec3d(0, 0, 0), Vec3d(1, 0, 0)), phong, true).stats.hiddenBackFacesCulled);
  // Open surfaces show their back faces.
  const render::Mesh plane = MeshOf(sl::datasets::MakeCorrugatedPlane(4, 8, 0.2));
  EXPECT_FALSE(Draw(plane, outside, phong, true).stats.hiddenBackFacesCulled);
  // A torus with one triangle missing is open.
  render::Mesh holed = torus;
  holed.connectivity.resize(holed.connectivity.size() - 3);
  holed.offsets.pop_back();
  const Frame open = Draw(holed, outside, phong, true);
  EXPECT_FALSE(open.stats.hiddenBackFacesCulled);
  EXPECT_EQ(open.stats.culled, 0);
  // Quads (a polygon need not be planar): not culled without --cull.
  const render::Mesh quads = MeshOf(sl::datasets::MakeQuadStrip(6));
  EXPECT_FALSE(Draw(quads, outside, phong, true).stats.hiddenBackFacesCulled);
}

TEST(HiddenBackFacesTest, EditingTheMeshInPlaceIsNoticed)
{
  // The closed-mesh test is cached against the arrays' contents: the same
  // renderer, the same Mesh object, one triangle turned around.
  render::Mesh torus = MeshOf(sl::datasets::MakeTorus(1.0, 0.4, 48, 24));
  const auto cam = Looking(Vec3d(0.5, 2.0, 3.0), Vec3d(0, 0, 0));
  render::RenderOptions opt;
  opt.width = 64;
  opt.height = 48;
  opt.threads = 1;
  sl::cpu::SoftwareRenderer renderer;
  const render::Scene scene{ &torus, cam, sl::Lighting<double>(), sl::Material<double>() };
  render::RenderStats stats;
  renderer.Render(scene, opt, &stats);
  EXPECT_TRUE(stats.hiddenBackFacesCulled);
  std::swap(torus.connectivity[0], torus.connectivity[1]);
  renderer.Render(scene, opt, &stats);
  EXPECT_FALSE(stats.hiddenBackFacesCulled);
  std::swap(torus.connectivity[0], torus.connectivity[1]);
  renderer.Render(scene, opt, &stats);
  EXPECT_TRUE(stats.hiddenBackFacesCulled);
}

TEST(HiddenBackFacesTest, ASmallImageTestsTheMeshOnItsSecondFrame)
{
  // Fewer pixels than triangles: the test waits for the mesh's second frame
  // (a one-frame render does not earn it back), then culls; culling hidden
  // back faces changes no pixel.
  render::Mesh torus = MeshOf(sl::datasets::MakeTorus(1.0, 0.4, 48, 24)); // 2,304 triangles
  const auto cam = Looking(Vec3d(0.5, 2.0, 3.0), Vec3d(0, 0, 0));
  render::RenderOptions opt;
  opt.width = 40;
  opt.height = 30; // 1,200 pixels
  sl::cpu::SoftwareRenderer renderer;
  const render::Scene scene{ &torus, cam, sl::Lighting<double>(), sl::Material<double>() };
  render::RenderStats stats;
  const std::vector<float> first = renderer.Render(scene, opt, &stats).rgb;
  EXPECT_FALSE(stats.hiddenBackFacesCulled);
  const std::vector<float> second = renderer.Render(scene, opt, &stats).rgb;
  EXPECT_TRUE(stats.hiddenBackFacesCulled);
  EXPECT_GT(stats.culled, 0);
  EXPECT_EQ(second, first);
  // Another mesh in between starts over: its first frame is untested.
  torus.points[0] += 0.01f;
  renderer.Render(scene, opt, &stats);
  EXPECT_FALSE(stats.hiddenBackFacesCulled);
  renderer.Render(scene, opt, &stats);
  EXPECT_TRUE(stats.hiddenBackFacesCulled);
}

TEST(HiddenBackFacesTest, TheMeshHashIsTheSameForAnyThreadsBehindIt)
{
  // The closed-mesh cache is keyed on Mesh::ContentHash: its value must not
  // depend on whether, or on how many threads, hash the slices, or a change
  // of thread count would re-run the test. 316 x 158 torus: 4.4 MB in all,
  // connectivity 2.4 MB (nine slices), points 0.6 MB (two).
  const render::Mesh torus = MeshOf(sl::datasets::MakeTorus(1.0, 0.4, 316, 158));
  const uint64_t alone = torus.ContentHash();
  sl::cpu::WorkerPool pool;
  for (int threads : { 1, 2, 3 })
  {
    int calls = 0, tasks = 0;
    const uint64_t ran = torus.ContentHash(
      [&](int n, const std::function<void(int)>& task)
      {
        ++calls;
        tasks = n;
        sl::cpu::ParallelFor(pool, n, threads,
          [&](int64_t b, int64_t e, int)
          {
            for (int64_t k = e - 1; k >= b; --k) // any order within a thread
            {
              task(static_cast<int>(k));
            }
          });
      });
    EXPECT_EQ(ran, alone) << threads;
    EXPECT_EQ(calls, 1); // every array's slices in one batch
    EXPECT_GE(tasks, 14);
    // The renderer's own runner, which hands out slices as threads free up.
    EXPECT_EQ(torus.ContentHash(sl::cpu::SpreadOver(pool, threads)), alone) << threads;
  }
  render::Mesh edited = torus;
  edited.connectivity.back() = edited.connectivity.front();
  EXPECT_NE(edited.ContentHash(), alone);
  edited = torus;
  edited.points[1] = std::nextafter(edited.points[1], 2.0f); // one bit of one point
  EXPECT_NE(edited.ContentHash(sl::cpu::SpreadOver(pool, 2)), alone);
}

TEST(HiddenBackFacesTest, BoundsAreExactForAnyThreadsBehindThem)
{
  // The renderer reads the bounds every frame, in slices of 64k points over
  // its threads: the box must be the serial one, NaN coordinates skipped.
  render::Mesh sphere = MeshOf(sl::datasets::MakeIcosphere(6)); // 40,962 points
  render::Mesh big = MeshOf(sl::datasets::MakeTorus(1.0, 0.4, 600, 300)); // 180,000
  big.points[3 * 170000 + 2] = 7.5f;       // the top, in the last slice
  big.points[3 * 70000] = -3.25f;          // the left, in the second
  big.points[3 * 100000 + 1] = std::nanf(""); // skipped
  sl::cpu::WorkerPool pool;
  for (const render::Mesh* mesh : { &sphere, &big })
  {
    double serial[6];
    mesh->Bounds(serial);
    for (int threads : { 1, 2, 3 })
    {
      double spread[6];
      mesh->Bounds(spread, sl::cpu::SpreadOver(pool, threads));
      for (int c = 0; c < 6; ++c)
      {
        EXPECT_EQ(spread[c], serial[c]) << threads << " " << c;
      }
    }
  }
  double b[6];
  big.Bounds(b, sl::cpu::SpreadOver(pool, 2));
  EXPECT_EQ(b[0], -3.25);
  EXPECT_EQ(b[5], 7.5);
  EXPECT_TRUE(std::isfinite(b[2]) && std::isfinite(b[3]));
  render::Mesh empty;
  empty.Bounds(b, sl::cpu::SpreadOver(pool, 2));
  EXPECT_GT(b[0], b[1]); // no points: an empty box
}

TEST(HiddenBackFacesTest, RunsFacingAwayAreSkippedWholeForTheSamePicture)
{
  // From a mesh's second culled frame on, binning skips runs of
  // kClusterPolygons triangles whose cone of normals faces away
  // (HiddenBackFaces.h). Only back faces go: the same pixels, depths and
  // scan-converted polygons as the first frame, which tests each triangle,
  // from cameras all round (near, far, parallel) on meshes whose runs are
  // strips (UV sphere, torus), patches (icosphere), an irregular decimated
  // surface and a marching-cubes isosurface.
  const render::Mesh meshes[] = { MeshOf(sl::datasets::MakeUVSphere(160, 80)),
    MeshOf(sl::datasets::MakeTorus(1.0, 0.4, 160, 64)), MeshOf(sl::datasets::MakeIcosphere(5)),
    MeshOf(sl::datasets::MakeNoisyDecimatedSphere(5, 0.02, 0.5)),
    MeshOf(sl::datasets::MakeMetaballIsosurface(40)) };
  int64_t skippedInAll = 0, polygonsInAll = 0;
  for (const render::Mesh& mesh : meshes)
  {
    double b[6];
    mesh.Bounds(b);
    const Vec3d centre(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]));
    const double size = std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] });
    for (int k = 0; k < 12; ++k)
    {
      // Directions spread over the sphere (a Fibonacci lattice).
      const double z = 1.0 - (k + 0.5) / 6.0;
      const double phi = k * 2.399963229728653;
      const double rxy = std::sqrt(std::max(0.0, 1.0 - z * z));
      const Vec3d dir(rxy * std::cos(phi), z, rxy * std::sin(phi));
      for (double distance : { 0.9, 3.0 })
      {
        for (bool parallel : { false, true })
        {
          render::Camera cam = Looking(centre + dir * (distance * size), centre, parallel);
          cam.viewUp = std::abs(dir.y) > 0.9 ? Vec3d(1, 0, 0) : Vec3d(0, 1, 0);
          cam.parallelScale = 0.6 * size;
          render::RenderOptions opt;
          opt.width = 160;
          opt.height = 120;
          opt.threads = 2;
          opt.keepDepth = true;
          opt.mode = render::ShadingMode::Phong;
          const render::Scene scene{ &mesh, cam, sl::Lighting<double>(), sl::Material<double>() };
          // The reference: back faces culled one by one (asked, on a
          // renderer's first frame, which has no cones yet).
          render::RenderOptions asked = opt;
          asked.cullBackFaces = true;
          sl::cpu::SoftwareRenderer fresh;
          render::RenderStats first, second;
          const render::Image one = fresh.Render(scene, asked, &first);
          // Hidden back faces found by the closed-mesh test, from the
          // renderer's third frame on with cones (ClusterConeCache). The
          // first two from the opposite side: a vertex the third frame
          // needs but did not project (TestRuns) would keep their
          // projection and show.
          render::Scene opposite = scene;
          opposite.camera = Looking(centre - dir * (distance * size), centre, parallel);
          opposite.camera.viewUp = cam.viewUp;
          opposite.camera.parallelScale = cam.parallelScale;
          sl::cpu::SoftwareRenderer renderer;
          renderer.Render(opposite, opt);
          renderer.Render(opposite, opt);
          const render::Image& two = renderer.Render(scene, opt, &second);
          SCOPED_TRACE("mesh of " + std::to_string(mesh.NumberOfPolygons()) + " polygons, view " +
            std::to_string(k) + " at " + std::to_string(distance) + (parallel ? " parallel" : ""));
          if (!second.hiddenBackFacesCulled)
          {
            continue; // the near camera inside the bounds: nothing culled
          }
          EXPECT_EQ(first.culledInClusters, 0);
          EXPECT_EQ(two.rgb, one.rgb);
          EXPECT_EQ(two.covered, one.covered);
          EXPECT_EQ(two.depth, one.depth);
          EXPECT_EQ(second.rasterized, first.rasterized);
          EXPECT_EQ(second.triangles, first.triangles);
          // The runs' back faces are no longer counted one by one.
          EXPECT_LE(second.culled, first.culled);
          EXPECT_GE(second.culled + second.culledInClusters, first.culled);
          skippedInAll += second.culledInClusters;
          polygonsInAll += second.polygons;
        }
      }
    }
  }
  // About half of each closed mesh faces away; much of it in whole runs.
  std::printf("culled in runs: %lld of %lld polygons\n", static_cast<long long>(skippedInAll),
    static_cast<long long>(polygonsInAll));
  EXPECT_GT(skippedInAll, polygonsInAll / 4);
}

TEST(HiddenBackFacesTest, AskedCullingOfAnOpenMeshSkipsRunsAndFollowsTheMesh)
{
  // --cull on an open mesh (the corrugated plane, from behind and in
  // front), and a new mesh in the same renderer gets its own cones: after
  // the sphere's frames, the sphere turned inside out is drawn as a fresh
  // renderer draws it (inside faces now front faces).
  const render::Mesh plane = MeshOf(sl::datasets::MakeCorrugatedPlane(8, 40, 0.05));
  const render::Mesh sphere = MeshOf(sl::datasets::MakeUVSphere(120, 60));
  const render::Mesh inside = Reversed(sphere);
  render::RenderOptions opt;
  opt.width = 160;
  opt.height = 120;
  opt.threads = 2;
  opt.cullBackFaces = true;
  opt.mode = render::ShadingMode::Gouraud;
  for (double side : { 1.0, -1.0 })
  {
    const auto cam = Looking(Vec3d(0.3, 0.4 * side, 2.5 * side), Vec3d(0, 0, 0));
    sl::cpu::SoftwareRenderer renderer;
    const render::Scene scene{ &plane, cam, sl::Lighting<double>(), sl::Material<double>() };
    render::RenderStats first, second;
    const render::Image one = renderer.Render(scene, opt, &first);
    const render::Image& two = renderer.Render(scene, opt, &second);
    EXPECT_EQ(two.rgb, one.rgb) << side;
    EXPECT_EQ(second.rasterized, first.rasterized) << side;
  }
  const auto cam = Looking(Vec3d(0.5, 1.0, 3.0), Vec3d(0, 0, 0));
  sl::cpu::SoftwareRenderer renderer, fresh;
  render::RenderStats stats;
  for (int frame = 0; frame < 2; ++frame)
  {
    renderer.Render({ &sphere, cam, sl::Lighting<double>(), sl::Material<double>() }, opt, &stats);
  }
  EXPECT_GT(stats.culledInClusters, stats.polygons / 8);
  const render::Scene turned{ &inside, cam, sl::Lighting<double>(), sl::Material<double>() };
  const render::Image expected = fresh.Render(turned, opt);
  for (int frame = 0; frame < 3; ++frame)
  {
    EXPECT_EQ(renderer.Render(turned, opt, &stats).rgb, expected.rgb) << "frame " << frame;
  }
  EXPECT_GT(stats.culledInClusters, stats.polygons / 8);
}
