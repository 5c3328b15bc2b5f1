// SPDX-License-Identifier: BSD-3-Clause
#include "shadinglab/render/Options.h"

#include <cmath>

namespace shadinglab::render
{

namespace
{

template <typename E, size_t N>
const EnumName<E>* Find(const EnumName<E> (&table)[N], E value)
{
  for (const auto& row : table)
  {
    if (row.value == value)
    {
      return &row;
    }
  }
  return nullptr;
}

template <typename E, size_t N>
bool ParseName(const EnumName<E> (&table)[N], const std::string& name, E& value)
{
  for (const auto& row : table)
  {
    if (name == row.name)
    {
      value = row.value;
      return true;
    }
  }
  return false;
}

} // namespace

const char* ShadingModeName(ShadingMode mode)
{
  const auto* row = Find(kShadingModes, mode);
  return row ? row->name : (mode == ShadingMode::Auto ? "auto" : "?");
}

const char* ShadingModeLabel(ShadingMode mode)
{
  const auto* row = Find(kShadingModes, mode);
  return row ? row->label : (mode == ShadingMode::Auto ? "Auto" : "?");
}

bool ParseShadingMode(const std::string& name, ShadingMode& mode)
{
  if (name == "auto")
  {
    mode = ShadingMode::Auto;
    return true;
  }
  return ParseName(kShadingModes, name, mode);
}

std::string ShadingModeChoices()
{
  std::string out;
  for (int i = 0; i < kShadingModeCount; ++i)
  {
    out += i == 0 ? "" : (i + 1 == kShadingModeCount ? " or " : ", ");
    out += kShadingModes[i].name;
  }
  return out;
}

const char* InterpolationSpaceName(InterpolationSpace space)
{
  const auto* row = Find(kInterpolationSpaces, space);
  return row ? row->name : "?";
}

bool ParseInterpolationSpace(const std::string& name, InterpolationSpace& space)
{
  return ParseName(kInterpolationSpaces, name, space);
}

std::string ValidateOptions(const RenderOptions& options)
{
  const std::string maxSize = std::to_string(kMaxImageSize);
  if (options.width < 1 || options.height < 1 || options.width > kMaxImageSize ||
    options.height > kMaxImageSize)
  {
    return "image size must be between 1x1 and " + maxSize + "x" + maxSize;
  }
  if (options.ssaa < 1 || options.ssaa > kMaxSupersampling)
  {
    return "supersampling factor must be 1 to " + std::to_string(kMaxSupersampling);
  }
  if (static_cast<double>(options.width) * options.height * options.ssaa * options.ssaa >
    kMaxFrameSamples)
  {
    return "image size times supersampling exceeds 4e8 samples (about 6.4 GB of frame buffers)";
  }
  if (options.threads < 0 || options.threads > 256)
  {
    return "threads must be 0..256";
  }
  if (!(options.fastPhongMaxSpread >= 0 && options.fastPhongMaxSpread <= 180))
  {
    return "fast-phong spread limit must be in [0, 180] degrees";
  }
  if (!(options.maxError >= kMinMaxError && options.maxError <= kMaxMaxError))
  {
    return "auto mode's max error must be in [0.01, 255] (1/255 units)";
  }
  if (options.keepDepth && options.ssaa != 1)
  {
    return "depth output needs supersampling 1 (a pixel's samples have several depths)";
  }
  if (options.displayBytes && options.ssaa != 1)
  {
    return "display bytes need supersampling 1 (they are written band by band)";
  }
  if (!IsFinite(options.background))
  {
    return "background colour is not finite";
  }
  return {};
}

} // namespace shadinglab::render
