// SPDX-License-Identifier: BSD-3-Clause
// The VTK component: the GL mapper configured through its settings (no
// window needed).
#include "vtkShadingLabPolyDataMapper.h"

bool MapperTakesASetting()
{
  vtkShadingLabPolyDataMapper* mapper = vtkShadingLabPolyDataMapper::New();
  const bool set = mapper->SetSetting("mode", "gouraud");
  mapper->Delete();
  return set;
}
