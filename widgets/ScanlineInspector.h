// SPDX-License-Identifier: BSD-3-Clause
// The scanline inspector: one triangle magnified until pixels are squares,
// drawn by the CPU renderer twice, with the per-row scan (exact
// interpolation) and with the lecture's incremental one (docs/model.md eq.
// 2.10-2.11). A click or drag picks the scan line and a pixel; the edge
// crossings x_4, x_5 with I_4, I_5 (Gouraud) or N_4, N_5 (Phong), every
// pixel's value, and slide 5's equations with the numbers of the picked
// pixel are shown. Every number is read back from the renderer's trace of
// that row (RenderOptions::traceRow), none is recomputed here.
#pragma once

#include "shadinglab/render/Image.h"
#include "shadinglab/render/Options.h"
#include "shadinglab/render/Scene.h"

#include <QWidget>

#include <memory>
#include <string>

class QComboBox;
class QLabel;

namespace shadinglab::widgets
{

class ScanlineInspector : public QWidget
{
  Q_OBJECT
public:
  explicit ScanlineInspector(QWidget* parent = nullptr);
  ~ScanlineInspector() override;

  /// The magnified image's size in pixels.
  static constexpr int kColumns = 14;
  static constexpr int kRows = 9;

  /// Gouraud (intensities stepped) or Phong (normals stepped).
  void SetMode(render::ShadingMode mode);
  void SetPrecision(render::ScanPrecision precision);
  /// The scan line (pixel row) and the pixel on it; clamped to the grid.
  void Select(int row, int column);
  int Row() const { return this->SelectedRow; }
  int Column() const { return this->SelectedColumn; }
  render::ShadingMode Mode() const { return this->ShadingMode; }

  /// The renderer's trace of the selected row: the per-row scan (exact
  /// interpolation) or the incremental one.
  const render::ScanTrace& Trace(bool incremental) const;
  /// The rendered images (linear, clamp display).
  const render::Image& Rendered(bool incremental) const;
  /// The selected pixel's value as shown: Gouraud's I (red channel of the
  /// traced lit colour), Phong's shaded intensity (red channel of the
  /// image); NaN when the pixel is outside the triangle.
  double SelectedValue(bool incremental) const;
  /// The equations panel's text (HTML).
  QString Equations() const;
  /// The row as CSV: pixel, exact and incremental values.
  std::string ToCsv() const;

signals:
  void selectionChanged();

private:
  class Canvas;
  friend class Canvas;
  void Rerender();
  void UpdateText();
  /// The traced pixel at column i, or nullptr.
  const render::TracedPixel* PixelAt(bool incremental, int i) const;
  /// The value a traced pixel shows (SelectedValue's rule).
  double ValueOf(bool incremental, const render::TracedPixel& p) const;

  render::ShadingMode ShadingMode = render::ShadingMode::Gouraud;
  render::ScanPrecision Precision = render::ScanPrecision::Float;
  int SelectedRow = 4, SelectedColumn = 6;
  render::Mesh Triangle;
  struct Result;
  std::unique_ptr<Result> Exact, Incremental;
  Canvas* Grid;
  QLabel* Text;
  QComboBox* ModeChoice;
  QComboBox* PrecisionChoice;
};

} // namespace shadinglab::widgets
