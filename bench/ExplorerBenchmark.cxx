// SPDX-License-Identifier: BSD-3-Clause
// The explorer's re-render times (issue 9: a slider drag on a 100k-triangle
// mesh re-renders one panel in under 100 ms on llvmpipe). A comparison of
// one GPU and one CPU panel, each about 640 x 560, on a 100k-triangle torus
// with vertex normals; per iteration one material edit (a new shininess, as
// a slider step) of one panel, or one camera step (every panel), through
// the widget's own calls, finished (glFinish) and composed by Qt.
// Run under an X server: xvfb-run -a bin/shadinglab_bench_explorer
#include "AnalyticMeshes.h"
#include "ComparisonWidget.h"
#include "shadinglab/gl/GpuRenderer.h"
#include "ShadingPanel.h"

#include <benchmark/benchmark.h>

#include <QApplication>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>
#include <vtkCamera.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkRenderWindow.h>

#include <cstdlib>
#include <iostream>
#include <memory>

using namespace shadinglab;

namespace
{

/// The torus at 316 x 158 quads split in two: 99,856 triangles.
vtkSmartPointer<vtkPolyData> Torus100k()
{
  vtkSmartPointer<vtkPolyData> raw;
  raw.TakeReference(datasets::MakeTorus(1.0, 0.4, 316, 158));
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(raw);
  normals->SplittingOff();
  normals->Update();
  return normals->GetOutput();
}

struct Fixture
{
  widgets::ComparisonWidget view;
  Fixture()
  {
    widgets::PanelSpec gpu;
    gpu.title = "GPU";
    gpu.mesh = Torus100k();
    gpu.mode = render::ShadingMode::Phong;
    gpu.backend = render::Backend::GPU;
    widgets::PanelSpec cpu = gpu;
    cpu.title = "CPU";
    cpu.backend = render::Backend::CPU;
    view.SetPanels({ gpu, cpu });
    view.resize(1300, 600);
    view.show();
    for (int i = 0; i < 10; ++i)
    {
      QApplication::processEvents();
    }
    view.ResetCamera(20, 30, 1.0, false);
    view.RenderAll();
    QApplication::processEvents();
  }
};

/// Made at first use, destroyed before the QApplication (widgets cannot
/// outlive it).
std::unique_ptr<Fixture> TheFixture;

Fixture& Get()
{
  if (!TheFixture)
  {
    TheFixture = std::make_unique<Fixture>();
  }
  return *TheFixture;
}

void Finish(widgets::ShadingPanel* panel)
{
  // GL commands are queued: wait until llvmpipe has drawn them.
  for (auto* w : panel->findChildren<QVTKOpenGLNativeWidget*>())
  {
    w->renderWindow()->WaitForCompletion();
  }
  QApplication::processEvents();
}

void BM_MaterialEdit(benchmark::State& state)
{
  Fixture& f = Get();
  const int index = static_cast<int>(state.range(0));
  widgets::ShadingPanel* panel = f.view.Panel(index);
  widgets::PanelSpec spec = panel->Spec();
  int step = 0;
  const int rendersBefore = panel->RenderCount();
  for (auto _ : state)
  {
    spec.material.shininess = 10.0 + (step++ % 50);
    f.view.SetPanelSpec(index, spec);
    Finish(panel);
  }
  state.SetLabel(index == 0 ? "GPU panel (QVTKOpenGLNativeWidget, llvmpipe)"
                            : "CPU panel (software renderer, all threads)");
  state.counters["renders_per_edit"] =
    static_cast<double>(panel->RenderCount() - rendersBefore) / std::max<int64_t>(1, state.iterations());
  state.counters["pixels"] = panel->Snapshot().width * panel->Snapshot().height;
}

void BM_CameraStep(benchmark::State& state)
{
  Fixture& f = Get();
  for (auto _ : state)
  {
    f.view.View().camera->Azimuth(1.0);
    f.view.RenderAll();
    Finish(f.view.Panel(0));
  }
  state.SetLabel("both panels");
}

} // namespace

BENCHMARK(BM_MaterialEdit)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CameraStep)->Unit(benchmark::kMillisecond)->UseRealTime();

int main(int argc, char** argv)
{
  std::string why;
  if (!gl::GpuAvailable(why))
  {
    std::cerr << "shadinglab_bench_explorer: " << why << "\n";
    return 2;
  }
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  TheFixture.reset();
  return 0;
}
