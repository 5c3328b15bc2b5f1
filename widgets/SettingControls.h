// SPDX-License-Identifier: BSD-3-Clause
// Qt controls made from the settings table (shadinglab/render/Settings.h):
// their range, choices, default and tooltip are the table's, as the CLI's
// flags and the ParaView properties are.
#pragma once

class QComboBox;
class QDoubleSpinBox;
class QString;
class QWidget;

namespace shadinglab::widgets
{

/// The setting's tooltip: its documentation, range, flag and property.
QString SettingToolTip(const char* key);

/// A spin box over the setting's range, at its default, documented.
QDoubleSpinBox* MakeSettingSpinBox(const char* key, QWidget* parent = nullptr);

/// The setting's choices by display label, each item's data its index (for
/// the enumerations in the table, the enum's value), documented.
QComboBox* MakeSettingComboBox(const char* key, QWidget* parent = nullptr);

} // namespace shadinglab::widgets
