// SPDX-License-Identifier: BSD-3-Clause
// Numerical stability of the whole pipeline on both backends (label gl):
// the same mesh at any scale and distance renders the same picture after the
// camera fit, and degenerate geometry and extreme parameters never put a NaN
// or an Inf into a pixel (the GPU's framebuffer cannot hold one: there, a
// NaN would show as a pixel unlike the CPU's).
#include "AnalyticMeshes.h"
#include "shadinglab/gl/GpuRenderer.h"
#include "PolyDataMesh.h"
#include "RenderTestUtil.h"
#include "shadinglab/model/Materials.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>

namespace sl = shadinglab;
using sl::render::ShadingMode;

namespace
{

constexpr int W = 160, H = 120;

bool HaveGpu()
{
  std::string why;
  return sl::gl::GpuAvailable(why);
}

/// `mesh` with every point p replaced by offset + scale p, kept in double.
vtkSmartPointer<vtkPolyData> Transformed(vtkPolyData* mesh, double scale, double offset)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(mesh);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    points->InsertNextPoint(offset + scale * p[0], offset + scale * p[1], offset + scale * p[2]);
  }
  out->SetPoints(points);
  return out;
}

/// The CLI's path: the mesh in its local frame, the camera fitted to the
/// world bounds, the key light; both mapped into the local frame.
sl::render::Image Render(sl::render::Renderer& renderer, vtkPolyData* polydata, ShadingMode mode,
  const sl::Material<double>& material)
{
  sl::render::WorldFrame frame;
  const sl::render::Mesh mesh = sl::render::MeshFromPolyData(polydata, frame);
  double bounds[6];
  polydata->GetBounds(bounds);
  sl::render::Camera camera =
    sl::render::FitCamera(bounds, 30, 20, 1.0, static_cast<double>(W) / H, false);
  sl::Lighting<double> lighting;
  lighting.lights[0] = sl::render::KeyLight(camera);
  sl::render::ToLocal(frame, camera);
  sl::render::ToLocal(frame, lighting);
  sl::render::RenderOptions options;
  options.mode = mode;
  options.width = W;
  options.height = H;
  return renderer.Render(sl::render::Scene{ &mesh, camera, lighting, material }, options);
}

sl::Material<double> Plastic()
{
  sl::Material<double> m;
  m.model = sl::ReflectanceModel::BlinnPhong;
  m.kd = 0.6;
  m.ks = 0.4;
  m.shininess = 40;
  return m;
}

/// Largest per-channel difference in 8-bit display values, and the number
/// of pixels covered by one image only.
void Compare(const sl::render::Image& a, const sl::render::Image& b, int& worst, int& coverage)
{
  // In the display values of the transform the GPU image went through.
  const auto display = a.displayApplied ? a.appliedDisplay
    : b.displayApplied                  ? b.appliedDisplay
                                        : sl::render::DisplayTransform::Clamp;
  const auto a8 = a.ToRGB8(display);
  const auto b8 = b.ToRGB8(display);
  worst = 0;
  coverage = 0;
  for (size_t p = 0; p < a.covered.size(); ++p)
  {
    coverage += a.covered[p] != b.covered[p];
    if (a.covered[p] && b.covered[p])
    {
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst, std::abs(int(a8[3 * p + c]) - int(b8[3 * p + c])));
      }
    }
  }
}

} // namespace

TEST(StabilityGLTest, SamePictureAtAnyScaleAndDistanceOnBothBackends)
{
  vtkSmartPointer<vtkPolyData> unit;
  unit.TakeReference(sl::datasets::MakeIcosphere(2));
  std::vector<std::unique_ptr<sl::render::Renderer>> renderers;
  renderers.push_back(std::make_unique<sl::cpu::SoftwareRenderer>());
  if (HaveGpu())
  {
    renderers.push_back(std::make_unique<sl::gl::GpuRenderer>());
  }
  ASSERT_EQ(renderers.size(), 2u) << "no GPU: run under Xvfb";
  for (auto& renderer : renderers)
  {
    for (ShadingMode mode :
      { ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong, ShadingMode::FastPhong })
    {
      const sl::render::Image reference = Render(*renderer, unit, mode, Plastic());
      long covered = 0;
      for (uint8_t c : reference.covered)
      {
        covered += c;
      }
      ASSERT_GT(covered, 2000);
      for (const auto& [scale, offset] : { std::pair<double, double>{ 1e-30, 0.0 }, { 1e-10, 0.0 },
             { 1e10, 0.0 }, { 1e30, 0.0 }, { 1.0, 1e7 }, { 1e-3, 1e7 } })
      {
        const sl::render::Image image =
          Render(*renderer, Transformed(unit, scale, offset), mode, Plastic());
        int worst = 0, coverage = 0;
        Compare(image, reference, worst, coverage);
        EXPECT_LE(worst, 1) << sl::render::BackendName(renderer->GetBackend()) << " "
                            << sl::render::ShadingModeName(mode) << " scale " << scale
                            << " offset " << offset;
        EXPECT_LE(coverage, covered / 1000)
          << sl::render::BackendName(renderer->GetBackend()) << " scale " << scale;
      }
    }
  }
}

TEST(StabilityGLTest, DegenerateGeometryAndExtremeMaterialsStayFinite)
{
  // A fan of slivers (one vertex 1e-12 off the line), near-coincident
  // vertices (1e-15 apart), zero-area triangles (repeated and collinear
  // vertices), and zero-length normals, next to a proper quad.
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  auto add = [&](double x, double y, double z, double nx, double ny, double nz) {
    normals->InsertNextTuple3(nx, ny, nz);
    return points->InsertNextPoint(x, y, z);
  };
  vtkNew<vtkCellArray> polys;
  auto tri = [&](vtkIdType a, vtkIdType b, vtkIdType c) {
    const vtkIdType ids[3] = { a, b, c };
    polys->InsertNextCell(3, ids);
  };
  const vtkIdType q0 = add(-1, -1, 0, 0, 0, 1), q1 = add(1, -1, 0, 0, 0, 1),
                  q2 = add(1, 1, 0, 0, 0, 1), q3 = add(-1, 1, 0, 0, 0, 1);
  tri(q0, q1, q2);
  tri(q0, q2, q3);
  const vtkIdType s0 = add(-1, 1.2, 0, 0, 0, 0), s1 = add(1, 1.2, 0, 0, 0, 0),
                  s2 = add(0, 1.2 + 1e-12, 0, 0, 0, 0);                  // zero normals
  tri(s0, s1, s2);                                                      // sliver
  const vtkIdType c0 = add(0.5, -1.3, 0, 0, 1, 0), c1 = add(0.5 + 1e-15, -1.3, 0, 0, 1, 0),
                  c2 = add(0.5, -1.3 + 1e-15, 0, 0, 1, 0);
  tri(c0, c1, c2);                                                      // near-coincident
  tri(q0, q0, q1);                                                      // repeated vertex
  const vtkIdType l0 = add(-1, -1.5, 0, 1, 0, 0), l1 = add(0, -1.5, 0, 1, 0, 0),
                  l2 = add(1, -1.5, 0, 1, 0, 0);
  tri(l0, l1, l2);                                                      // collinear
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  mesh->GetPointData()->SetNormals(normals);

  std::vector<sl::Material<double>> materials;
  sl::Material<double> sharp = Plastic();
  sharp.shininess = sl::kMaxShininess<double>;
  materials.push_back(sharp);
  sl::Material<double> smooth;
  smooth.model = sl::ReflectanceModel::CookTorrance;
  smooth.kd = 0.2;
  smooth.ks = 0.8;
  smooth.lobes[0] = { 1.0, sl::kMinRoughness<double> };
  materials.push_back(smooth);
  sl::Material<double> conductor = smooth;
  conductor.k = { 3, 3, 3 };
  conductor.lobes[0].m = 1.0;
  materials.push_back(conductor);

  sl::cpu::SoftwareRenderer cpu;
  std::unique_ptr<sl::gl::GpuRenderer> gpu;
  if (HaveGpu())
  {
    gpu = std::make_unique<sl::gl::GpuRenderer>();
  }
  ASSERT_TRUE(gpu) << "no GPU: run under Xvfb";
  for (const auto& material : materials)
  {
    for (ShadingMode mode :
      { ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong, ShadingMode::FastPhong })
    {
      if (!sl::render::SupportsModel(mode, material.model))
      {
        continue;
      }
      const sl::render::Image a = Render(cpu, mesh, mode, material);
      long covered = 0;
      for (size_t p = 0; p < a.covered.size(); ++p)
      {
        covered += a.covered[p];
        for (int c = 0; c < 3; ++c)
        {
          ASSERT_TRUE(std::isfinite(a.rgb[3 * p + c]) && a.rgb[3 * p + c] >= 0.0f)
            << sl::render::ShadingModeName(mode) << " pixel " << p;
        }
      }
      ASSERT_GT(covered, 1000);
      const sl::render::Image b = Render(*gpu, mesh, mode, material);
      int worst = 0, coverage = 0;
      Compare(a, b, worst, coverage);
      // The parity tests' bound for a single pixel (p99 is 0): a NaN on the
      // GPU would show as a pixel far from the CPU's.
      EXPECT_LE(worst, 4) << sl::render::ShadingModeName(mode) << " "
                          << sl::ReflectanceModelName(material.model);
      EXPECT_LE(coverage, covered / 100);
    }
  }
}
