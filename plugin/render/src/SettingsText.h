// SPDX-License-Identifier: BSD-3-Clause
// Text helpers shared by the settings table (SettingsTable.cpp) and the
// code that parses, applies and prints its rows (Settings.cpp). Private to
// the render library.
#pragma once

#include <cctype>
#include <cstdlib>
#include <sstream>
#include <string>

namespace shadinglab::render::settings_text
{

inline std::string Lower(std::string text)
{
  for (char& c : text)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return text;
}

inline std::string Number(double v, int digits)
{
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

/// The shortest of 10 to 17 significant digits that reads back as `v`
/// exactly (pi as a default stays pi through a .pvsm or a command line).
inline std::string RoundTripNumber(double v)
{
  for (int digits = 10; digits < 17; ++digits)
  {
    const std::string text = Number(v, digits);
    if (std::strtod(text.c_str(), nullptr) == v)
    {
      return text;
    }
  }
  return Number(v, 17);
}

} // namespace shadinglab::render::settings_text
