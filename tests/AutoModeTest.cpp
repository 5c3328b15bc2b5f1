// SPDX-License-Identifier: BSD-3-Clause
// The auto mode's cost model (docs/model.md eq. 4.2): the orderings the
// choice depends on, which the first fit got wrong.
#include "shadinglab/model/Materials.h"
#include "shadinglab/render/AutoMode.h"

#include <gtest/gtest.h>

namespace sl = shadinglab;
using sl::render::ShadingMode;

namespace
{

/// A view of a mid-size mesh at 320x240: 2,208 triangles over 16,000 pixels
/// (the held-out flattened ellipsoid whose auto choice was Phong).
sl::render::ViewPredictors MidSizeView()
{
  sl::render::ViewPredictors view;
  view.triangles = 2208;
  view.visibleTriangles = 1100;
  view.frontPixels = 16000;
  view.trianglePixels = 16000.0 / 1100;
  view.normalSpread = 0.17;
  return view;
}

} // namespace

TEST(AutoModeTest, GouraudIsCheaperThanPhongOnMidSizeMeshesForEveryModelClass)
{
  // Measured side by side (held-out check, 2026-11-25, SIMD Phong and kept
  // threads): Gouraud 0.26 ms, Phong 0.41 ms with a Cook-Torrance
  // dielectric (the first fit predicted the reverse); with gold 0.35 and
  // 0.46 ms.
  const sl::render::ViewPredictors view = MidSizeView();
  for (const char* preset : { "plastic", "gold" })
  {
    const sl::Material<double> ct = sl::FindMaterialPreset(preset)->material;
    ASSERT_EQ(ct.model, sl::ReflectanceModel::CookTorrance);
    EXPECT_LT(sl::render::PredictCost(ShadingMode::Gouraud, view, ct),
      sl::render::PredictCost(ShadingMode::Phong, view, ct))
      << preset;
  }
  sl::Material<double> blinn;
  blinn.model = sl::ReflectanceModel::BlinnPhong;
  EXPECT_LT(sl::render::PredictCost(ShadingMode::Gouraud, view, blinn),
    sl::render::PredictCost(ShadingMode::Phong, view, blinn));
}

TEST(AutoModeTest, ConductorsCostWhatDielectricsCostInEveryMode)
{
  // The conductor Fresnel in real arithmetic (docs/model.md eq. 1.9) costs
  // about what the dielectric one does: measured (two runs of the study,
  // 2026-11-25, conductor / dielectric frame time over matching
  // configurations) median 1.00 in flat, 1.01 in Gouraud, 1.00 in Phong
  // (72 pairs each under 100k triangles; 0.99-1.02 over 6 pairs above).
  // With the complex form it was 1.1x in Phong and 1.7x in Gouraud on
  // 38,400 triangles, and the cost model said so; it must not now.
  const sl::render::ViewPredictors view = MidSizeView();
  const sl::Material<double> gold = sl::FindMaterialPreset("gold")->material;
  const sl::Material<double> plastic = sl::FindMaterialPreset("plastic")->material;
  ASSERT_TRUE(gold.IsConductor());
  ASSERT_FALSE(plastic.IsConductor());
  sl::render::ViewPredictors fine = view;
  fine.triangles = 200000;
  for (const auto& v : { view, fine })
  {
    for (const ShadingMode mode : { ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong })
    {
      const double ratio = sl::render::PredictCost(mode, v, gold) /
        sl::render::PredictCost(mode, v, plastic);
      EXPECT_GT(ratio, 0.85) << static_cast<int>(mode) << " " << v.triangles;
      EXPECT_LT(ratio, 1.15) << static_cast<int>(mode) << " " << v.triangles;
    }
  }
}
