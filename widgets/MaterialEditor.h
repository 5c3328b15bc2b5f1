// SPDX-License-Identifier: BSD-3-Clause
// Presets and a slider for every parameter of the model's Material: kd, ks
// (kd + ks <= 1 enforced as either moves), shininess, the Beckmann mixture
// (one or two lobes: roughness and weight), eta and k per channel, the
// Cook-Torrance 1982 / Walter 2007 variant, albedo, the (Blinn-)Phong
// specular colour, ambient.
#pragma once

#include "shadinglab/model/Shading.h"

#include <QHash>
#include <QWidget>

#include <vector>

class QComboBox;
class QGridLayout;
class QDoubleSpinBox;
class QSlider;

namespace shadinglab::widgets
{

class MaterialEditor : public QWidget
{
  Q_OBJECT
public:
  explicit MaterialEditor(QWidget* parent = nullptr);
  /// Shows `material` without emitting materialChanged.
  void SetMaterial(const Material<double>& material);
  const Material<double>& GetMaterial() const { return this->Value; }
  /// Sets one parameter by its label (as a user would move its slider):
  /// emits materialChanged once. False when no such parameter.
  bool SetParameter(const QString& label, double value);

signals:
  /// Every edit, already valid (ValidateMaterial passes).
  void materialChanged(const Material<double>& material);

private:
  struct Row
  {
    const char* key; ///< the settings table's key (a model declares the keys it reads)
    QString label;
    double lo, hi;   ///< the slider's span
    double min, max; ///< the setting's range (shadinglab/render/Settings.h)
    bool logScale;
    QSlider* slider;
    QDoubleSpinBox* box;
    double* target;
    QWidget* line = nullptr; ///< slider and box, one row of the form
  };
  /// One row of the grid: `label`, then `field`.
  void AddField(const QString& label, QWidget* field);
  /// A slider and spin box for `target`, the setting `key`'s value (or one
  /// channel of it).
  void AddRow(const char* key, const QString& label, double lo, double hi, bool logScale,
    double* target);
  void OnRowEdited(int index, double value);
  void Refresh();
  /// Shows the rows of the parameters the chosen model declares
  /// (ReflectanceModelRow::parameters), the second lobe's with two lobes.
  void ShowModelParameters();
  void Emit();

  Material<double> Value;
  QComboBox* Preset;
  QComboBox* Model;
  QComboBox* Variant;
  QComboBox* Lobes;
  /// Fresnel per wavelength (docs/model.md section 7): "RGB" or a measured
  /// spectrum (a preset's data) through SetSpectral.
  QComboBox* Spectrum;
  std::vector<Row> Rows;
  QGridLayout* Grid = nullptr;
  QHash<QWidget*, QWidget*> Labels; ///< each field's label (hidden with it)
  bool Updating = false;
};

} // namespace shadinglab::widgets
