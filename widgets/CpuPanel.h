// SPDX-License-Identifier: BSD-3-Clause
// A panel drawn by the CPU software renderer (cpu::SoftwareRenderer), or a
// heat map of its error against a reference panel. The mouse moves the
// shared camera as VTK's trackball style does.
#pragma once

#include "ShadingPanel.h"

#include "shadinglab/render/Stokes.h"

#include <QImage>

#include <memory>

namespace shadinglab::cpu
{
class SoftwareRenderer;
}

namespace shadinglab::widgets
{

class ImageView;
class ProfileOverlay;

/// A mesh converted for the CPU renderer, with its world frame, re-made only
/// when the vtkPolyData changes.
struct CpuMeshCache
{
  render::Mesh Mesh;
  render::WorldFrame Frame;
  const void* Source = nullptr; ///< the vtkPolyData Mesh was made from
  unsigned long Time = 0;       ///< and its modification time then
  std::string ColorBy;          ///< and the array its scalars were taken from
  /// The mesh with the scalars of `colorBy` when it has that array.
  const render::Mesh& Get(vtkPolyData* polydata, const std::string& colorBy = {});
};

/**
 * Renders `spec` as a panel of `view` would at width x height with the CPU
 * renderer (the shared camera and light, clipping fitted to the mesh).
 * The panels and the explorer's parameter studies both draw through it.
 * An auto panel's choice is the renderer's (`stats`: drawnMode, autoChoice).
 * Throws what Renderer::Render throws.
 */
/// The scene RenderOnCpu draws: `spec`'s mesh (from `cache`) and material
/// under `view`'s camera and light, in the mesh's local frame.
render::Scene PanelScene(CpuMeshCache& cache, const PanelSpec& spec, const ViewState& view);

/// `image` (linear) with `display` applied in float, as a panel shows it.
render::Image DisplayValues(render::Image image, render::DisplayTransform display);

const render::Image& RenderOnCpu(cpu::SoftwareRenderer& renderer, CpuMeshCache& cache,
  const PanelSpec& spec, const ViewState& view, int width, int height,
  render::RenderStats* stats = nullptr);

class CpuPanel final : public ShadingPanel
{
  Q_OBJECT
public:
  CpuPanel(const PanelSpec& spec, ViewState* view, QWidget* parent);
  ~CpuPanel() override;

  /// The last image in display values (the view's display transform), as
  /// a GPU panel reads its framebuffer.
  render::Image Snapshot() override;
  render::Backend Backend() const override { return render::Backend::CPU; }
  /// A DoLP panel's last Stokes image (PanelSpec::dolpImage), else empty.
  const render::StokesImage& LastStokes() const { return this->Stokes; }

protected:
  bool RenderView() override;
  void OnSpecChanged() override;
  void OnProfileLineChanged() override;

private:
  /// |I - I_ref| as a heat map (and the colour bar), both images in
  /// display values from float frames.
  QImage HeatMap(const render::Image& reference);
  /// The reference panel's picture drawn here by the CPU renderer in float
  /// (the panel itself may be a GPU one, whose 8-bit framebuffer would
  /// quantize the difference into speckle and rings), in display values.
  render::Image ReferenceOnCpu(int width, int height);
  /// The degree of linear polarization in viridis (and the colour bar).
  QImage DolpMap() const;

  std::unique_ptr<cpu::SoftwareRenderer> Renderer;
  ImageView* ViewWidget;
  ProfileOverlay* Overlay;
  CpuMeshCache Cache;
  CpuMeshCache ReferenceCache; ///< the reference panel's mesh, converted here
  render::Image Last;
  render::StokesImage Stokes;
};

} // namespace shadinglab::widgets
