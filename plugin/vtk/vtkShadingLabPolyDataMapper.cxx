// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadingLabPolyDataMapper.h"

#include "CpuBackend.h"
#include "shadinglab/render/Backend.h"

#include <vtkActor.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarsToColors.h>

#include <algorithm>
#include <string>

namespace sl = shadinglab;

struct vtkShadingLabPolyDataMapper::Internals
{
  /// Backend CPU: the software renderer and its hand-over to OpenGL.
  sl::vtk::CpuBackend Cpu;
  std::string CpuFailure; ///< the last reason the CPU could not draw (said once)
  std::string BackendChoice = "gpu"; ///< the last render's backend and why
  std::string GlRenderer;            ///< GL_RENDERER of RendererOf
  const vtkRenderWindow* RendererOf = nullptr;
};

vtkStandardNewMacro(vtkShadingLabPolyDataMapper);

vtkShadingLabPolyDataMapper::vtkShadingLabPolyDataMapper()
  : Internal(new Internals)
{
}

vtkShadingLabPolyDataMapper::~vtkShadingLabPolyDataMapper() = default;

bool vtkShadingLabPolyDataMapper::ChooseCpu(vtkRenderer* ren)
{
  Internals& in = *this->Internal;
  const sl::render::Settings& settings = this->GetSettings();
  sl::render::BackendFacts facts;
  if (settings.polarizationImage != sl::render::PolarizationImage::Intensity)
  {
    facts.cpuOnly = "a polarization image is measured on the CPU renderer's linear frames";
  }
  if (settings.backend == sl::render::Backend::Auto && facts.cpuOnly.empty())
  {
    // The context's renderer string, read once per window (the context is
    // current while a mapper renders).
    if (in.RendererOf != ren->GetRenderWindow())
    {
      in.GlRenderer = sl::render::GlRendererFromReport(ren->GetRenderWindow()->ReportCapabilities());
      in.RendererOf = ren->GetRenderWindow();
    }
    facts.glRenderer = in.GlRenderer;
    vtkPolyData* input = this->GetInput();
    facts.polygons = input ? static_cast<long long>(input->GetNumberOfPolys()) : 0;
  }
  const sl::render::BackendChoice choice = sl::render::ChooseBackend(settings.backend, facts);
  in.BackendChoice = choice.why;
  return choice.backend == sl::render::Backend::CPU;
}

const std::string& vtkShadingLabPolyDataMapper::GetBackendChoice() const
{
  return this->Internal->BackendChoice;
}

void vtkShadingLabPolyDataMapper::RenderPiece(vtkRenderer* ren, vtkActor* act)
{
  const bool cpu = this->ChooseCpu(ren) && !ren->GetSelector() &&
    !act->HasTranslucentPolygonalGeometry();
  if (!cpu || !this->RenderPieceOnCpu(ren, act))
  {
    this->Superclass::RenderPiece(ren, act);
  }
}

bool vtkShadingLabPolyDataMapper::RenderPieceOnCpu(vtkRenderer* ren, vtkActor* act)
{
  Internals& in = *this->Internal;
  vtkPolyData* input = this->GetInput();
  if (!input)
  {
    return false;
  }
  if (!this->Static && this->GetInputAlgorithm())
  {
    this->GetInputAlgorithm()->Update();
    input = this->GetInput();
  }
  if (!input || !input->GetPoints())
  {
    return true; // nothing to draw, as the GL path
  }
  // The normals as the GL path draws them; the CPU resolves auto itself.
  // (Flat shading drops point normals: the CPU takes face normals anyway.)
  vtkPolyData* drawn = this->PrepareInput(input);
  sl::vtk::CpuDrawInputs inputs;
  inputs.polydata = drawn;
  // rho without scalar colours: the property's diffuse colour (or the
  // block's), as the GL path's slDiffuseColor.
  double albedo[3];
  const double* dc = this->BlockColorSet ? this->BlockColor : act->GetProperty()->GetDiffuseColor();
  std::copy(dc, dc + 3, albedo);
  inputs.albedo = albedo;
  int cellFlag = 0;
  vtkDataArray* scalars = this->ScalarVisibility
    ? vtkAbstractMapper::GetScalars(drawn, this->ScalarMode, this->ArrayAccessMode, this->ArrayId,
        this->ArrayName, cellFlag)
    : nullptr;
  const bool direct = scalars && scalars->GetDataType() == VTK_UNSIGNED_CHAR &&
    this->ColorMode != VTK_COLOR_MODE_MAP_SCALARS;
  if (scalars && !direct && scalars->GetName() && cellFlag != 2)
  {
    vtkScalarsToColors* lut = this->GetLookupTable();
    if (this->UseLookupTableScalarRange == 0)
    {
      lut->SetRange(this->ScalarRange);
    }
    inputs.lookupTable = lut;
    inputs.scalarName = scalars->GetName();
    inputs.scalarsOnCells = cellFlag == 1;
    inputs.scalarComponent = scalars->GetNumberOfComponents() == 1
      ? 0
      : (lut->GetVectorMode() == vtkScalarsToColors::COMPONENT ? lut->GetVectorComponent() : -1);
  }
  const std::string failure = in.Cpu.Draw(ren, inputs, this->GetSettings());
  if (!failure.empty())
  {
    if (failure != in.CpuFailure)
    {
      vtkWarningMacro("CPU backend: " << failure << "; drawing with OpenGL");
      in.CpuFailure = failure;
    }
    return false;
  }
  this->SetDrawnElsewhere(static_cast<int>(in.Cpu.LastStats().drawnMode), in.Cpu.LastStats().autoChoice);
  return true;
}

double vtkShadingLabPolyDataMapper::GetCpuRenderMilliseconds() const
{
  return this->Internal->Cpu.LastStats().milliseconds;
}

double vtkShadingLabPolyDataMapper::GetCpuHandOverMilliseconds() const
{
  return this->Internal->Cpu.LastHandOverMilliseconds();
}

void vtkShadingLabPolyDataMapper::SetCpuHandOverTimingFinishes(bool finish)
{
  this->Internal->Cpu.SetFinishForTiming(finish);
}

int vtkShadingLabPolyDataMapper::GetCpuMeshConversions() const
{
  return this->Internal->Cpu.Conversions();
}

void vtkShadingLabPolyDataMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internal->Cpu.ReleaseGraphicsResources(window);
  this->Superclass::ReleaseGraphicsResources(window);
}


void vtkShadingLabPolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BackendChoice: " << this->Internal->BackendChoice << "\n";
}
