// SPDX-License-Identifier: BSD-3-Clause
// Ear clipping (mesh/core/PolygonTriangulation.h) against an exact
// point-in-polygon coverage: keyholes, stars, combs, collinear runs and
// repeated corners, in any winding and plane; and the GL path's copy with
// concave polygons split (WithConcavePolygonsSplit), cell data kept.
#include "MeshArrays.h"
#include "PolygonTriangulation.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace sl = shadinglab;

namespace
{
using Ring = std::vector<sl::Vec3<double>>;
constexpr double kPi = 3.14159265358979323846;

/// A disc of radius 1 with a hole of radius r, cut open along +x: outer
/// circle counter-clockwise, the slit in, the hole clockwise, the slit out.
Ring Keyhole(int n, double r)
{
  Ring ring;
  for (int i = 0; i <= n; ++i)
  {
    ring.push_back({ std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n), 0 });
  }
  for (int i = 0; i <= n; ++i)
  {
    ring.push_back({ r * std::cos(-2 * kPi * i / n), r * std::sin(-2 * kPi * i / n), 0 });
  }
  return ring;
}

Ring Star(int spikes, double inner)
{
  Ring ring;
  for (int i = 0; i < 2 * spikes; ++i)
  {
    const double a = kPi * i / spikes, r = i % 2 ? inner : 1.0;
    ring.push_back({ r * std::cos(a), r * std::sin(a), 0 });
  }
  return ring;
}

/// A comb: a bar along the bottom with `teeth` teeth upward, each side of
/// each tooth a collinear run of `run` corners.
Ring Comb(int teeth, int run)
{
  Ring ring{ { 0, 0, 0 }, { 2.0 * teeth - 1, 0, 0 } };
  for (int t = teeth - 1; t >= 0; --t)
  {
    const double x0 = 2.0 * t, x1 = x0 + 1;
    for (int k = 0; k <= run; ++k)
    {
      ring.push_back({ x1, 0.5 + 2.0 * k / run, 0 }); // up the right side
    }
    for (int k = 0; k <= run; ++k)
    {
      ring.push_back({ x0, 2.5 - 2.0 * k / run, 0 }); // down the left side
    }
  }
  ring.pop_back();           // the last tooth's foot is the bar's corner
  ring.push_back({ 0, 0.5, 0 });
  return ring;
}

/// Even-odd point in the polygon's (x, y) projection.
bool Inside(const Ring& ring, double x, double y)
{
  bool in = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
  {
    const auto &a = ring[i], &b = ring[j];
    if ((a.y > y) != (b.y > y) && x < (b.x - a.x) * (y - a.y) / (b.y - a.y) + a.x)
    {
      in = !in;
    }
  }
  return in;
}

double Orient(const sl::Vec3<double>& a, const sl::Vec3<double>& b, const sl::Vec3<double>& c)
{
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/// Triangulates `ring` (placed by `place`, then read back in its plane)
/// and checks, on a grid of sample points, that each lies in exactly one
/// triangle when the polygon holds it and in none otherwise.
void ExpectExactCover(const Ring& ring, const std::string& what, bool reversed = false,
  bool tilted = false)
{
  Ring placed = ring;
  if (reversed)
  {
    placed.assign(ring.rbegin(), ring.rend());
  }
  // Tilted: the plane z = 0.3 x + 0.2 y (the projection onto xy is the ring).
  for (auto& p : placed)
  {
    p.z = tilted ? 0.3 * p.x + 0.2 * p.y : 0.0;
  }
  std::vector<int64_t> tris;
  ASSERT_TRUE(sl::mesh::TriangulatePolygon(static_cast<int64_t>(placed.size()),
    [&](int64_t k) { return placed[static_cast<size_t>(k)]; }, tris))
    << what;
  ASSERT_EQ(tris.size() % 3, 0u);
  const double winding = reversed ? -1.0 : 1.0;
  for (size_t t = 0; t < tris.size(); t += 3)
  {
    EXPECT_GT(winding * Orient(placed[tris[t]], placed[tris[t + 1]], placed[tris[t + 2]]), 0)
      << what << ": triangle " << t / 3 << " keeps the polygon's winding";
  }
  double lo[2] = { 1e9, 1e9 }, hi[2] = { -1e9, -1e9 };
  for (const auto& p : ring)
  {
    lo[0] = std::min(lo[0], p.x), lo[1] = std::min(lo[1], p.y);
    hi[0] = std::max(hi[0], p.x), hi[1] = std::max(hi[1], p.y);
  }
  int wrong = 0, inside = 0;
  // Samples offset by irrational fractions of a cell: none lies exactly on
  // an edge or a diagonal, where a strict inside test would count it 0 times.
  const int grid = 157;
  const double dx = 0.5 + 1e-3 * std::sqrt(2.0), dy = 0.5 + 1e-3 * std::sqrt(3.0);
  for (int i = 0; i < grid; ++i)
  {
    for (int j = 0; j < grid; ++j)
    {
      const double x = lo[0] + (hi[0] - lo[0]) * (i + dx) / grid;
      const double y = lo[1] + (hi[1] - lo[1]) * (j + dy) / grid;
      const sl::Vec3<double> p{ x, y, 0 };
      int covering = 0;
      for (size_t t = 0; t < tris.size(); t += 3)
      {
        const auto &a = placed[tris[t]], &b = placed[tris[t + 1]], &c = placed[tris[t + 2]];
        const double s = winding;
        covering += s * Orient(a, b, p) > 0 && s * Orient(b, c, p) > 0 && s * Orient(c, a, p) > 0;
      }
      const bool in = Inside(ring, x, y);
      inside += in;
      wrong += covering != (in ? 1 : 0);
    }
  }
  EXPECT_GT(inside, 100) << what;
  EXPECT_EQ(wrong, 0) << what << ": samples covered other than once inside, never outside";
}
} // namespace

TEST(PolygonTriangulationTest, KeyholesStarsCombsAndCollinearRunsAreCoveredExactly)
{
  for (bool reversed : { false, true })
  {
    for (bool tilted : { false, true })
    {
      const std::string how =
        std::string(reversed ? " clockwise" : "") + (tilted ? " in a tilted plane" : "");
      ExpectExactCover(Keyhole(32, 0.5), "keyhole 66" + how, reversed, tilted);
      ExpectExactCover(Keyhole(7, 0.8), "thin keyhole" + how, reversed, tilted);
      ExpectExactCover(Star(5, 0.38), "five-pointed star" + how, reversed, tilted);
      ExpectExactCover(Star(24, 0.9), "24-pointed star" + how, reversed, tilted);
      ExpectExactCover(Comb(6, 5), "comb with collinear runs" + how, reversed, tilted);
    }
  }
  // Repeated corners and a square whose sides are runs of collinear corners.
  Ring square;
  for (int k = 0; k < 40; ++k)
  {
    const int side = k / 10, step = k % 10;
    const double s = step / 10.0;
    const double xy[4][2] = { { s, 0 }, { 1, s }, { 1 - s, 1 }, { 0, 1 - s } };
    square.push_back({ xy[side][0], xy[side][1], 0 });
    if (step == 3)
    {
      square.push_back(square.back()); // a corner given twice
    }
  }
  ExpectExactCover(square, "square of collinear runs and repeated corners");
}

TEST(PolygonTriangulationTest, PolygonsWithoutAreaGiveNoTriangles)
{
  std::vector<int64_t> tris;
  const Ring line{ { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 3, 0, 0 } };
  EXPECT_FALSE(sl::mesh::TriangulatePolygon(4, [&](int64_t k) { return line[k]; }, tris));
  const Ring point{ { 1, 1, 1 }, { 1, 1, 1 }, { 1, 1, 1 } };
  EXPECT_FALSE(sl::mesh::TriangulatePolygon(3, [&](int64_t k) { return point[k]; }, tris));
  const Ring bad{ { 0, 0, 0 }, { 1, 0, 0 }, { std::nan(""), 1, 0 }, { 0, 1, 0 } };
  EXPECT_FALSE(sl::mesh::TriangulatePolygon(4, [&](int64_t k) { return bad[k]; }, tris));
  EXPECT_TRUE(tris.empty());
}

TEST(PolygonTriangulationTest, ConcavePolygonsSplitForTheGlPathKeepCellData)
{
  // A keyhole and a convex quad, each with a cell value.
  const Ring keyhole = Keyhole(16, 0.4);
  vtkNew<vtkPoints> points;
  for (const auto& p : keyhole)
  {
    points->InsertNextPoint(p.x, p.y, p.z);
  }
  const vtkIdType q = points->GetNumberOfPoints();
  points->InsertNextPoint(3, 0, 0);
  points->InsertNextPoint(4, 0, 0);
  points->InsertNextPoint(4, 1, 0);
  points->InsertNextPoint(3, 1, 0);
  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> ids(keyhole.size());
  for (size_t k = 0; k < ids.size(); ++k)
  {
    ids[k] = static_cast<vtkIdType>(k);
  }
  polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  const vtkIdType quad[4] = { q, q + 1, q + 2, q + 3 };
  polys->InsertNextCell(4, quad);
  vtkNew<vtkPolyData> input;
  input->SetPoints(points);
  input->SetPolys(polys);
  vtkNew<vtkIntArray> label;
  label->SetName("label");
  label->InsertNextValue(7);
  label->InsertNextValue(9);
  input->GetCellData()->AddArray(label);
  const vtkMTimeType before = input->GetMTime();

  int64_t split = 0;
  vtkSmartPointer<vtkPolyData> out = sl::mesh::WithConcavePolygonsSplit(input, &split);
  EXPECT_EQ(split, 1);
  ASSERT_NE(out.Get(), input.Get());
  EXPECT_EQ(input->GetNumberOfPolys(), 2) << "filters never modify their input";
  EXPECT_EQ(input->GetMTime(), before);
  // 34 corners, two repeated positions: 34 - 2 triangles, plus the quad.
  EXPECT_EQ(out->GetNumberOfPolys(), static_cast<vtkIdType>(keyhole.size()) - 2 + 1);
  auto* labels = vtkIntArray::SafeDownCast(out->GetCellData()->GetArray("label"));
  ASSERT_NE(labels, nullptr);
  ASSERT_EQ(labels->GetNumberOfTuples(), out->GetNumberOfPolys());
  for (vtkIdType c = 0; c + 1 < out->GetNumberOfPolys(); ++c)
  {
    EXPECT_EQ(labels->GetValue(c), 7) << c;
  }
  EXPECT_EQ(labels->GetValue(out->GetNumberOfPolys() - 1), 9);
  // All convex: the input itself, nothing copied.
  vtkNew<vtkPolyData> convex;
  convex->SetPoints(points);
  vtkNew<vtkCellArray> one;
  one->InsertNextCell(4, quad);
  convex->SetPolys(one);
  EXPECT_EQ(sl::mesh::WithConcavePolygonsSplit(convex).Get(), convex.Get());
}
