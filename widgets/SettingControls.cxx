// SPDX-License-Identifier: BSD-3-Clause
#include "SettingControls.h"

#include "shadinglab/render/Settings.h"

#include <QComboBox>
#include <QDoubleSpinBox>

#include <stdexcept>

namespace shadinglab::widgets
{

namespace
{

const render::SettingRow& Row(const char* key)
{
  const render::SettingRow* row = render::FindSetting(key);
  if (!row)
  {
    throw std::logic_error(std::string("no setting '") + key + "' in the settings table");
  }
  return *row;
}

} // namespace

QString SettingToolTip(const char* key)
{
  const render::SettingRow& row = Row(key);
  return QString::fromStdString(row.doc + " (" + render::RangeText(row) + "; --" + row.key +
    " on the command line, " + row.property + " in ParaView)");
}

QDoubleSpinBox* MakeSettingSpinBox(const char* key, QWidget* parent)
{
  const render::SettingRow& row = Row(key);
  auto* box = new QDoubleSpinBox(parent);
  box->setRange(row.min, row.max);
  box->setDecimals(2);
  box->setValue(row.get(render::Settings{}).numbers.at(0));
  box->setToolTip(SettingToolTip(key));
  box->setObjectName(QString::fromStdString(row.key));
  return box;
}

QComboBox* MakeSettingComboBox(const char* key, QWidget* parent)
{
  const render::SettingRow& row = Row(key);
  auto* combo = new QComboBox(parent);
  for (size_t i = 0; i < row.choices.size(); ++i)
  {
    combo->addItem(QString::fromStdString(row.choices[i].label), static_cast<int>(i));
  }
  const render::SettingValue def = row.get(render::Settings{});
  if (!def.numbers.empty())
  {
    combo->setCurrentIndex(static_cast<int>(def.numbers[0]));
  }
  for (size_t i = 0; def.numbers.empty() && i < row.choices.size(); ++i)
  {
    if (row.choices[i].key == def.text) // a Text row's default
    {
      combo->setCurrentIndex(static_cast<int>(i));
    }
  }
  combo->setToolTip(SettingToolTip(key));
  combo->setObjectName(QString::fromStdString(row.key));
  return combo;
}

} // namespace shadinglab::widgets
