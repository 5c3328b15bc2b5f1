// SPDX-License-Identifier: BSD-3-Clause
#include "MaterialEditor.h"

#include "shadinglab/model/Materials.h"
#include "shadinglab/model/Spectrum.h"
#include "SettingControls.h"
#include "shadinglab/render/Settings.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>

#include <algorithm>
#include <cmath>
#include <string_view>

namespace shadinglab::widgets
{

namespace
{
/// Slider steps: fine enough that a drag looks continuous.
constexpr int kSliderSteps = 1000;
} // namespace

MaterialEditor::MaterialEditor(QWidget* parent)
  : QWidget(parent)
  , Preset(new QComboBox(this))
  , Model(new QComboBox(this))
  , Variant(new QComboBox(this))
  , Lobes(new QComboBox(this))
  , Spectrum(new QComboBox(this))
{
  // A grid, not a QFormLayout: Qt 5's form keeps the height of a row whose
  // label and field are hidden, which left a gap wherever the chosen model
  // hides a parameter (Lambert: ks and shininess between kd and albedo).
  this->Grid = new QGridLayout(this);
  this->Grid->setContentsMargins(0, 0, 0, 0);
  this->Grid->setColumnStretch(1, 1);
  this->Preset->addItem("(custom)");
  for (const MaterialPreset& preset : MaterialPresets())
  {
    this->Preset->addItem(QString::fromStdString(preset.name));
    this->Preset->setItemData(this->Preset->count() - 1,
      QString::fromStdString(preset.source), Qt::ToolTipRole);
  }
  this->AddField("Preset", this->Preset);
  for (const ReflectanceModelRow& row : kReflectanceModels)
  {
    this->Model->addItem(row.label, static_cast<int>(row.value));
  }
  this->AddField("Model", this->Model);
  this->Variant->addItem("Cook-Torrance 1982 (1/pi)");
  this->Variant->addItem("Walter 2007 (1/4)");
  this->AddField("CT variant", this->Variant);
  this->Lobes->addItem("1 Beckmann lobe");
  this->Lobes->addItem("2 lobes (mixture)");
  this->AddField("Roughness", this->Lobes);
  this->Spectrum->addItem("RGB: eta, k per channel");
  for (const std::string& name : PresetDispersionNames())
  {
    const QString q = QString::fromStdString(name);
    this->Spectrum->addItem(QString("spectral: %1 (measured)").arg(q), q);
  }
  // Shown when a scene's material came with a spectrum of its own.
  this->Spectrum->addItem("spectral (the scene's)", QString());
  this->Spectrum->setToolTip("F per wavelength from measured n and k, 16 samples under D65 "
                             "(docs/model.md section 7), or three RGB samples");
  this->AddField("Fresnel", this->Spectrum);
  this->AddRow("kd", "kd", 0.0, 1.0, false, &this->Value.kd);
  this->AddRow("ks", "ks", 0.0, 1.0, false, &this->Value.ks);
  this->AddRow("shininess", "shininess n", 1.0, 1000.0, true, &this->Value.shininess);
  this->AddRow("m", "m (lobe 1)", kMinRoughness<double>, 1.0, true, &this->Value.lobes[0].m);
  this->AddRow("w", "weight lobe 1", 0.0, 1.0, false, &this->Value.lobes[0].weight);
  this->AddRow("m", "m (lobe 2)", kMinRoughness<double>, 1.0, true, &this->Value.lobes[1].m);
  this->AddRow("eta", "eta R", 0.05, 4.0, false, &this->Value.eta.x);
  this->AddRow("eta", "eta G", 0.05, 4.0, false, &this->Value.eta.y);
  this->AddRow("eta", "eta B", 0.05, 4.0, false, &this->Value.eta.z);
  this->AddRow("k", "k R", 0.0, 10.0, false, &this->Value.k.x);
  this->AddRow("k", "k G", 0.0, 10.0, false, &this->Value.k.y);
  this->AddRow("k", "k B", 0.0, 10.0, false, &this->Value.k.z);
  this->AddRow("albedo", "albedo R", 0.0, 1.0, false, &this->Value.diffuseColor.x);
  this->AddRow("albedo", "albedo G", 0.0, 1.0, false, &this->Value.diffuseColor.y);
  this->AddRow("albedo", "albedo B", 0.0, 1.0, false, &this->Value.diffuseColor.z);
  this->AddRow("specular", "specular R", 0.0, 1.0, false, &this->Value.specularColor.x);
  this->AddRow("specular", "specular G", 0.0, 1.0, false, &this->Value.specularColor.y);
  this->AddRow("specular", "specular B", 0.0, 1.0, false, &this->Value.specularColor.z);
  this->AddRow("ambient", "ambient", 0.0, 0.5, false, &this->Value.ambient.x);
  for (Row& row : this->Rows)
  {
    auto* line = new QWidget(this);
    row.line = line;
    auto* h = new QHBoxLayout(line);
    h->setContentsMargins(0, 0, 0, 0);
    h->addWidget(row.slider, 1);
    h->addWidget(row.box);
    this->AddField(row.label, line);
  }
  connect(this->Preset, QOverload<int>::of(&QComboBox::activated), this, [this](int index) {
    if (index <= 0)
    {
      return;
    }
    const MaterialPreset* preset =
      FindMaterialPreset(this->Preset->itemText(index).toStdString());
    if (preset)
    {
      this->Value = preset->material;
      this->Refresh();
      this->Emit();
    }
  });
  connect(this->Model, QOverload<int>::of(&QComboBox::activated), this, [this](int index) {
    this->Value.model = static_cast<ReflectanceModel>(this->Model->itemData(index).toInt());
    this->Refresh();
    this->Emit();
  });
  connect(this->Variant, QOverload<int>::of(&QComboBox::activated), this, [this](int index) {
    this->Value.variant =
      index == 1 ? SpecularVariant::Walter2007 : SpecularVariant::CookTorrance1982;
    this->Refresh();
    this->Emit();
  });
  connect(this->Spectrum, QOverload<int>::of(&QComboBox::activated), this, [this](int index) {
    const std::string name = this->Spectrum->itemData(index).toString().toStdString();
    if (index > 0 && name.empty())
    {
      return; // "the scene's": keep the material's own spectrum
    }
    const Dispersion* dispersion = index > 0 ? PresetDispersion(name) : nullptr;
    this->Value.spectralCount = 0;
    if (dispersion)
    {
      SetSpectral(this->Value, *dispersion);
    }
    this->Refresh();
    this->Emit();
  });
  connect(this->Lobes, QOverload<int>::of(&QComboBox::activated), this, [this](int index) {
    this->Value.lobeCount = index + 1;
    if (this->Value.lobeCount == 1)
    {
      this->Value.lobes[0].weight = 1.0;
    }
    else
    {
      this->Value.lobes[0].weight = 0.5;
      this->Value.lobes[1].weight = 0.5;
      if (!(this->Value.lobes[1].m > 0))
      {
        this->Value.lobes[1].m = std::min(1.0, 2.5 * this->Value.lobes[0].m);
      }
    }
    this->Refresh();
    this->Emit();
  });
  this->Refresh();
}

void MaterialEditor::AddField(const QString& label, QWidget* field)
{
  const int row = static_cast<int>(this->Labels.size());
  auto* text = new QLabel(label, this);
  text->setBuddy(field);
  this->Grid->addWidget(text, row, 0);
  this->Grid->addWidget(field, row, 1);
  this->Labels.insert(field, text);
}

void MaterialEditor::AddRow(const char* key, const QString& label, double lo, double hi,
  bool logScale, double* target)
{
  // The value's range and documentation are the settings table's (one
  // home for every front end); [lo, hi] is the part the slider spans.
  const render::SettingRow* setting = render::FindSetting(key);
  Row row{ key, label, lo, hi, setting->min, setting->max, logScale,
    new QSlider(Qt::Horizontal, this), new QDoubleSpinBox(this), target };
  row.slider->setRange(0, kSliderSteps);
  row.slider->setObjectName(label); // found by label (tests, scripting)
  row.box->setRange(row.min, row.max);
  row.box->setDecimals(hi > 100 ? 1 : 3);
  const QString tip = SettingToolTip(key);
  row.slider->setToolTip(tip);
  row.box->setToolTip(tip);
  row.box->setSingleStep((hi - lo) / 100.0);
  row.box->setKeyboardTracking(false);
  const int index = static_cast<int>(this->Rows.size());
  connect(row.slider, &QSlider::valueChanged, this, [this, index](int step) {
    if (this->Updating)
    {
      return;
    }
    const Row& r = this->Rows[index];
    const double t = static_cast<double>(step) / kSliderSteps;
    const double value =
      r.logScale ? r.lo * std::pow(r.hi / r.lo, t) : r.lo + t * (r.hi - r.lo);
    this->OnRowEdited(index, value);
  });
  connect(row.box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
    [this, index](double value) {
      if (!this->Updating)
      {
        this->OnRowEdited(index, value);
      }
    });
  this->Rows.push_back(row);
}

void MaterialEditor::OnRowEdited(int index, double value)
{
  Row& row = this->Rows[index];
  *row.target = std::clamp(value, row.min, row.max);
  Material<double>& m = this->Value;
  // kd + ks <= 1 (docs/model.md eq. 1.2): the other coefficient gives way.
  if (row.target == &m.kd && m.kd + m.ks > 1.0)
  {
    m.ks = 1.0 - m.kd;
  }
  if (row.target == &m.ks && m.kd + m.ks > 1.0)
  {
    m.kd = 1.0 - m.ks;
  }
  // Mixture weights sum to 1: lobe 2 takes the rest.
  if (m.lobeCount == 2)
  {
    m.lobes[1].weight = 1.0 - m.lobes[0].weight;
  }
  else
  {
    m.lobes[0].weight = 1.0;
  }
  // One ambient slider: grey ambient reflectance.
  m.ambient.y = m.ambient.z = m.ambient.x;
  this->Refresh();
  this->Emit();
}

bool MaterialEditor::SetParameter(const QString& label, double value)
{
  for (size_t i = 0; i < this->Rows.size(); ++i)
  {
    if (this->Rows[i].label == label)
    {
      this->OnRowEdited(static_cast<int>(i), value);
      return true;
    }
  }
  return false;
}

void MaterialEditor::SetMaterial(const Material<double>& material)
{
  this->Value = material;
  this->Refresh();
}

void MaterialEditor::Refresh()
{
  this->Updating = true;
  for (Row& row : this->Rows)
  {
    const double v = std::clamp(*row.target, row.min, row.max);
    const double onSlider = std::clamp(v, row.lo, row.hi);
    const double t = row.logScale ? std::log(onSlider / row.lo) / std::log(row.hi / row.lo)
                                  : (onSlider - row.lo) / (row.hi - row.lo);
    row.slider->setValue(static_cast<int>(std::lround(t * kSliderSteps)));
    row.box->setValue(v);
  }
  // The preset the material is, or "(custom)": a scene's gold is "gold".
  const MaterialPreset* preset = PresetMatching(this->Value);
  this->Preset->setCurrentIndex(
    preset ? std::max(0, this->Preset->findText(QString::fromStdString(preset->name))) : 0);
  this->Model->setCurrentIndex(this->Model->findData(static_cast<int>(this->Value.model)));
  this->Variant->setCurrentIndex(this->Value.variant == SpecularVariant::Walter2007 ? 1 : 0);
  this->Lobes->setCurrentIndex(std::clamp(this->Value.lobeCount, 1, 2) - 1);
  if (this->Value.spectralCount == 0)
  {
    this->Spectrum->setCurrentIndex(0);
  }
  else if (this->Spectrum->currentIndex() == 0)
  {
    this->Spectrum->setCurrentIndex(this->Spectrum->count() - 1);
  }
  this->ShowModelParameters();
  this->Updating = false;
}

void MaterialEditor::ShowModelParameters()
{
  const ReflectanceModel model = this->Value.model;
  auto show = [this](QWidget* field, bool visible) {
    field->setVisible(visible);
    if (QWidget* label = this->Labels.value(field))
    {
      label->setVisible(visible);
    }
  };
  show(this->Variant, ModelUsesParameter(model, "variant"));
  show(this->Lobes, ModelUsesParameter(model, "m"));
  show(this->Spectrum, ModelUsesParameter(model, "spectral"));
  const bool spectral = this->Value.spectralCount > 0;
  for (const Row& row : this->Rows)
  {
    // The second lobe's roughness and the first lobe's weight mean
    // something only in a mixture of two.
    const bool secondLobe = row.label.contains("lobe 2") || row.label.contains("weight lobe");
    // With a measured spectrum, F does not read the RGB eta and k.
    const bool rgbIndex = std::string_view(row.key) == "eta" || std::string_view(row.key) == "k";
    show(row.line,
      ModelUsesParameter(model, row.key) && (!secondLobe || this->Value.lobeCount == 2) &&
        !(spectral && rgbIndex));
  }
}

void MaterialEditor::Emit()
{
  if (ValidateMaterial(this->Value).empty())
  {
    emit this->materialChanged(this->Value);
  }
}

} // namespace shadinglab::widgets
