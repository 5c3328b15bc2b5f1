// SPDX-License-Identifier: BSD-3-Clause
// The explorer under Xvfb (label gl), one QTest class whose functions live
// by theme: ExplorerGLTest.cxx (the window: camera link, re-rendering only
// what changed, screenshots, user meshes, colour by data, auto panels),
// ExplorerArtifactTests.cxx (the interpolation artifacts' numbers against
// the lecture's formulas), ExplorerMaterialTests.cxx (materials, optics).
#pragma once

#include <QObject>

class ExplorerGLTest : public QObject
{
  Q_OBJECT
private slots:
  void CameraLinkMovesAllPanels();
  void MaterialSliderRerendersOnePanel();
  void EveryScreenshotIsDrawn();
  void MachBandsProfiles();
  void PerspectiveProfiles();
  void MoonProfiles();
  void MetalHighlightsKeepTheirColour();
  void DroppedMeshIsShown();
  void AutoPanelFollowsItsBudget();
  void OrientationDependsOnRotation();
  void LommelSeeligerOnGpuMatchesCpu();
  void UserMeshIsFramedWhateverItsPlaceAndSize();
  void ColourByDataOnBothBackends();
  void MaterialEditorShowsTheModelsParameters();
  void FlatConditionsErrorVanishesForTheCubeOnly();
  void PolarizationSceneShowsBrewster();
  void SpectralSceneShowsTheColourDifference();
  void CreasesAveragedCorrugationShadesFlat();
  void ScanlineInspectorShowsTheRenderersNumbers();
  void WheelChangesAControlOnlyWithItsFocus();
  void ControlsKeepEachOtherAndFold();
  void BrdfPlotShowsEveryLobe();
  void SpectralErrorMapIsFromFloatFrames();
  void HighlightsOnDataFollowTheirControl();
};
