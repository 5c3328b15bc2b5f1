// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadingLabPolyDataMapper
 * @brief   the ShadingLab shading modes, drawn by the GPU or the CPU renderer
 *
 * The mapper applications and ParaView use. Its settings (SetSettings,
 * SetSetting: shadinglab/render/Settings.h's table) choose the mode, the
 * material and who draws (the Backend setting, render/Backend.h's chooser):
 * - GPU: the GL renderer's shaders (vtkShadingLabOpenGLPolyDataMapper, its
 *   superclass, in plugin/gl);
 * - CPU: the CPU software renderer (plugin/cpu) draws the input for the
 *   renderer's viewport, camera and lights, and hands its colour and depth
 *   to OpenGL (CpuBackend.h), so that other actors, annotations and
 *   compositing see an ordinary depth-tested surface;
 * - Auto: the CPU where OpenGL is a software rasterizer and the mesh is
 *   large, the GPU otherwise.
 * As VTK's vtkPolyDataMapper and vtkOpenGLPolyDataMapper, the front end
 * subclasses the GL implementation; the CPU one stays apart from plugin/gl.
 *
 * @warning Hardware selection (its pass needs the GL path's cell ids) and
 * translucent actors (the hand-over writes opaque pixels) are drawn with
 * OpenGL whatever the backend.
 */
#ifndef vtkShadingLabPolyDataMapper_h
#define vtkShadingLabPolyDataMapper_h

#include "vtkShadingLabOpenGLPolyDataMapper.h"

#include "shadinglabVTKModule.h" // for export macro

#include <memory>
#include <string>

class SHADINGLABVTK_EXPORT vtkShadingLabPolyDataMapper : public vtkShadingLabOpenGLPolyDataMapper
{
public:
  static vtkShadingLabPolyDataMapper* New();
  vtkTypeMacro(vtkShadingLabPolyDataMapper, vtkShadingLabOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The last render's backend and why ("cpu: OpenGL renderer 'llvmpipe
  /// ...' is a software rasterizer, 996000 polygons >= 30000";
  /// render::BackendChoice::why).
  const std::string& GetBackendChoice() const;

  ///@{
  /// Backend CPU: the last frame's render milliseconds, hand-over
  /// milliseconds (textures and quad) and mesh conversions so far (a camera
  /// move converts nothing).
  double GetCpuRenderMilliseconds() const;
  double GetCpuHandOverMilliseconds() const;
  int GetCpuMeshConversions() const;
  ///@}
  /// Benchmarks: make GetCpuHandOverMilliseconds include OpenGL's share of
  /// the hand-over (glFinish before and after it; stalls the pipeline).
  void SetCpuHandOverTimingFinishes(bool finish);

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkShadingLabPolyDataMapper();
  ~vtkShadingLabPolyDataMapper() override;

  /// The backend the chooser takes draws the piece; OpenGL also where the
  /// CPU could not (said once) or cannot (selection, translucency).
  void RenderPiece(vtkRenderer* ren, vtkActor* act) override;

private:
  vtkShadingLabPolyDataMapper(const vtkShadingLabPolyDataMapper&) = delete;
  void operator=(const vtkShadingLabPolyDataMapper&) = delete;

  /// Whether this render goes to the CPU (render::ChooseBackend with this
  /// window's GL_RENDERER and the input's size; GetBackendChoice says why).
  bool ChooseCpu(vtkRenderer* ren);
  /// Backend CPU; false (having said why once) when it could not draw.
  bool RenderPieceOnCpu(vtkRenderer* ren, vtkActor* act);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
