// SPDX-License-Identifier: BSD-3-Clause
// vtkWeightedPolyDataNormals: weights, creases, boundaries, non-manifold
// edges, data carried through, input untouched, accuracy on analytic shapes.
#include "AnalyticMeshes.h"
#include "vtkWeightedPolyDataNormals.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "VertexNormals.h"

namespace
{

vtkSmartPointer<vtkPolyData> MakePolyData(
  const std::vector<double>& pts, const std::vector<std::vector<vtkIdType>>& polys)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  for (size_t i = 0; i < pts.size(); i += 3)
  {
    points->InsertNextPoint(pts[i], pts[i + 1], pts[i + 2]);
  }
  vtkNew<vtkCellArray> cells;
  for (const auto& p : polys)
  {
    cells->InsertNextCell(static_cast<vtkIdType>(p.size()), p.data());
  }
  pd->SetPoints(points);
  pd->SetPolys(cells);
  return pd;
}

vtkSmartPointer<vtkPolyData> Cube()
{
  return MakePolyData({ 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1 },
    { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 1, 2, 6, 5 }, { 2, 3, 7, 6 },
      { 3, 0, 4, 7 } });
}

vtkSmartPointer<vtkPolyData> RunNormals(vtkPolyData* input, int weighting, bool splitting = true,
  vtkWeightedPolyDataNormals** filterOut = nullptr)
{
  static vtkSmartPointer<vtkWeightedPolyDataNormals> keep;
  keep = vtkSmartPointer<vtkWeightedPolyDataNormals>::New();
  keep->SetInputData(input);
  keep->SetWeighting(weighting);
  keep->SetSplitting(splitting);
  keep->Update();
  if (filterOut)
  {
    *filterOut = keep;
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(keep->GetOutput());
  return out;
}

// atan2(|a x b|, a.b): unlike acos(a.b) it stays accurate for nearly equal
// vectors (acos turns float rounding of 3e-8 into 0.014 degrees).
double AngleDeg(const double* a, const double* b)
{
  const double c[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
    a[0] * b[1] - a[1] * b[0] };
  const double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), d) * 180.0 /
    3.14159265358979;
}

} // namespace

TEST(NormalsTest, AreaWeightingReallyWeighsByArea)
{
  // Vertex 0 at the apex of a large triangle tilted one way and a small one
  // tilted the other: uniform averages the unit normals, area weighs by size.
  auto pd = MakePolyData({ 0, 0, 0, 4, 0, 1, 0, 4, 1, -0.5, -0.5, 0.2 },
    { { 0, 1, 2 }, { 0, 3, 1 } });
  auto area = RunNormals(pd, vtkWeightedPolyDataNormals::AREA, false);
  auto uniform = RunNormals(pd, vtkWeightedPolyDataNormals::UNIFORM, false);
  const double* na = area->GetPointData()->GetNormals()->GetTuple3(0);
  double a[3] = { na[0], na[1], na[2] };
  const double* nu = uniform->GetPointData()->GetNormals()->GetTuple3(0);
  // Expected area-weighted normal: normalized sum of the cross products.
  auto cross = [](const double* p0, const double* p1, const double* p2, double* out) {
    const double u[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
    const double v[3] = { p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2] };
    out[0] = u[1] * v[2] - u[2] * v[1];
    out[1] = u[2] * v[0] - u[0] * v[2];
    out[2] = u[0] * v[1] - u[1] * v[0];
  };
  double P[4][3];
  for (int i = 0; i < 4; ++i)
  {
    pd->GetPoint(i, P[i]);
  }
  double c1[3], c2[3];
  cross(P[0], P[1], P[2], c1);
  cross(P[0], P[3], P[1], c2);
  double e[3] = { c1[0] + c2[0], c1[1] + c2[1], c1[2] + c2[2] };
  const double l = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  for (double& x : e)
  {
    x /= l;
  }
  EXPECT_LT(AngleDeg(a, e), 1e-4);
  EXPECT_GT(AngleDeg(a, nu), 5.0); // the two weightings really differ here
}

TEST(NormalsTest, CubeHasTwelveCreasesAndThreeNormalsPerCorner)
{
  vtkWeightedPolyDataNormals* filter = nullptr;
  auto out = RunNormals(Cube(), vtkWeightedPolyDataNormals::AREA, true, &filter);
  EXPECT_EQ(filter->GetNumberOfCreaseEdges(), 12);
  EXPECT_EQ(out->GetNumberOfPoints(), 24);
  EXPECT_EQ(filter->GetNumberOfSplitPoints(), 16);
  // Every output normal is axis aligned.
  vtkDataArray* n = out->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < n->GetNumberOfTuples(); ++i)
  {
    const double* v = n->GetTuple3(i);
    EXPECT_NEAR(std::abs(v[0]) + std::abs(v[1]) + std::abs(v[2]), 1.0, 1e-12);
  }
  ASSERT_NE(out->GetPointData()->GetArray("OriginalPointIds"), nullptr);
  // Without splitting: 8 points, normals along the diagonals.
  auto smooth = RunNormals(Cube(), vtkWeightedPolyDataNormals::AREA, false);
  EXPECT_EQ(smooth->GetNumberOfPoints(), 8);
  const double* d = smooth->GetPointData()->GetNormals()->GetTuple3(0);
  EXPECT_NEAR(d[0], -1 / std::sqrt(3.0), 1e-7); // float output
}

TEST(NormalsTest, ThreadsGiveTheSameBitsAndSplitNumbering)
{
  // A rough terrain of quads: creases everywhere at 30 degrees, so every
  // range of vertices adds split points, numbered across the ranges.
  const int n = 60;
  std::vector<double> points;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> height(0.0, 1.0);
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      points.insert(points.end(), { double(i), double(j), height(random) });
    }
  }
  std::vector<int64_t> offsets{ 0 }, connectivity;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const int64_t a = j * (n + 1) + i;
      connectivity.insert(connectivity.end(), { a, a + 1, a + n + 2, a + n + 1 });
      offsets.push_back(static_cast<int64_t>(connectivity.size()));
    }
  }
  shadinglab::mesh::MeshView mesh;
  mesh.points = points.data();
  mesh.numberOfPoints = static_cast<int64_t>(points.size() / 3);
  mesh.offsets = offsets.data();
  mesh.connectivity = connectivity.data();
  mesh.numberOfPolygons = static_cast<int64_t>(offsets.size() - 1);
  shadinglab::mesh::NormalOptions options;
  options.threads = 1;
  const auto one = shadinglab::mesh::ComputeVertexNormals(mesh, options);
  ASSERT_GT(one.splitPoints, 100);
  for (int threads : { 2, 3, 7 })
  {
    options.threads = threads;
    const auto many = shadinglab::mesh::ComputeVertexNormals(mesh, options);
    EXPECT_EQ(many.normals, one.normals) << threads << " threads";
    EXPECT_EQ(many.originalPointIds, one.originalPointIds) << threads << " threads";
    EXPECT_EQ(many.connectivity, one.connectivity) << threads << " threads";
    EXPECT_EQ(many.creaseEdges, one.creaseEdges);
    EXPECT_EQ(many.boundaryEdges, one.boundaryEdges);
    EXPECT_EQ(many.splitPoints, one.splitPoints);
  }
}

TEST(NormalsTest, FeatureAngleDecidesAndLinesForceCreases)
{
  // A folded strip: two quads meeting at 20 degrees.
  const double t = std::tan(20.0 * 3.14159265358979 / 180.0);
  auto pd = MakePolyData({ 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0, t, 2, 1, t },
    { { 0, 1, 2, 3 }, { 1, 4, 5, 2 } });
  vtkNew<vtkWeightedPolyDataNormals> filter;
  filter->SetInputData(pd);
  filter->SetFeatureAngle(30);
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfCreaseEdges(), 0);
  filter->SetFeatureAngle(10);
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfCreaseEdges(), 1);
  EXPECT_EQ(filter->GetNumberOfSplitPoints(), 2);
  // An explicit feature edge (a line cell) splits even at 30 degrees.
  vtkNew<vtkCellArray> lines;
  const vtkIdType seg[2] = { 1, 2 };
  lines->InsertNextCell(2, seg);
  pd->SetLines(lines);
  filter->SetFeatureAngle(30);
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfCreaseEdges(), 1);
  EXPECT_EQ(filter->GetNumberOfBoundaryEdges(), 6);
}

TEST(NormalsTest, NonManifoldEdgesAreCountedAndSplit)
{
  // Three triangles sharing edge (0, 1).
  auto pd = MakePolyData({ 0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0.2, 0.5, 0, 1 },
    { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } });
  vtkWeightedPolyDataNormals* filter = nullptr;
  auto out = RunNormals(pd, vtkWeightedPolyDataNormals::AREA, true, &filter);
  EXPECT_EQ(filter->GetNumberOfNonManifoldEdges(), 1);
  EXPECT_EQ(out->GetNumberOfPolys(), 3);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    const double* v = out->GetPointData()->GetNormals()->GetTuple3(i);
    ASSERT_TRUE(std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]));
  }
}

TEST(NormalsTest, PointDataIsCarriedAndInputUntouched)
{
  auto cube = Cube();
  vtkNew<vtkFloatArray> temperature;
  temperature->SetName("Temperature");
  for (int i = 0; i < 8; ++i)
  {
    temperature->InsertNextValue(10.0f * i);
  }
  cube->GetPointData()->AddArray(temperature);
  const vtkMTimeType mtime = cube->GetMTime();
  auto out = RunNormals(cube, vtkWeightedPolyDataNormals::ANGLE);
  EXPECT_EQ(cube->GetMTime(), mtime);
  EXPECT_EQ(cube->GetNumberOfPoints(), 8);
  EXPECT_EQ(cube->GetPointData()->GetNormals(), nullptr);
  vtkDataArray* t = out->GetPointData()->GetArray("Temperature");
  vtkDataArray* ids = out->GetPointData()->GetArray("OriginalPointIds");
  ASSERT_NE(t, nullptr);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    EXPECT_EQ(t->GetTuple1(i), 10.0 * ids->GetTuple1(i));
  }
}

TEST(NormalsTest, MaxWeightsAreExactOnTheSphere)
{
  vtkSmartPointer<vtkPolyData> sphere;
  sphere.TakeReference(shadinglab::datasets::MakeIcosphere(3));
  double worst[4] = { 0, 0, 0, 0 };
  for (int w = 0; w < 4; ++w)
  {
    auto out = RunNormals(sphere, w, false);
    vtkDataArray* n = out->GetPointData()->GetNormals();
    vtkDataArray* exact = out->GetPointData()->GetArray("ExactNormal");
    ASSERT_NE(exact, nullptr);
    for (vtkIdType i = 0; i < n->GetNumberOfTuples(); ++i)
    {
      double a[3], b[3];
      n->GetTuple(i, a);
      exact->GetTuple(i, b);
      worst[w] = std::max(worst[w], AngleDeg(a, b));
    }
  }
  // Max 1999: exact for points on a sphere (float output: ~1e-5 degrees).
  EXPECT_LT(worst[vtkWeightedPolyDataNormals::MAX], 1e-3);
  EXPECT_GT(worst[vtkWeightedPolyDataNormals::UNIFORM], worst[vtkWeightedPolyDataNormals::MAX]);
}

TEST(NormalsTest, AbramowitzStegunAcosIsAccurate)
{
  double worst = 0;
  for (int i = -100000; i <= 100000; ++i)
  {
    const double x = i / 100000.0;
    worst = std::max(worst, std::abs(shadinglab::mesh::AcosAbramowitzStegun(x) - std::acos(x)));
  }
  // A&S 4.4.46 bounds the error by 2e-8 rad.
  EXPECT_LT(worst, 2.5e-8);
}

TEST(NormalsTest, PolygonSizesThatSumLikeTrianglesAreNotTakenForTriangles)
{
  // A 2-gon beside a quad has 6 corners for 2 polygons, as two triangles
  // would: the crease pass must still find each corner's own polygon. The
  // quad lies in z = 0; the 2-gon's points stand above it, so a corner
  // filed under the wrong polygon would tilt the quad's normals.
  const std::vector<double> pts{ 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1 };
  const std::vector<int64_t> offsets{ 0, 2, 6 };
  const std::vector<int64_t> conn{ 4, 5, 0, 1, 2, 3 };
  const shadinglab::mesh::MeshView mesh{ pts.data(), 6, offsets.data(), conn.data(), 2 };
  for (auto w : { shadinglab::mesh::NormalWeighting::Uniform, shadinglab::mesh::NormalWeighting::Area,
         shadinglab::mesh::NormalWeighting::Angle, shadinglab::mesh::NormalWeighting::Max })
  {
    shadinglab::mesh::NormalOptions opt;
    opt.weighting = w;
    const auto r = shadinglab::mesh::ComputeVertexNormals(mesh, opt);
    ASSERT_EQ(r.normals.size(), 18u);
    for (int v = 0; v < 6; ++v)
    {
      // The quad's corners: its normal; the 2-gon's points: no usable face.
      EXPECT_NEAR(r.normals[3 * v], 0.0, 1e-12) << v;
      EXPECT_NEAR(r.normals[3 * v + 1], 0.0, 1e-12) << v;
      EXPECT_NEAR(r.normals[3 * v + 2], 1.0, 1e-12) << v;
    }
    EXPECT_EQ(r.boundaryEdges, 4); // the quad's four edges
  }
}

TEST(NormalsTest, AngleAndMaxTrianglePathsMatchTheGeneralCornerFormula)
{
  // Quads go through the general per-corner code, triangles through the
  // shared-edge fast path: a quad mesh and its triangulation with the same
  // geometry (planar quads split along a diagonal) must agree on a sphere
  // with Max weights up to the diagonal's contribution... simpler and exact:
  // compare the fast path against the corner formula on random triangles.
  std::vector<double> pts;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 300; ++i)
  {
    pts.push_back(u(rng));
  }
  std::vector<int64_t> offsets{ 0 }, conn;
  for (int t = 0; t + 2 < 100; t += 3)
  {
    conn.insert(conn.end(), { t, t + 1, t + 2 });
    offsets.push_back(static_cast<int64_t>(conn.size()));
  }
  shadinglab::mesh::MeshView mesh{ pts.data(), 100, offsets.data(), conn.data(),
    static_cast<int64_t>(offsets.size() - 1) };
  for (auto w : { shadinglab::mesh::NormalWeighting::Angle, shadinglab::mesh::NormalWeighting::Max })
  {
    std::vector<double> fast;
    shadinglab::mesh::ComputeVertexNormalsNoSplit(mesh, w, fast);
    shadinglab::mesh::NormalOptions opt;
    opt.weighting = w;
    opt.splitting = false;
    const auto general = shadinglab::mesh::ComputeVertexNormals(mesh, opt);
    for (size_t i = 0; i < 3 * 99; ++i)
    {
      // Angle: the batched loop's atan2 polynomial (1e-8 rad) against the
      // corner formula's A&S acos (2e-8 rad); Max: the same formula through
      // other arithmetic. Agreement to 1e-7.
      EXPECT_NEAR(fast[i], general.normals[i], 1e-7) << i;
    }
  }
}

TEST(NormalsTest, AngleWeightsAgreeOnBothSimdWidthsAndWithTheCornerFormula)
{
  // 1000 random triangles (batches of 256 and a tail) with a quad every
  // 97th polygon (the run of triangles is cut there): the AVX2 and SSE2
  // builds of the batched loop give the same normals, and both match the
  // general per-corner formula (ComputeVertexNormals without splitting).
  std::vector<double> pts;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 3 * 400; ++i)
  {
    pts.push_back(u(rng));
  }
  std::uniform_int_distribution<int64_t> vertex(0, 399);
  std::vector<int64_t> offsets{ 0 }, conn;
  for (int p = 0; p < 1000; ++p)
  {
    const int corners = p % 97 == 50 ? 4 : 3;
    for (int k = 0; k < corners; ++k)
    {
      conn.push_back(vertex(rng));
    }
    offsets.push_back(static_cast<int64_t>(conn.size()));
  }
  shadinglab::mesh::MeshView mesh{ pts.data(), 400, offsets.data(), conn.data(), 1000 };
  std::vector<double> wide, narrow;
  shadinglab::mesh::SetWideSimd(true);
  shadinglab::mesh::ComputeVertexNormalsNoSplit(mesh, shadinglab::mesh::NormalWeighting::Angle, wide);
  shadinglab::mesh::SetWideSimd(false);
  shadinglab::mesh::ComputeVertexNormalsNoSplit(mesh, shadinglab::mesh::NormalWeighting::Angle, narrow);
  shadinglab::mesh::SetWideSimd(true);
  shadinglab::mesh::NormalOptions opt;
  opt.weighting = shadinglab::mesh::NormalWeighting::Angle;
  opt.splitting = false;
  const auto general = shadinglab::mesh::ComputeVertexNormals(mesh, opt);
  ASSERT_EQ(general.normals.size(), wide.size()); // nothing split
  for (size_t i = 0; i < wide.size(); ++i)
  {
    EXPECT_DOUBLE_EQ(wide[i], narrow[i]) << i;
    // The batched loop's atan2 polynomial (1e-8 rad) against the corner
    // formula's A&S acos (2e-8 rad); the batched loop takes the third angle
    // as pi minus the other two, so its error there is up to 2e-8 rad: 2e-7
    // on a normalized component of these random slivers (measured worst
    // 1.04e-7 with A&S acos on both sides).
    EXPECT_NEAR(wide[i], general.normals[i], 2e-7) << i;
  }
}

// Filters never modify their input, its modification time included (a moved
// time re-executes every pipeline downstream of it): split or not, on the
// input or on a shallow copy of it (the mapper's and the CPU renderer's use).
TEST(NormalsTest, InputKeepsItsModificationTime)
{
  for (const double featureAngle : { 30.0, 180.0 })
  {
    vtkSmartPointer<vtkPolyData> mesh;
    mesh.TakeReference(shadinglab::datasets::MakeIcosphere(2));
    const vtkMTimeType before = mesh->GetMTime();
    for (const bool viaCopy : { false, true })
    {
      vtkNew<vtkPolyData> copy;
      copy->ShallowCopy(mesh);
      vtkNew<vtkWeightedPolyDataNormals> normals;
      normals->SetInputData(viaCopy ? copy.GetPointer() : mesh.GetPointer());
      normals->SetFeatureAngle(featureAngle);
      normals->ConsistencyOn();
      normals->Update();
      ASSERT_NE(normals->GetOutput()->GetPointData()->GetNormals(), nullptr);
      EXPECT_EQ(mesh->GetMTime(), before) << featureAngle << " " << viaCopy;
    }
  }
}

// Float points read in place (FloatMeshView: a file's points, no double
// copy) and 32-bit ids read in place (NarrowMeshView, FloatNarrowMeshView:
// a fast reader's cells) give the normals of the double, 64-bit copy bit
// for bit: the split
// points, their numbering and the moved corners too, in every weighting,
// with and without creases, on the batched angle path and the general one,
// quads and pentagons among the triangles.
TEST(NormalsTest, FloatPointsAndNarrowIdsInPlaceGiveTheWideCopysBits)
{
  namespace slm = shadinglab::mesh;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const int64_t n = 30; // a noisy 30 x 30 height field, 3 polygon sizes
  std::vector<float> floats;
  for (int64_t j = 0; j < n; ++j)
  {
    for (int64_t i = 0; i < n; ++i)
    {
      // Centred, jittered: coordinates change sign between neighbours, so
      // their differences round in float (not in double).
      floats.insert(floats.end(), { (float(i - n / 2) + 0.4f * u(rng)) / 7.0f,
                                    (float(j - n / 2) + 0.4f * u(rng)) / 7.0f, 0.3f * u(rng) });
    }
  }
  std::vector<int64_t> offsets{ 0 }, conn;
  for (int64_t j = 0; j + 1 < n; ++j)
  {
    for (int64_t i = 0; i + 1 < n; ++i)
    {
      const int64_t a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
      if ((i + j) % 11 == 0)
      {
        conn.insert(conn.end(), { a, b, c, d });
        offsets.push_back(static_cast<int64_t>(conn.size()));
        continue;
      }
      conn.insert(conn.end(), { a, b, c });
      offsets.push_back(static_cast<int64_t>(conn.size()));
      conn.insert(conn.end(), { a, c, d });
      offsets.push_back(static_cast<int64_t>(conn.size()));
    }
  }
  const std::vector<double> doubles(floats.begin(), floats.end());
  const int64_t polygons = static_cast<int64_t>(offsets.size()) - 1;
  const slm::MeshView wide{ doubles.data(), n * n, offsets.data(), conn.data(), polygons };
  const slm::FloatMeshView inPlace{ floats.data(), n * n, offsets.data(), conn.data(), polygons };
  // The same ids in 32 bits (a fast reader's cells), with either points.
  const std::vector<int32_t> offsets32(offsets.begin(), offsets.end());
  const std::vector<int32_t> conn32(conn.begin(), conn.end());
  const slm::NarrowMeshView narrow{ doubles.data(), n * n, offsets32.data(), conn32.data(), polygons };
  const slm::FloatNarrowMeshView floatNarrow{ floats.data(), n * n, offsets32.data(), conn32.data(),
    polygons };
  for (const auto w : { slm::NormalWeighting::Uniform, slm::NormalWeighting::Area,
         slm::NormalWeighting::Angle, slm::NormalWeighting::Max })
  {
    for (const double angle : { 20.0, 180.0 })
    {
      slm::NormalOptions opt;
      opt.weighting = w;
      opt.featureAngle = angle;
      const slm::NormalResult a = slm::ComputeVertexNormals(wide, opt);
      if (angle < 90)
      {
        EXPECT_GT(a.splitPoints, 0); // creases were split
      }
      for (const slm::NormalResult& b : { slm::ComputeVertexNormals(inPlace, opt),
             slm::ComputeVertexNormals(narrow, opt), slm::ComputeVertexNormals(floatNarrow, opt) })
      {
        EXPECT_EQ(a.normals, b.normals) << static_cast<int>(w) << " " << angle;
        EXPECT_EQ(a.originalPointIds, b.originalPointIds);
        EXPECT_EQ(a.connectivity, b.connectivity);
        EXPECT_EQ(a.creaseEdges, b.creaseEdges);
      }
    }
    std::vector<double> a, b, c, d;
    slm::ComputeVertexNormalsNoSplit(wide, w, a);
    slm::ComputeVertexNormalsNoSplit(inPlace, w, b);
    slm::ComputeVertexNormalsNoSplit(narrow, w, c);
    slm::ComputeVertexNormalsNoSplit(floatNarrow, w, d);
    EXPECT_EQ(a, b) << static_cast<int>(w);
    EXPECT_EQ(a, c) << static_cast<int>(w);
    EXPECT_EQ(a, d) << static_cast<int>(w);
  }
}
