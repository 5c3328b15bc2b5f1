// ShadingLab vertex-shader declarations (vtkShadingLabPolyDataMapper).
uniform int slCameraParallel;
uniform vec3 slDiffuseColor;
uniform vec4 slViewport; // x, y, width, height of the viewport in pixels
#if SL_MODE == SL_MODE_GOURAUD
//SL::VertexRho::Dec
SL_INTERP out vec3 slGouraudFrontVSOut;
SL_INTERP out vec3 slGouraudBackVSOut;
SL_INTERP out vec3 slGouraudFrontRhoVSOut;
SL_INTERP out vec3 slGouraudBackRhoVSOut;
#endif
#if SL_MODE == SL_MODE_FLAT || SL_MODE == SL_MODE_FAST_PHONG
flat out vec4 slProvokingVCVSOut;
#endif
#if SL_MODE == SL_MODE_FAST_PHONG
noperspective out vec3 slNormalVCVSOut;
flat out vec2 slProvokingXYVSOut;
#endif
