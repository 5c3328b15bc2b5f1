// SPDX-License-Identifier: BSD-3-Clause
// The settings table (shadinglab/render/Settings.h): every row complete and
// consistent, values round-tripping through their text, both spellings of a
// choice accepted, ranges enforced with a message naming the setting.
#include "shadinglab/model/Materials.h"
#include "shadinglab/render/Settings.h"

#include <gtest/gtest.h>

#include <set>

namespace sr = shadinglab::render;

TEST(SettingsTest, EveryRowIsCompleteAndUnique)
{
  std::set<std::string> keys, properties;
  for (const auto& row : sr::SettingsTable())
  {
    EXPECT_FALSE(row.key.empty());
    EXPECT_FALSE(row.property.empty()) << row.key;
    EXPECT_FALSE(row.label.empty()) << row.key;
    EXPECT_FALSE(row.doc.empty()) << row.key;
    EXPECT_NE(row.frontEnds, 0u) << row.key;
    EXPECT_TRUE(row.set && row.get) << row.key;
    EXPECT_TRUE(keys.insert(row.key).second) << "duplicate key " << row.key;
    EXPECT_TRUE(properties.insert(row.property).second) << "duplicate property " << row.property;
    if (row.kind == sr::SettingKind::Choice)
    {
      EXPECT_GE(row.choices.size(), 2u) << row.key;
    }
    if (row.kind == sr::SettingKind::Real || row.kind == sr::SettingKind::Integer)
    {
      EXPECT_LT(row.min, row.max) << row.key;
    }
  }
}

TEST(SettingsTest, EveryDefaultIsInRangeAndRoundTrips)
{
  for (const auto& row : sr::SettingsTable())
  {
    sr::Settings settings;
    const std::string text = sr::DefaultText(row);
    EXPECT_EQ(sr::ApplySettingText(settings, row.key, text), "") << row.key << " = " << text;
    EXPECT_TRUE(sr::SameSettings(settings, sr::Settings{})) << row.key << " = " << text;
  }
}

TEST(SettingsTest, ChoicesTakeBothSpellingsInAnyCase)
{
  sr::Settings a, b, c;
  EXPECT_EQ(sr::ApplySettingText(a, "mode", "fast-phong"), "");
  EXPECT_EQ(sr::ApplySettingText(b, "mode", "Fast Phong"), "");
  EXPECT_EQ(sr::ApplySettingText(c, "mode", "FAST-PHONG"), "");
  EXPECT_EQ(a.render.mode, sr::ShadingMode::FastPhong);
  EXPECT_TRUE(sr::SameSettings(a, b));
  EXPECT_TRUE(sr::SameSettings(a, c));
  sr::Settings gold, Gold;
  EXPECT_EQ(sr::ApplySettingText(gold, "material", "gold"), "");
  EXPECT_EQ(sr::ApplySettingText(Gold, "material", "Gold"), "");
  EXPECT_TRUE(sr::SameSettings(gold, Gold));
  EXPECT_EQ(gold.preset, "gold");
  EXPECT_GT(gold.material.k.x, 0.0); // a conductor
  sr::Settings autoMode;
  EXPECT_EQ(sr::ApplySettingText(autoMode, "mode", "Auto"), "");
  EXPECT_EQ(autoMode.render.mode, sr::ShadingMode::Auto);
  sr::Settings lommel;
  EXPECT_EQ(sr::ApplySettingText(lommel, "model", "lommel-seeliger"), "");
  EXPECT_EQ(lommel.material.model, shadinglab::ReflectanceModel::LommelSeeliger);
}

TEST(SettingsTest, OutOfRangeAndMalformedValuesNameTheSetting)
{
  sr::Settings s;
  const sr::Settings before = s;
  const std::string bad[][2] = { { "max-error", "0" }, { "max-error", "nan" },
    { "ssaa", "2.5" }, { "ssaa", "9" }, { "kd", "1.5" }, { "eta", "1,2" }, { "mode", "goraud" },
    { "m", "0.1,0.2,0.3,0.4,0.5" }, { "light-intensity", "-1" }, { "cull", "maybe" },
    { "threads", "" } };
  for (const auto& [key, value] : bad)
  {
    const std::string problem = sr::ApplySettingText(s, key, value, "--");
    EXPECT_NE(problem.find("--" + key), std::string::npos) << key << "=" << value << ": " << problem;
    EXPECT_EQ(problem.find('\n'), std::string::npos) << problem;
  }
  EXPECT_TRUE(sr::SameSettings(s, before)) << "a refused value changed the settings";
  EXPECT_NE(sr::ApplySettingText(s, "no-such-setting", "1"), "");
}

TEST(SettingsTest, RgbRowsBroadcastOneValue)
{
  sr::Settings s;
  EXPECT_EQ(sr::ApplySettingText(s, "eta", "1.3"), "");
  EXPECT_EQ(s.material.eta.x, 1.3);
  EXPECT_EQ(s.material.eta.z, 1.3);
  EXPECT_EQ(sr::ApplySettingText(s, "eta", "1.1,1.2,1.3"), "");
  EXPECT_EQ(s.material.eta.y, 1.2);
}

TEST(SettingsTest, LobesAreTheLeadingPositiveSlopesAndWeightsAreRelative)
{
  sr::Settings s;
  EXPECT_EQ(sr::ApplySettingText(s, "m", "0.2,0.6,0,0"), "");
  EXPECT_EQ(s.material.lobeCount, 2);
  EXPECT_EQ(sr::ApplySettingText(s, "w", "0.25,0.75,0,0"), "");
  sr::NormalizeLobeWeights(s.material);
  EXPECT_DOUBLE_EQ(s.material.lobes[0].weight, 0.25);
  EXPECT_EQ(sr::ApplySettingText(s, "w", "0.1,0.3"), "");
  sr::NormalizeLobeWeights(s.material);
  EXPECT_DOUBLE_EQ(s.material.lobes[0].weight, 0.25);
  EXPECT_DOUBLE_EQ(s.material.lobes[1].weight, 0.75);
}

TEST(SettingsTest, CliHelpListsEveryCommandLineSetting)
{
  std::string help;
  for (auto group : { sr::SettingGroup::Render, sr::SettingGroup::Lights,
         sr::SettingGroup::Material, sr::SettingGroup::Mesh })
  {
    help += sr::CliHelp(group);
  }
  for (const auto& row : sr::SettingsTable())
  {
    const bool listed = help.find("--" + row.key + " ") != std::string::npos ||
      help.find("--" + row.key + "\n") != std::string::npos;
    EXPECT_EQ(listed, (row.frontEnds & sr::kCli) != 0) << row.key;
  }
}
