// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadingLabSettings
 * @brief   every ShadingLab setting, by the table's keys, for VTK's wrappers
 *
 * A vtkObject holding one shadinglab::render::Settings (mode, interpolation,
 * material, lights' intensity, normals, ...), set by the settings table's
 * keys and texts as on the command line: Set("mode", "gouraud"),
 * Set("eta", "1.5"). A refused value leaves the settings unchanged and
 * Set returns the table's one-line error, the CLI's message without its
 * "--". Python's shadinglab package turns keyword arguments into Set calls
 * and its errors into ValueError; vtkSoftwareShadingRenderer and
 * vtkShadingLabPolyDataMapper take the whole object.
 */
#ifndef vtkShadingLabSettings_h
#define vtkShadingLabSettings_h

#include "shadinglabRenderVTKModule.h" // for export macro

#include <vtkObject.h>

#include <memory>
#include <string>

#ifndef __VTK_WRAP__
namespace shadinglab::render
{
struct Settings;
}
#endif

class SHADINGLABRENDERVTK_EXPORT vtkShadingLabSettings : public vtkObject
{
public:
  static vtkShadingLabSettings* New();
  vtkTypeMacro(vtkShadingLabSettings, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// One setting by its table key and text: "" or the table's one-line
  /// error (the settings are then unchanged). Unknown keys are errors.
  std::string Set(const char* key, const char* value);
  /// A setting's value as a user would type it; "" for an unknown key.
  std::string Get(const char* key) const;
  /// Back to the defaults (render::Settings{}).
  void Reset();
  /// "" or why these settings cannot be drawn (render::ValidateSettings).
  std::string Validate() const;

  /// The settings table as a JSON list, one object a row: key, label,
  /// group, kind, count (min, max), min, max, choices, default, metavar,
  /// doc, front_ends (cli, paraview, mapper, explorer).
  static std::string GetTableJson();

#ifndef __VTK_WRAP__
  /// The settings themselves (C++).
  const shadinglab::render::Settings& GetSettings() const;
  void SetSettings(const shadinglab::render::Settings& settings);
#endif

protected:
  vtkShadingLabSettings();
  ~vtkShadingLabSettings() override;

private:
  vtkShadingLabSettings(const vtkShadingLabSettings&) = delete;
  void operator=(const vtkShadingLabSettings&) = delete;

  std::unique_ptr<shadinglab::render::Settings> Values;
};

#endif
