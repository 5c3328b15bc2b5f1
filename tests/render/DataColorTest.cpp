// SPDX-License-Identifier: BSD-3-Clause
// Colour by data and the default lights (docs/model.md section 9): the
// material rule, vtkLightKit's geometry, and the fidelity measure on the
// CPU renderer's frames, each able to fail.
#include "shadinglab/cpu/SoftwareRenderer.h"
#include "shadinglab/model/Materials.h"
#include "shadinglab/render/DataColor.h"
#include "shadinglab/render/Fidelity.h"
#include "shadinglab/render/Scene.h"

#include "AnalyticMeshes.h"
#include "PolyDataMesh.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <cmath>

namespace sl = shadinglab;
using sl::render::Highlights;

TEST(DataColorTest, DataDropsHighlightsAndGreyAmbientUnlessAsked)
{
  const sl::Material<double> plastic; // kd 0.7, ks 0.3, Ra 0.05
  const auto onData = sl::render::MaterialForData(plastic, Highlights::Auto, true);
  EXPECT_DOUBLE_EQ(onData.ks, 0.0);
  EXPECT_DOUBLE_EQ(onData.kd, 1.0); // eq. 9.1: kd + ks
  EXPECT_DOUBLE_EQ(onData.ambient.x, 0.0);
  const auto solid = sl::render::MaterialForData(plastic, Highlights::Auto, false);
  EXPECT_DOUBLE_EQ(solid.ks, plastic.ks);
  EXPECT_DOUBLE_EQ(solid.ambient.y, plastic.ambient.y);
  const auto kept = sl::render::MaterialForData(plastic, Highlights::On, true);
  EXPECT_DOUBLE_EQ(kept.ks, plastic.ks);
  EXPECT_NE(sl::render::DataColorNotice(plastic, Highlights::On, true).find("not data"), std::string::npos);
  const auto off = sl::render::MaterialForData(plastic, Highlights::Off, false);
  EXPECT_DOUBLE_EQ(off.ks, 0.0);
  EXPECT_DOUBLE_EQ(off.ambient.z, plastic.ambient.z); // not on data: Ra stays
  // Idempotent: a front end and the mapper may both apply it.
  const auto twice = sl::render::MaterialForData(onData, Highlights::Auto, true);
  EXPECT_DOUBLE_EQ(twice.kd, onData.kd);
  EXPECT_DOUBLE_EQ(twice.ks, 0.0);
  // A conductor on data: the data colour as its F0 (eq. 9.4), highlights
  // kept, a grey surround; with highlights off, diffuse in the data colour.
  const sl::Material<double> gold = sl::FindMaterialPreset("gold")->material;
  ASSERT_TRUE(gold.IsConductor());
  const auto tinted = sl::render::MaterialForData(gold, Highlights::Auto, true);
  EXPECT_TRUE(tinted.albedoTintsFresnel);
  EXPECT_DOUBLE_EQ(tinted.ks, gold.ks);
  EXPECT_GT(tinted.ambient.x, 0.0);
  EXPECT_NE(sl::render::DataColorNotice(gold, Highlights::Auto, true, "gold").find("Fresnel F0"),
    std::string::npos);
  EXPECT_FALSE(sl::render::MaterialForData(gold, Highlights::Auto, false).albedoTintsFresnel);
  const auto diffuse = sl::render::MaterialForData(gold, Highlights::Off, true);
  EXPECT_FALSE(diffuse.albedoTintsFresnel);
  EXPECT_DOUBLE_EQ(diffuse.ks, 0.0);
  EXPECT_DOUBLE_EQ(diffuse.kd, 1.0);
  // F_Tinted: the data colour at normal incidence, white at grazing.
  const sl::Vec3<double> F0 = gold.Fresnel(1.0), c(0.2, 0.4, 0.9);
  const auto atNormal = sl::F_Tinted(F0, F0, c);
  EXPECT_NEAR(atNormal.x, c.x, 1e-12);
  EXPECT_NEAR(atNormal.z, c.z, 1e-12);
  const auto atGrazing = sl::F_Tinted(gold.Fresnel(0.0), F0, c);
  EXPECT_NEAR(atGrazing.y, 1.0, 1e-9);
}

TEST(DataColorTest, LightKitIsVtkLightKitsAndLightsEveryFacingNormal)
{
  const double bounds[6] = { -1, 1, -1, 1, -1, 1 };
  const sl::render::Camera camera = sl::render::FitCamera(bounds, 30, 20, 1, 1.5, false);
  const sl::Lighting<double> kit = sl::render::LightKit(camera);
  ASSERT_EQ(kit.lightCount, 5);
  // vtkLightKit: key 0.75, fill 0.75 / 3, back 0.75 / 3.5 (two), head 0.75 / 3.
  const double expected[5] = { 0.75, 0.25, 0.75 / 3.5, 0.75 / 3.5, 0.25 };
  for (int k = 0; k < 5; ++k)
  {
    EXPECT_NEAR(kit.lights[k].intensity.x, expected[k], 1e-12) << k;
    EXPECT_EQ(kit.lights[k].intensity.x, kit.lights[k].intensity.z) << "white";
  }
  const sl::Light<double> key = sl::render::CameraLight(camera, 10, 50, 0.75);
  EXPECT_NEAR(sl::Dot(kit.lights[0].vector, key.vector), 1.0, 1e-12);
  // The last light is a headlight: toward the camera.
  const auto toEye = sl::NormalizeOr(camera.position - camera.focalPoint, sl::Vec3<double>(0, 0, 1));
  EXPECT_NEAR(sl::Dot(kit.lights[4].vector, toEye), 1.0, 1e-12);
  // Every normal facing the camera gets light (the single key light left
  // about 40 % of that hemisphere black).
  int unlit = 0, unlitByKey = 0, samples = 0;
  for (int i = 0; i < 40; ++i)
  {
    for (int j = 0; j < 80; ++j)
    {
      const double theta = std::acos(1 - 2 * (i + 0.5) / 40), phi = 2 * sl::kPi<double> * j / 80;
      const sl::Vec3<double> n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
        std::cos(theta));
      if (sl::Dot(n, toEye) <= 1e-3)
      {
        continue;
      }
      ++samples;
      double sum = 0;
      for (int k = 0; k < kit.lightCount; ++k)
      {
        sum += std::max(0.0, sl::Dot(n, kit.lights[k].vector));
      }
      unlit += sum <= 0;
      unlitByKey += sl::Dot(n, sl::render::KeyLight(camera).vector) <= 0;
    }
  }
  EXPECT_EQ(unlit, 0) << "of " << samples;
  EXPECT_GT(unlitByKey, samples / 10) << "the old single light must leave some black";
}

TEST(DataColorTest, FidelityIsZeroWithoutHighlightsAndCountsThem)
{
  // A sphere coloured by its height, drawn by the CPU renderer.
  vtkSmartPointer<vtkPolyData> sphere;
  sphere.TakeReference(sl::datasets::MakeUVSphere(48, 24));
  sl::render::WorldFrame frame;
  sl::render::Mesh mesh = sl::render::MeshFromPolyData(sphere, frame);
  mesh.scalars.resize(static_cast<size_t>(mesh.NumberOfPoints()));
  for (size_t v = 0; v < mesh.scalars.size(); ++v)
  {
    mesh.scalars[v] = mesh.points[3 * v + 1];
  }
  sl::render::ColorMap map;
  ASSERT_TRUE(sl::render::FindColorMap("cool-to-warm", map));
  map.rangeMin = -1;
  map.rangeMax = 1;
  double bounds[6];
  mesh.Bounds(bounds);
  sl::render::Scene scene;
  scene.mesh = &mesh;
  scene.colorMap = &map;
  scene.camera = sl::render::FitCamera(bounds, 20, 30, 1, 1, false);
  scene.lighting = sl::render::LightKit(scene.camera);
  sl::render::RenderOptions options;
  options.width = options.height = 160;
  options.mode = sl::render::ShadingMode::Phong;
  sl::cpu::SoftwareRenderer renderer;
  const sl::Material<double> plastic;
  scene.material = sl::render::MaterialForData(plastic, Highlights::Auto, true);
  const auto honest = sl::render::MeasureColorFidelity(renderer, scene, options);
  EXPECT_GT(honest.covered, 5000);
  EXPECT_EQ(honest.unfaithful, 0);
  scene.material = sl::render::MaterialForData(plastic, Highlights::On, true);
  const auto shiny = sl::render::MeasureColorFidelity(renderer, scene, options);
  EXPECT_GT(shiny.Fraction(), 0.5) << "the grey ambient lifts every pixel off the map";
  scene.material.ambient = sl::Vec3<double>(0, 0, 0);
  const auto highlightsOnly = sl::render::MeasureColorFidelity(renderer, scene, options);
  EXPECT_GT(highlightsOnly.unfaithful, 100) << "the highlights";
  // A metal on data (eq. 9.4): no covered pixel is black, and most are the
  // data colour scaled (the rest: highlights whitening toward grazing).
  scene.material = sl::render::MaterialForData(
    sl::FindMaterialPreset("gold")->material, Highlights::Auto, true);
  options.ssaa = 1;
  const sl::render::Image metal = renderer.Render(scene, options);
  float darkest = 1e30f;
  for (size_t i = 0; i < metal.covered.size(); ++i)
  {
    if (metal.covered[i])
    {
      darkest = std::min(darkest, metal.rgb[3 * i] + metal.rgb[3 * i + 1] + metal.rgb[3 * i + 2]);
    }
  }
  EXPECT_GT(darkest, 0.05f) << "the grey surround in the data colour";
  const auto gold = sl::render::MeasureColorFidelity(renderer, scene, options);
  EXPECT_LT(gold.Fraction(), 0.5) << gold.Fraction();
  // With supersampling the edges where bins mix stay within the tolerance.
  options.ssaa = 3;
  scene.material = sl::render::MaterialForData(plastic, Highlights::Auto, true);
  EXPECT_EQ(sl::render::MeasureColorFidelity(renderer, scene, options).unfaithful, 0);
}
