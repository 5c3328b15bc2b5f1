// SPDX-License-Identifier: BSD-3-Clause
// --polygons direct on polygons that are not convex (docs/model.md section
// 3): kept whole by the conversion and scan-converted with the even-odd
// rule, every pixel centre covered exactly where an exact even-odd
// point-in-polygon test puts it, for the per-row and the incremental scans;
// the same pixels as --polygons triangulate (ear clipping). A polygon whose
// edges cross (the pentagram) is even-odd too, its doubly wound middle open.
#include "PolyDataMesh.h"
#include "RenderTestUtil.h"
#include "shadinglab/render/Image.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace sl = shadinglab;
namespace render = shadinglab::render;

namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr int kWidth = 240, kHeight = 200;
/// Pixel centres nearer an edge than this (in pixels) are not judged: the
/// float projection may put them either side (an edge through a centre is
/// the half-open rule's, not the polygon's).
constexpr double kEdgeBand = 1e-3;

struct Shape
{
  std::string name;
  std::vector<std::pair<double, double>> ring;
};

/// A disc of radius 1 cut open along +x to a hole of radius r.
Shape Keyhole(int n, double r)
{
  Shape s{ "keyhole", {} };
  for (int i = 0; i <= n; ++i)
  {
    s.ring.emplace_back(std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n));
  }
  for (int i = 0; i <= n; ++i)
  {
    s.ring.emplace_back(r * std::cos(-2 * kPi * i / n), r * std::sin(-2 * kPi * i / n));
  }
  return s;
}

Shape Star(int spikes, double inner)
{
  Shape s{ "star" + std::to_string(spikes), {} };
  for (int i = 0; i < 2 * spikes; ++i)
  {
    const double a = kPi * i / spikes + 0.1, r = i % 2 ? inner : 1.0;
    s.ring.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return s;
}

/// Three teeth upward from a bar, each side a collinear run of three.
Shape Comb()
{
  Shape s{ "comb", { { -1.0, -0.8 }, { 1.0, -0.8 } } };
  for (int t = 2; t >= 0; --t)
  {
    const double x0 = -1.0 + 0.8 * t, x1 = x0 + 0.4;
    for (double y : { -0.4, 0.2, 0.8 })
    {
      s.ring.emplace_back(x1, y);
    }
    for (double y : { 0.8, 0.2, -0.4 })
    {
      s.ring.emplace_back(x0, y);
    }
  }
  s.ring.pop_back(); // the first tooth's foot is on the bar's left edge
  return s;
}

/// The pentagram {5/2}: five edges crossing, its middle wound twice.
Shape Pentagram()
{
  Shape s{ "pentagram", {} };
  for (int i = 0; i < 5; ++i)
  {
    const double a = kPi / 2 + 4 * kPi * i / 5;
    s.ring.emplace_back(std::cos(a), std::sin(a));
  }
  return s;
}

vtkSmartPointer<vtkPolyData> PolygonOf(const Shape& shape)
{
  vtkNew<vtkPoints> points;
  std::vector<vtkIdType> ids;
  for (const auto& [x, y] : shape.ring)
  {
    ids.push_back(points->InsertNextPoint(x, y, 0));
  }
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetPolys(polys);
  return pd;
}

/// Even-odd inside test and the distance to the nearest edge.
bool Inside(const std::vector<std::pair<double, double>>& ring, double x, double y, double& nearest)
{
  bool inside = false;
  nearest = 1e300;
  const size_t n = ring.size();
  for (size_t k = 0, l = n - 1; k < n; l = k++)
  {
    const auto [xa, ya] = ring[l];
    const auto [xb, yb] = ring[k];
    if ((ya > y) != (yb > y) && x < xa + (y - ya) * (xb - xa) / (yb - ya))
    {
      inside = !inside;
    }
    const double dx = xb - xa, dy = yb - ya, len2 = dx * dx + dy * dy;
    const double t = len2 > 0 ? std::clamp(((x - xa) * dx + (y - ya) * dy) / len2, 0.0, 1.0) : 0;
    nearest = std::min(nearest, std::hypot(x - xa - t * dx, y - ya - t * dy));
  }
  return inside;
}

struct Coverage
{
  std::vector<uint16_t> count;
  int64_t polygons = 0; ///< in the mesh drawn
};

Coverage Draw(const Shape& shape, render::PolygonHandling polygons, render::ScanConversion scan,
  render::ScanPrecision precision, render::WorldFrame& frame)
{
  const render::Mesh mesh = render::MeshFromPolyData(PolygonOf(shape), frame, polygons);
  render::RenderOptions opt;
  opt.width = kWidth;
  opt.height = kHeight;
  opt.polygons = polygons;
  opt.scan = scan;
  opt.scanPrecision = precision;
  opt.mode = render::ShadingMode::Gouraud;
  opt.countCoverage = true;
  render::Camera cam;
  cam.parallel = true;
  cam.parallelScale = 1.1 / frame.scale; // the unit shape and a margin, in the local frame
  sl::Lighting<float> light; // coverage only: any light
  light.lightCount = 1;
  light.lights[0].vector = sl::Vec3f(0, 0, 1);
  const render::Image image = sl::test::RenderCpu(mesh, cam, light, sl::Material<float>(), opt);
  return { image.coverage, mesh.NumberOfPolygons() };
}

} // namespace

TEST(DirectPolygonsTest, ConcavePolygonsAreScannedWholeByTheEvenOddRule)
{
  const Shape shapes[] = { Keyhole(24, 0.5), Keyhole(30, 0.2), Star(5, 0.4), Star(12, 0.6),
    Comb(), Pentagram() };
  const std::pair<render::ScanConversion, render::ScanPrecision> scans[] = {
    { render::ScanConversion::Plane, render::ScanPrecision::Float },
    { render::ScanConversion::Incremental, render::ScanPrecision::Float },
    { render::ScanConversion::Incremental, render::ScanPrecision::Double },
  };
  for (const Shape& shape : shapes)
  {
    for (const auto& [scan, precision] : scans)
    {
      SCOPED_TRACE(shape.name + " scan " + std::to_string(static_cast<int>(scan)) +
        std::to_string(static_cast<int>(precision)));
      render::WorldFrame frame;
      const Coverage direct = Draw(
        shape, render::PolygonHandling::Direct, scan, precision, frame);
      const Coverage ears = Draw(
        shape, render::PolygonHandling::Triangulate, scan, precision, frame);
      EXPECT_EQ(direct.polygons, 1) << "kept whole";
      // Split by ear clipping; the pentagram turns one way at every corner
      // and stays whole (fanned, as VTK fans it: no triangles cover it).
      const bool crossing = shape.name == "pentagram";
      EXPECT_EQ(ears.polygons > 1, !crossing);
      // Pixel centre (i + 0.5, j + 0.5) in the world: the parallel view of
      // half-height parallelScale, centred on the frame's centre.
      const double pixel = 2 * 1.1 / kHeight;
      int64_t inside = 0, wrong = 0, twice = 0, differ = 0, middle = 0;
      for (int j = 0; j < kHeight; ++j)
      {
        for (int i = 0; i < kWidth; ++i)
        {
          const double x = frame.center.x + (i + 0.5 - 0.5 * kWidth) * pixel;
          const double y = frame.center.y + (0.5 * kHeight - j - 0.5) * pixel;
          double nearest = 0;
          const bool in = Inside(shape.ring, x, y, nearest);
          const size_t at = static_cast<size_t>(j) * kWidth + i;
          twice += direct.count[at] > 1;
          if (nearest < kEdgeBand * pixel)
          {
            continue;
          }
          inside += in;
          wrong += (direct.count[at] > 0) != in;
          // The pentagram's middle (inner radius cos 72 / cos 36 = 0.38)
          // is wound twice: outside by even-odd.
          middle += crossing && std::hypot(x, y) < 0.3 && direct.count[at] == 0;
          differ += !crossing && (direct.count[at] > 0) != (ears.count[at] > 0);
        }
      }
      EXPECT_GT(inside, 2000);
      EXPECT_EQ(wrong, 0) << "pixels against the exact even-odd coverage";
      EXPECT_EQ(twice, 0);
      EXPECT_EQ(differ, 0) << "direct and ear-clipped coverage";
      if (crossing)
      {
        EXPECT_GT(middle, 500) << "even-odd leaves the middle open";
      }
    }
  }
}

TEST(DirectPolygonsTest, FastPhongAndTriangulateSplitConcavePolygons)
{
  render::RenderOptions opt;
  opt.polygons = render::PolygonHandling::Direct;
  EXPECT_TRUE(render::ScansPolygonsWhole(opt));
  opt.mode = render::ShadingMode::FastPhong; // Taylor form per triangle: fanned
  EXPECT_FALSE(render::ScansPolygonsWhole(opt));
  opt.mode = render::ShadingMode::Phong;
  opt.polygons = render::PolygonHandling::Triangulate;
  EXPECT_FALSE(render::ScansPolygonsWhole(opt));
  // More corners than the renderer takes whole: split in either handling.
  render::WorldFrame frame;
  const render::Mesh big =
    render::MeshFromPolyData(PolygonOf(Keyhole(40, 0.5)), frame, render::PolygonHandling::Direct);
  EXPECT_GT(big.NumberOfPolygons(), 1);
}
