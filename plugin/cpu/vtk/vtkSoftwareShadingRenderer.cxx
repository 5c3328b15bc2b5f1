// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSoftwareShadingRenderer.h"

#include "PolyDataMesh.h"
#include "vtkShadingLabSettings.h"
#include "vtkWeightedPolyDataNormals.h"
#include "shadinglab/model/Materials.h"
#include "shadinglab/render/Settings.h"

#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace sl = shadinglab;

struct vtkSoftwareShadingRenderer::Internals
{
  sl::cpu::SoftwareRenderer Renderer;
  sl::Material<double> Material;
  sl::Lighting<double> Lighting;
  bool HasLighting = false;
  vtkSmartPointer<vtkCamera> Camera;
  vtkSmartPointer<vtkShadingLabSettings> Settings;
  sl::render::RenderStats Stats;
  bool Rendered = false;
  std::string Error;
  bool ErrorIsRequest = false;
  std::string Model; ///< the last render's reflectance model
};

vtkStandardNewMacro(vtkSoftwareShadingRenderer);

// The VTK enum is the render::ShadingMode list, checked at compile time.
static_assert(vtkSoftwareShadingRenderer::FLAT == static_cast<int>(shadinglab::render::ShadingMode::Flat) &&
  vtkSoftwareShadingRenderer::GOURAUD == static_cast<int>(shadinglab::render::ShadingMode::Gouraud) &&
  vtkSoftwareShadingRenderer::PHONG == static_cast<int>(shadinglab::render::ShadingMode::Phong) &&
  vtkSoftwareShadingRenderer::FAST_PHONG == static_cast<int>(shadinglab::render::ShadingMode::FastPhong) &&
  shadinglab::render::kShadingModeCount == 4);

vtkSoftwareShadingRenderer::vtkSoftwareShadingRenderer()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

vtkSoftwareShadingRenderer::~vtkSoftwareShadingRenderer() = default;

void vtkSoftwareShadingRenderer::SetCamera(vtkCamera* camera)
{
  if (this->Internal->Camera != camera)
  {
    this->Internal->Camera = camera;
    this->Modified();
  }
}

vtkCamera* vtkSoftwareShadingRenderer::GetCamera()
{
  return this->Internal->Camera;
}

void vtkSoftwareShadingRenderer::SetSettings(vtkShadingLabSettings* settings)
{
  if (this->Internal->Settings != settings)
  {
    this->Internal->Settings = settings;
    this->Modified();
  }
}

vtkShadingLabSettings* vtkSoftwareShadingRenderer::GetSettings()
{
  return this->Internal->Settings;
}

vtkMTimeType vtkSoftwareShadingRenderer::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->Internal->Settings)
  {
    time = std::max(time, this->Internal->Settings->GetMTime());
  }
  if (this->Internal->Camera)
  {
    time = std::max(time, this->Internal->Camera->GetMTime());
  }
  return time;
}

std::string vtkSoftwareShadingRenderer::GetLastError() const
{
  return this->Internal->Error;
}

bool vtkSoftwareShadingRenderer::GetLastErrorIsRequest() const
{
  return this->Internal->ErrorIsRequest;
}

std::string vtkSoftwareShadingRenderer::GetLastStatsJson() const
{
  if (!this->Internal->Rendered)
  {
    return "{}";
  }
  const sl::render::RenderStats& st = this->Internal->Stats;
  char json[1024];
  std::snprintf(json, sizeof json,
    "{\"backend\":\"cpu\",\"mode\":\"%s\",\"model\":\"%s\",\"milliseconds\":%.3f,"
    "\"polygons\":%lld,\"triangles\":%lld,\"rasterized\":%lld,\"clipped\":%lld,"
    "\"degenerate\":%lld,\"culled\":%lld,\"hidden_back_faces_culled\":%s,"
    "\"pixels_covered\":%lld,\"pixels_shaded\":%lld,\"fast_phong_exact\":%lld,"
    "\"fast_phong_as_phong\":%s,\"threads\":%d,\"normals_computed\":%s",
    sl::render::ShadingModeName(st.drawnMode), this->Internal->Model.c_str(), st.milliseconds,
    static_cast<long long>(st.polygons), static_cast<long long>(st.triangles),
    static_cast<long long>(st.rasterized), static_cast<long long>(st.clipped),
    static_cast<long long>(st.degenerate), static_cast<long long>(st.culled),
    st.hiddenBackFacesCulled ? "true" : "false", static_cast<long long>(st.pixelsCovered),
    static_cast<long long>(st.pixelsShaded), static_cast<long long>(st.fastPhongExact),
    st.fastPhongAsPhong ? "true" : "false", st.threads, st.normalsComputed ? "true" : "false");
  std::string out = json;
  if (!st.autoChoice.empty())
  {
    std::string quoted;
    for (const char c : st.autoChoice)
    {
      if (c == '"' || c == '\\')
      {
        quoted += '\\';
      }
      quoted += c == '\n' ? ' ' : c;
    }
    out += ",\"auto\":\"" + quoted + "\"";
  }
  return out + "}";
}

void vtkSoftwareShadingRenderer::SetMaterial(const sl::Material<double>& material)
{
  this->Internal->Material = material;
  this->Modified();
}

void vtkSoftwareShadingRenderer::SetLighting(const sl::Lighting<double>& lighting)
{
  this->Internal->Lighting = lighting;
  this->Internal->HasLighting = true;
  this->Modified();
}

void vtkSoftwareShadingRenderer::ClearLighting()
{
  this->Internal->HasLighting = false;
  this->Modified();
}

const sl::render::RenderStats& vtkSoftwareShadingRenderer::GetLastStats() const
{
  return this->Internal->Stats;
}

int vtkSoftwareShadingRenderer::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkSoftwareShadingRenderer::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, this->Size[0] - 1, 0, this->Size[1] - 1, 0, 0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_UNSIGNED_CHAR, 3);
  return 1;
}

namespace
{

/// The input to draw for `settings`: a smooth mode draws the input's
/// normals or (none, or asked to) the settings' weighted normals split at
/// creases, as the command line and the mapper do; made on a copy: the
/// input is never modified.
vtkSmartPointer<vtkPolyData> WithNormals(vtkPolyData* input, const sl::render::Settings& settings)
{
  vtkSmartPointer<vtkPolyData> drawn = input;
  const sl::render::NormalSettings& made = settings.normals;
  if (settings.render.mode != sl::render::ShadingMode::Flat &&
    (!input->GetPointData()->GetNormals() || made.recompute))
  {
    vtkNew<vtkPolyData> copy;
    copy->ShallowCopy(input);
    vtkNew<vtkWeightedPolyDataNormals> normals;
    normals->SetInputData(copy);
    normals->SetWeighting(made.weighting);
    normals->SetFeatureAngle(made.featureAngle);
    normals->SetSplitting(made.featureAngle < 180.0);
    normals->ConsistencyOn();
    normals->Update();
    drawn = normals->GetOutput();
  }
  return drawn;
}

/// The image as the output's point data, rows turned over (VTK's row 0 is
/// the bottom): "RGB" (display bytes, the scalars), "LinearRGB", "Covered".
void FillOutput(vtkImageData* output, const sl::render::Image& frame, sl::render::DisplayTransform display)
{
  const sl::render::Image* image = &frame;
  output->SetExtent(0, image->width - 1, 0, image->height - 1, 0, 0);
  const vtkIdType n = static_cast<vtkIdType>(image->width) * image->height;
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(n);
  vtkNew<vtkFloatArray> linear;
  linear->SetName("LinearRGB");
  linear->SetNumberOfComponents(3);
  linear->SetNumberOfTuples(n);
  vtkNew<vtkUnsignedCharArray> covered;
  covered->SetName("Covered");
  covered->SetNumberOfTuples(n);
  // Row by row, turned over (VTK's row 0 is the bottom), straight into the
  // arrays: the frame's one copy.
  const size_t W = static_cast<size_t>(image->width);
  uint8_t* rgbOut = rgb->WritePointer(0, 3 * n);
  float* linearOut = linear->WritePointer(0, 3 * n);
  uint8_t* coveredOut = covered->WritePointer(0, n);
  for (int y = 0; y < image->height; ++y)
  {
    const size_t src = static_cast<size_t>(image->height - 1 - y) * W, dst = static_cast<size_t>(y) * W;
    image->ToRGB8(display, src, W, rgbOut + 3 * dst); // display bytes, made in place
    std::copy_n(image->rgb.data() + 3 * src, 3 * W, linearOut + 3 * dst);
    std::copy_n(image->covered.data() + src, W, coveredOut + dst);
  }
  output->GetPointData()->SetScalars(rgb);
  output->GetPointData()->AddArray(linear);
  output->GetPointData()->AddArray(covered);
}

} // namespace

sl::render::Settings vtkSoftwareShadingRenderer::CurrentSettings() const
{
  const Internals& in = *this->Internal;
  sl::render::Settings settings;
  if (in.Settings)
  {
    settings = in.Settings->GetSettings();
  }
  else
  {
    settings.render.mode = static_cast<sl::render::ShadingMode>(this->Mode);
    settings.render.interpolation = this->PerspectiveCorrect
      ? sl::render::InterpolationSpace::Perspective
      : sl::render::InterpolationSpace::Screen;
    settings.render.polygons = this->DirectPolygons ? sl::render::PolygonHandling::Direct
                                                    : sl::render::PolygonHandling::Triangulate;
    settings.render.ssaa = this->Supersampling;
    settings.render.threads = this->NumberOfThreads;
    settings.material = in.Material;
  }
  return settings;
}

int vtkSoftwareShadingRenderer::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  if (!input || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    this->Internal->Error = "input has no polygons";
    vtkErrorMacro("input has no polygons");
    return 0;
  }
  Internals& in = *this->Internal;
  in.Error.clear();
  in.ErrorIsRequest = false;
  const sl::render::Settings settings = this->CurrentSettings();
  sl::render::RenderOptions options = settings.render;
  options.width = this->Size[0];
  options.height = this->Size[1];
  vtkSmartPointer<vtkPolyData> drawn = WithNormals(input, settings);
  // The mesh in a local frame (centred, unit size), the camera fitted to
  // it or converted from the vtkCamera, and the lights: as the command line.
  sl::render::WorldFrame frame;
  const sl::render::Image* image = nullptr;
  // Concave polygons whole for the direct scan (even-odd), else split.
  const auto polygons = sl::render::ScansPolygonsWhole(options)
    ? sl::render::PolygonHandling::Direct
    : sl::render::PolygonHandling::Triangulate;
  try
  {
    // Colour by data (the settings' color-by, colormap and range).
    sl::render::Mesh mesh;
    sl::render::ColorMap map;
    const bool colored = !settings.color.array.empty();
    if (colored)
    {
      std::string title;
      const std::string problem =
        sl::render::MeshColoredBy(drawn, frame, settings.color, "", mesh, map, title, polygons);
      if (!problem.empty())
      {
        throw std::invalid_argument(problem);
      }
    }
    else
    {
      mesh = sl::render::MeshFromPolyData(drawn, frame, polygons);
    }
    double bounds[6];
    mesh.Bounds(bounds);
    sl::render::Camera camera = sl::render::FitCamera(
      bounds, 0.0, 0.0, 1.0, static_cast<double>(options.width) / options.height, false);
    if (vtkCamera* cam = in.Camera)
    {
      double v[3];
      cam->GetPosition(v);
      camera.position = { v[0], v[1], v[2] };
      cam->GetFocalPoint(v);
      camera.focalPoint = { v[0], v[1], v[2] };
      cam->GetViewUp(v);
      camera.viewUp = { v[0], v[1], v[2] };
      camera.viewAngle = cam->GetViewAngle();
      camera.parallel = cam->GetParallelProjection() != 0;
      camera.parallelScale = cam->GetParallelScale();
      cam->GetClippingRange(v);
      camera.nearClip = v[0];
      camera.farClip = v[1];
      sl::render::ToLocal(frame, camera);
    }
    sl::Lighting<double> lighting = in.Lighting;
    if (in.HasLighting)
    {
      sl::render::ToLocal(frame, lighting);
    }
    else
    {
      lighting = sl::render::LightKit(camera, settings.lightIntensity);
      for (int k = 0; k < lighting.lightCount; ++k)
      {
        lighting.lights[k].solidAngle = settings.lightSolidAngle;
      }
      lighting.ambientIntensity = sl::Vec3<double>(1, 1, 1);
    }
    in.Model = sl::ReflectanceModelName(settings.material.model);
    sl::render::Scene scene{ &mesh, camera, lighting,
      sl::render::MaterialForData(settings.material, settings.highlights, colored) };
    scene.colorMap = colored ? &map : nullptr;
    image = &in.Renderer.Render(scene, options, &in.Stats);
    in.Stats.normalsComputed = in.Stats.normalsComputed || drawn != input;
    in.Rendered = true;
  }
  catch (const std::invalid_argument& e)
  {
    // An unusable request (mode and model, camera, colour by data).
    in.Error = e.what();
    in.ErrorIsRequest = true;
    vtkErrorMacro(<< e.what());
    return 0;
  }
  catch (const std::exception& e)
  {
    in.Error = e.what();
    vtkErrorMacro(<< e.what());
    return 0;
  }
  FillOutput(output, *image, options.display);
  return 1;
}

void vtkSoftwareShadingRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << sl::render::ShadingModeName(static_cast<sl::render::ShadingMode>(this->Mode))
     << "\n";
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
  os << indent << "PerspectiveCorrect: " << this->PerspectiveCorrect << "\n";
  os << indent << "DirectPolygons: " << this->DirectPolygons << "\n";
  os << indent << "Supersampling: " << this->Supersampling << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "Camera: " << this->Internal->Camera.GetPointer() << "\n";
}
