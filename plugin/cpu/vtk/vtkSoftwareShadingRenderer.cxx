// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSoftwareShadingRenderer.h"

#include "PolyDataMesh.h"

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

namespace sl = shadinglab;

struct vtkSoftwareShadingRenderer::Internals
{
  sl::cpu::SoftwareRenderer Renderer;
  sl::Material<double> Material;
  sl::Lighting<double> Lighting;
  bool HasLighting = false;
  vtkSmartPointer<vtkCamera> Camera;
  sl::render::RenderStats Stats;
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

int vtkSoftwareShadingRenderer::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  if (!input || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro("input has no polygons");
    return 0;
  }
  const sl::render::Mesh mesh = sl::render::MeshFromPolyData(input);
  sl::render::RenderOptions options;
  options.mode = static_cast<sl::render::ShadingMode>(this->Mode);
  options.width = this->Size[0];
  options.height = this->Size[1];
  options.interpolation = this->PerspectiveCorrect ? sl::render::InterpolationSpace::Perspective
                                                   : sl::render::InterpolationSpace::Screen;
  options.polygons =
    this->DirectPolygons ? sl::render::PolygonHandling::Direct : sl::render::PolygonHandling::Triangulate;
  options.ssaa = this->Supersampling;
  options.threads = this->NumberOfThreads;

  double bounds[6];
  mesh.Bounds(bounds);
  sl::render::Camera camera = sl::render::FitCamera(
    bounds, 0.0, 0.0, 1.0, static_cast<double>(options.width) / options.height, false);
  if (vtkCamera* cam = this->Internal->Camera)
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
  }
  sl::Lighting<double> lighting = this->Internal->Lighting;
  if (!this->Internal->HasLighting)
  {
    lighting = sl::Lighting<double>();
    lighting.lights[0] = sl::render::KeyLight(camera);
    lighting.lightCount = 1;
  }
  const sl::render::Image* image = nullptr;
  try
  {
    const sl::render::Scene scene{ &mesh, camera, lighting, this->Internal->Material };
    image = &this->Internal->Renderer.Render(scene, options, &this->Internal->Stats);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  output->SetExtent(0, image->width - 1, 0, image->height - 1, 0, 0);
  const vtkIdType n = static_cast<vtkIdType>(image->width) * image->height;
  const std::vector<uint8_t> rgb8 = image->ToRGB8(options.display);
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
  for (int y = 0; y < image->height; ++y)
  {
    const size_t src = static_cast<size_t>(image->height - 1 - y) * image->width;
    for (int x = 0; x < image->width; ++x)
    {
      const vtkIdType dst = static_cast<vtkIdType>(y) * image->width + x;
      for (int c = 0; c < 3; ++c)
      {
        rgb->SetTypedComponent(dst, c, rgb8[3 * (src + x) + c]);
        linear->SetTypedComponent(dst, c, image->rgb[3 * (src + x) + c]);
      }
      covered->SetValue(dst, image->covered[src + x]);
    }
  }
  output->GetPointData()->SetScalars(rgb);
  output->GetPointData()->AddArray(linear);
  output->GetPointData()->AddArray(covered);
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
