// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSoftwareShadingRenderer
 * @brief   renders vtkPolyData with the CPU shading renderer into vtkImageData
 *
 * A VTK pipeline front end to shadinglab::cpu::SoftwareRenderer: input port 0
 * takes vtkPolyData, the output is a Width x Height vtkImageData whose point
 * scalars are the display image ("RGB", unsigned char), with the linear
 * intensities ("LinearRGB", float) and the coverage mask ("Covered") beside
 * them. Row 0 of the VTK image is the bottom of the picture, as usual in VTK.
 *
 * The camera is a vtkCamera (SetCamera); without one the view is fitted to
 * the input bounds, as the command line fits it. The settings (mode,
 * interpolation, material, light intensity, normals, ...: the settings
 * table) come from a vtkShadingLabSettings (SetSettings); without one, from
 * this class's own properties (Mode, PerspectiveCorrect, ...) and the
 * material set from C++. The lights default to the command line's key light.
 *
 * As the command line and the mapper, a smooth mode draws the input's point
 * normals, or (none, or the settings' recompute) weighted vertex normals
 * split at the settings' feature angle (vtkWeightedPolyDataNormals), made
 * for the render only; the mesh is drawn in a local frame (centred, unit
 * size), so the picture is the command line's for the same settings.
 *
 * @warning The input is never modified.
 */
#ifndef vtkSoftwareShadingRenderer_h
#define vtkSoftwareShadingRenderer_h

#include "shadinglab/cpu/SoftwareRenderer.h"

#include "shadinglabCPUVTKModule.h" // for export macro

#include <vtkImageAlgorithm.h>

#include <memory>
#include <string>

class vtkCamera;
class vtkShadingLabSettings;
#ifndef __VTK_WRAP__
namespace shadinglab::render
{
struct Settings;
}
#endif

class SHADINGLABCPUVTK_EXPORT vtkSoftwareShadingRenderer : public vtkImageAlgorithm
{
public:
  static vtkSoftwareShadingRenderer* New();
  vtkTypeMacro(vtkSoftwareShadingRenderer, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Where the model is evaluated: shadinglab::render::ShadingMode's values
  /// (plain numbers for VTK's wrappers; static_asserts in the .cxx tie them).
  enum Modes
  {
    FLAT = 0,
    GOURAUD = 1,
    PHONG = 2,
    FAST_PHONG = 3
  };

  ///@{
  /// Shading mode (default PHONG). The reflectance model is the material's.
  vtkSetClampMacro(Mode, int, FLAT, FAST_PHONG);
  vtkGetMacro(Mode, int);
  ///@}

  ///@{
  /// Image size in pixels (default 640 x 480, 1 .. kMaxImageSize = 16384 each).
  vtkSetVector2Macro(Size, int);
  vtkGetVector2Macro(Size, int);
  ///@}

  ///@{
  /// Perspective-correct interpolation (default on); off interpolates
  /// linearly in screen space, as the lecture.
  vtkSetMacro(PerspectiveCorrect, bool);
  vtkGetMacro(PerspectiveCorrect, bool);
  vtkBooleanMacro(PerspectiveCorrect, bool);
  ///@}

  ///@{
  /// Scan-convert polygons directly instead of triangulating (default off).
  vtkSetMacro(DirectPolygons, bool);
  vtkGetMacro(DirectPolygons, bool);
  vtkBooleanMacro(DirectPolygons, bool);
  ///@}

  ///@{
  /// Supersampling factor per axis, 1 .. 8 (default 1).
  vtkSetClampMacro(Supersampling, int, 1, 8);
  vtkGetMacro(Supersampling, int);
  ///@}

  ///@{
  /// Worker threads; 0 uses every core (default 0).
  vtkSetClampMacro(NumberOfThreads, int, 0, 256);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// Camera; nullptr (default) fits the view to the input bounds.
  void SetCamera(vtkCamera* camera);
  vtkCamera* GetCamera();
  ///@}

  ///@{
  /// Every setting of the table (nullptr, the default: this class's
  /// properties). The object is copied when the render runs; changing it
  /// re-renders.
  void SetSettings(vtkShadingLabSettings* settings);
  vtkShadingLabSettings* GetSettings();
  ///@}

  /// The last render's statistics as one JSON object, the keys of the
  /// command line's `render --stats` ("mode", "polygons", "milliseconds",
  /// "pixels_covered", ...); "{}" before the first.
  std::string GetLastStatsJson() const;
  /// Why the last render failed ("" when it did not), and whether the
  /// request itself was unusable (the mode cannot evaluate the material's
  /// model, no such array to colour by, ...) rather than the renderer failing.
  std::string GetLastError() const;
  bool GetLastErrorIsRequest() const;

#ifndef __VTK_WRAP__
  /// The illumination model's material (default: Blinn-Phong, kd 0.7, ks 0.3).
  void SetMaterial(const shadinglab::Material<double>& material);
  /// Lights (default: one key light above-left of the camera).
  void SetLighting(const shadinglab::Lighting<double>& lighting);
  void ClearLighting();

  /// Statistics of the last render.
  const shadinglab::render::RenderStats& GetLastStats() const;
#endif

protected:
  vtkSoftwareShadingRenderer();
  ~vtkSoftwareShadingRenderer() override;

  vtkMTimeType GetMTime() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Mode = PHONG;
  int Size[2] = { 640, 480 };
  bool PerspectiveCorrect = true;
  bool DirectPolygons = false;
  int Supersampling = 1;
  int NumberOfThreads = 0;

private:
  vtkSoftwareShadingRenderer(const vtkSoftwareShadingRenderer&) = delete;
#ifndef __VTK_WRAP__
  /// The settings object's, or this class's properties (and the material).
  shadinglab::render::Settings CurrentSettings() const;
#endif
  void operator=(const vtkSoftwareShadingRenderer&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
