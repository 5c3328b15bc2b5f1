// SPDX-License-Identifier: BSD-3-Clause
// The explorer's window: the scene list and its explanation (left), the
// comparison and its plot (centre), the controls (right).
#pragma once

#include "Scenes.h"

#include <QMainWindow>

#include <vtkSmartPointer.h>

class QCheckBox;
class QComboBox;
class QGroupBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QSlider;
class QSpinBox;
class QStackedWidget;
class QTextBrowser;
class QTimer;
class vtkPolyData;

namespace shadinglab::widgets
{
class ColorLegend;
class BrdfPlot;
class ComparisonWidget;
class MaterialEditor;
class ParameterPlot;
class ProfilePlot;
class ScanlineInspector;
}

namespace shadinglab::gui
{

class MainWindow : public QMainWindow
{
  Q_OBJECT
public:
  explicit MainWindow(const SceneOptions& options);
  ~MainWindow() override;

  /// Builds and shows scene `name`; false with `error` (one line) if it fails.
  bool LoadScene(const std::string& name, std::string& error);
  /// Reads a mesh (the CLI's reader and its one-line errors) and shows it
  /// in the current scene if it shows a mesh, else in "modes".
  bool OpenMesh(const std::string& path, std::string& error);
  /// Renders every panel and recomputes the plot now (not deferred).
  void RefreshNow();
  /// Colours every panel by the Array box's array through the Colour map
  /// box's map (or by `colorBy` when given, as the box spells it); "" or a
  /// one-line error (also shown in the status bar).
  std::string ApplyColorBy(const std::string& colorBy = {});

  widgets::ComparisonWidget* Comparison() const { return this->View; }
  widgets::ProfilePlot* Profile() const { return this->ProfileChart; }
  widgets::ParameterPlot* Parameter() const { return this->ParameterChart; }
  widgets::ScanlineInspector* Scanline() const { return this->Inspector; }
  widgets::MaterialEditor* Materials() const { return this->Editor; }
  const Scene& CurrentScene() const { return this->Current; }
  /// The current plot's numbers as CSV (profile, study or lobes).
  std::string PlotCsv() const;
  /// File > Open's filter: every extension the reader takes
  /// (ReadableExtensions, the list of the CLI's help).
  static QString MeshFileFilter();
  /// Rebuilds the current scene for a changed option, keeping the light
  /// and the camera the user set (one control never resets another).
  void ReloadScene();

protected:
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

private:
  QWidget* BuildControls();
  /// BuildControls' groups, top to bottom.
  QGroupBox* BuildPanelBox();
  QGroupBox* BuildColorBox();
  QGroupBox* BuildMaterialBox();
  QGroupBox* BuildLightBox();
  QGroupBox* BuildMeshBox();
  QGroupBox* BuildPlotBox();

  void BuildMenus();
  void OnPanelSelected(int index);
  /// The arrays of the scene's first mesh into the Array box.
  void ListArrays();
  void OnPanelEdited();
  void UpdatePlot();
  void UpdateBrdfPlot();
  /// orientation: new quads in the same panels (the study and the widgets
  /// stay; only the panels re-render and the plot's marker moves).
  void OnRotation(int degrees);

  SceneOptions Options;
  vtkSmartPointer<vtkPolyData> Input;
  Scene Current;
  Study CurrentStudy;

  widgets::ComparisonWidget* View;
  QStackedWidget* Plots;
  widgets::ProfilePlot* ProfileChart;
  widgets::BrdfPlot* BrdfChart;
  widgets::ParameterPlot* ParameterChart;
  widgets::ScanlineInspector* Inspector;
  widgets::MaterialEditor* Editor;
  QListWidget* SceneNames;
  QTextBrowser* Explanation;
  QLabel* PanelLabel;
  QComboBox* Mode;
  QDoubleSpinBox* MaxError; ///< auto mode's budget (enabled with auto)
  QComboBox* Backend;
  QComboBox* Interpolation;
  QComboBox* Scan;
  QDoubleSpinBox* Distance; ///< flat-conditions: light and viewer distance
  QComboBox* ScanPrecision;
  QSlider* LightAzimuth;
  QSlider* LightElevation;
  QDoubleSpinBox* LightIntensity; ///< the light-intensity setting: I_L of the one light
  QDoubleSpinBox* LightSolidAngle; ///< the light-solid-angle setting: its dw
  QComboBox* Weighting;
  QDoubleSpinBox* CreaseAngle;
  QSpinBox* Subdivision;
  QCheckBox* Repair;
  QCheckBox* ProfileTool;
  QCheckBox* Perceived;
  QSlider* Rotation;
  QComboBox* Variant;
  QComboBox* ColorBy;        ///< "None", the point arrays, then CELLS:name
  QComboBox* ColorMapChoice; ///< the colormap setting's choices
  widgets::ColorLegend* Legend;
  QSlider* ThetaL;
  QSlider* Shininess;
  QSlider* Roughness;
  QTimer* PlotTimer;
  bool Updating = false;
};

} // namespace shadinglab::gui
