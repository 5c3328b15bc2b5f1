// SPDX-License-Identifier: BSD-3-Clause
// The explorer's controls dock: the selected panel's mode, backend,
// interpolation and material; the light; the preparation of the user's
// mesh; the plot and scene parameters.
#include "MainWindow.h"

#include "BrdfPlot.h"
#include "ComparisonWidget.h"
#include "MaterialEditor.h"
#include "ColorLegend.h"
#include "ProfilePlot.h"
#include "SettingControls.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

namespace shadinglab::gui
{

namespace
{

QSlider* MakeSlider(int lo, int hi, int value)
{
  auto* slider = new QSlider(Qt::Horizontal);
  slider->setRange(lo, hi);
  slider->setValue(value);
  return slider;
}

} // namespace

/// The selected panel's mode, error budget, backend, interpolation and scan.
QGroupBox* MainWindow::BuildPanelBox()
{
  auto* panelBox = new QGroupBox("Panel (click a panel to select it)");
  auto* panelForm = new QFormLayout(panelBox);
  this->PanelLabel = new QLabel;
  this->PanelLabel->setWordWrap(true);
  panelForm->addRow(this->PanelLabel);
  // Choices, ranges and tooltips from the settings table.
  this->Mode = widgets::MakeSettingComboBox("mode");
  panelForm->addRow("Shading", this->Mode);
  this->MaxError = widgets::MakeSettingSpinBox("max-error");
  this->MaxError->setSingleStep(0.5);
  this->MaxError->setEnabled(false); // until an auto panel is selected
  panelForm->addRow("Max error (1/255)", this->MaxError);
  connect(this->MaxError, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
    &MainWindow::OnPanelEdited);
  this->Backend = new QComboBox;
  this->Backend->addItem("GPU (ShadingLab mapper)", static_cast<int>(render::Backend::GPU));
  this->Backend->addItem("CPU (software renderer)", static_cast<int>(render::Backend::CPU));
  // (Short labels: the longest item sets the dock's width.)
  this->Backend->addItem("Auto", static_cast<int>(render::Backend::Auto));
  this->Backend->setToolTip(QString::fromStdString(render::FindSetting("backend")->doc));
  panelForm->addRow("Backend", this->Backend);
  this->Interpolation = widgets::MakeSettingComboBox("interp");
  panelForm->addRow("Interpolation", this->Interpolation);
  this->Scan = widgets::MakeSettingComboBox("scan");
  panelForm->addRow("Scan (CPU)", this->Scan);
  this->ScanPrecision = widgets::MakeSettingComboBox("scan-precision");
  panelForm->addRow("Scan precision", this->ScanPrecision);
  return panelBox;
}

/// Colour by data: the mesh's arrays and ParaView's colour maps, for every panel.
QGroupBox* MainWindow::BuildColorBox()
{
  // Colour by data (every panel): the mesh's arrays, ParaView's colour maps.
  auto* colorBox = new QGroupBox("Colour by data (all panels)");
  auto* colorForm = new QFormLayout(colorBox);
  this->ColorBy = new QComboBox;
  this->ColorBy->setToolTip(widgets::SettingToolTip("color-by"));
  colorForm->addRow("Array", this->ColorBy);
  this->ColorMapChoice = widgets::MakeSettingComboBox("colormap");
  colorForm->addRow("Colour map", this->ColorMapChoice);
  auto* highlights = widgets::MakeSettingComboBox("highlights");
  colorForm->addRow("Highlights", highlights);
  connect(highlights, QOverload<int>::of(&QComboBox::activated), this, [this](int index) {
    this->View->View().highlights = render::kHighlightModes[index].value;
    this->View->RenderAll();
  });
  this->Legend = new widgets::ColorLegend;
  colorForm->addRow(this->Legend);
  for (QComboBox* box : { this->ColorBy, this->ColorMapChoice })
  {
    connect(box, QOverload<int>::of(&QComboBox::activated), this, [this] { this->ApplyColorBy(); });
  }
  for (QComboBox* box :
    { this->Mode, this->Backend, this->Interpolation, this->Scan, this->ScanPrecision })
  {
    connect(box, QOverload<int>::of(&QComboBox::activated), this, &MainWindow::OnPanelEdited);
  }
  return colorBox;
}

/// The selected panel's material (the MaterialEditor).
QGroupBox* MainWindow::BuildMaterialBox()
{
  auto* materialBox = new QGroupBox("Material of the panel");
  auto* materialLayout = new QVBoxLayout(materialBox);
  materialLayout->addWidget(this->Editor);
  connect(this->Editor, &widgets::MaterialEditor::materialChanged, this,
    &MainWindow::OnPanelEdited);
  return materialBox;
}

/// The light, relative to the view, for every panel.
QGroupBox* MainWindow::BuildLightBox()
{
  auto* lightBox = new QGroupBox("Light (relative to the view; all panels)");
  auto* lightForm = new QFormLayout(lightBox);
  this->LightAzimuth = MakeSlider(-90, 90, -25);
  this->LightElevation = MakeSlider(-90, 90, 25);
  this->LightAzimuth->setObjectName("lightAzimuth");
  this->LightElevation->setObjectName("lightElevation");
  lightForm->addRow("Azimuth (deg)", this->LightAzimuth);
  lightForm->addRow("Elevation (deg)", this->LightElevation);
  this->LightIntensity = widgets::MakeSettingSpinBox("light-intensity");
  this->LightIntensity->setSingleStep(0.1);
  lightForm->addRow("Intensity I_L", this->LightIntensity);
  this->LightSolidAngle = widgets::MakeSettingSpinBox("light-solid-angle");
  this->LightSolidAngle->setSingleStep(0.1);
  lightForm->addRow("Solid angle dw (sr)", this->LightSolidAngle);
  connect(this->LightSolidAngle, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
    [this](double solidAngle) {
      if (!this->Updating)
      {
        this->View->SetLightSolidAngle(solidAngle);
      }
    });
  connect(this->LightIntensity, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
    [this](double intensity) {
      if (!this->Updating)
      {
        this->View->SetLightIntensity(intensity);
      }
    });

  for (QSlider* slider : { this->LightAzimuth, this->LightElevation })
  {
    connect(slider, &QSlider::valueChanged, this, [this] {
      if (!this->Updating)
      {
        this->View->SetLight(this->LightAzimuth->value(), this->LightElevation->value());
      }
    });
  }
  return lightBox;
}

/// The preparation of the user's mesh (normals, creases, subdivision, repair).
QGroupBox* MainWindow::BuildMeshBox()
{
  auto* meshBox = new QGroupBox("Mesh preparation (your mesh)");
  meshBox->setToolTip("Applies to your mesh in the scenes that show it: modes, silhouette, moon, metal");
  auto* meshForm = new QFormLayout(meshBox);
  this->Weighting = new QComboBox;
  for (const char* name : { "uniform", "area", "angle", "max" })
  {
    this->Weighting->addItem(name);
  }
  this->Weighting->setCurrentText(mesh::NormalWeightingName(this->Options.preparation.weighting));
  meshForm->addRow("Normal weighting", this->Weighting);
  this->CreaseAngle = new QDoubleSpinBox;
  this->CreaseAngle->setRange(0, 180);
  this->CreaseAngle->setValue(this->Options.preparation.featureAngle);
  this->CreaseAngle->setSuffix(" deg");
  meshForm->addRow("Crease angle", this->CreaseAngle);
  this->Subdivision = new QSpinBox;
  this->Subdivision->setRange(0, mesh::kMaxSubdivisionLevels);
  this->Subdivision->setValue(this->Options.preparation.subdivisionLevels);
  meshForm->addRow("Subdivision levels", this->Subdivision);
  this->Repair = new QCheckBox("weld, orient, T-junctions");
  this->Repair->setToolTip("Welds duplicate points, orients faces consistently, splits "
                           "non-manifold edges and fixes T-junctions");
  this->Repair->setChecked(this->Options.preparation.repair);
  meshForm->addRow("Repair", this->Repair);
  auto applyPreparation = [this] {
    if (this->Updating)
    {
      return;
    }
    mesh::PreparationOptions& p = this->Options.preparation;
    mesh::ParseNormalWeighting(this->Weighting->currentText().toStdString(), p.weighting);
    p.featureAngle = this->CreaseAngle->value();
    p.subdivisionLevels = this->Subdivision->value();
    p.repair = this->Repair->isChecked();
    p.fixTJunctions = p.repair;
    this->ReloadScene();
  };
  connect(this->Weighting, QOverload<int>::of(&QComboBox::activated), this, applyPreparation);
  connect(this->CreaseAngle, &QDoubleSpinBox::editingFinished, this, applyPreparation);
  connect(this->Subdivision, QOverload<int>::of(&QSpinBox::valueChanged), this, applyPreparation);
  connect(this->Repair, &QCheckBox::toggled, this, applyPreparation);
  return meshBox;
}

/// The plot's tools and the scenes' own parameters.
QGroupBox* MainWindow::BuildPlotBox()
{
  auto* plotBox = new QGroupBox("Plot");
  auto* plotForm = new QFormLayout(plotBox);
  this->ProfileTool = new QCheckBox("left-drag draws the profile");
  this->ProfileTool->setToolTip("Left-drag in a panel draws the profile line (Ctrl+drag always does)");
  plotForm->addRow(this->ProfileTool);
  this->Perceived = new QCheckBox("perceived profile");
  this->Perceived->setToolTip("Adds the profile as the eye perceives it (lateral inhibition)");
  plotForm->addRow(this->Perceived);
  this->Rotation = MakeSlider(0, 90, 0);
  plotForm->addRow("orientation: rotation", this->Rotation);
  this->Variant = new QComboBox;
  this->Variant->addItems({ "corrugated", "isosurface" });
  this->Variant->setCurrentText(QString::fromStdString(this->Options.variant));
  plotForm->addRow("normals: surface", this->Variant);
  connect(this->Variant, QOverload<int>::of(&QComboBox::activated), this, [this] {
    this->Options.variant = this->Variant->currentText().toStdString();
    if (this->Current.name == "normals")
    {
      this->ReloadScene();
    }
  });
  // A scene's own number: editing it sets the option and reloads the scene
  // when that scene is shown (the option is kept for when it is loaded).
  auto sceneNumber = [this, plotForm](const char* name, const QString& label, double& option,
                       const std::string& scene, double lo, double hi, int decimals, double step,
                       const QString& suffix) {
    auto* box = new QDoubleSpinBox;
    box->setObjectName(name);
    box->setRange(lo, hi);
    box->setDecimals(decimals);
    box->setSingleStep(step);
    box->setValue(option);
    box->setSuffix(suffix);
    plotForm->addRow(label, box);
    connect(box, &QDoubleSpinBox::editingFinished, this, [this, box, &option, scene] {
      option = box->value();
      if (this->Current.name == scene)
      {
        this->ReloadScene();
      }
    });
    return box;
  };
  this->Distance = sceneNumber("distance", "flat-conditions: distance", this->Options.distance,
    "flat-conditions", kMinConditionsDistance, kMaxConditionsDistance, 1, 1.0, " radii");
  sceneNumber("polarizer", "polarization: polarizer", this->Options.polarizer, "polarization",
    0.0, 180.0, 0, 15.0, " deg");
  sceneNumber("lightPolarizer", "polarization: light polarizer", this->Options.lightPolarizer,
    "polarization", -1.0, 180.0, 0, 15.0, " deg")
    ->setSpecialValueText("none (unpolarized)");
  this->ThetaL = MakeSlider(0, 89, 45);
  plotForm->addRow("brdf: light angle", this->ThetaL);
  this->Shininess = MakeSlider(1, 200, 32);
  plotForm->addRow("brdf: shininess n", this->Shininess);
  this->Roughness = MakeSlider(5, 100, 30);
  plotForm->addRow("brdf: roughness m x 100", this->Roughness);
  auto* brdfScale = new QComboBox;
  brdfScale->setObjectName("brdfScale");
  brdfScale->addItem("each lobe to its peak", static_cast<int>(widgets::BrdfScale::PerLobe));
  brdfScale->addItem("f_r, linear", static_cast<int>(widgets::BrdfScale::Absolute));
  brdfScale->addItem("f_r, log", static_cast<int>(widgets::BrdfScale::Log));
  plotForm->addRow("brdf: scale", brdfScale);
  connect(brdfScale, QOverload<int>::of(&QComboBox::activated), this, [this, brdfScale] {
    this->BrdfChart->SetScale(static_cast<widgets::BrdfScale>(brdfScale->currentData().toInt()));
  });
  connect(this->ProfileTool, &QCheckBox::toggled, this,
    [this](bool on) { this->View->SetProfileTool(on); });
  connect(this->Perceived, &QCheckBox::toggled, this->ProfileChart,
    &widgets::ProfilePlot::SetShowPerceived);
  connect(this->Rotation, &QSlider::valueChanged, this, &MainWindow::OnRotation);
  for (QSlider* slider : { this->ThetaL, this->Shininess, this->Roughness })
  {
    connect(slider, &QSlider::valueChanged, this, &MainWindow::UpdateBrdfPlot);
  }
  return plotBox;
}

QWidget* MainWindow::BuildControls()
{
  auto* root = new QWidget;
  auto* layout = new QVBoxLayout(root);
  layout->addWidget(this->BuildPanelBox());
  layout->addWidget(this->BuildColorBox());
  layout->addWidget(this->BuildMaterialBox());
  layout->addWidget(this->BuildLightBox());
  layout->addWidget(this->BuildMeshBox());
  layout->addWidget(this->BuildPlotBox());
  layout->addStretch(1);
  return root;
}


} // namespace shadinglab::gui
