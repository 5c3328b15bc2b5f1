// ShadingLab fragment-shader declarations (vtkShadingLabPolyDataMapper).
uniform int slCameraParallel;
uniform float slInvDiffuseIntensity;
uniform float slFastPhongMinCos; // cos of the fast-phong spread limit
#if SL_MODE == SL_MODE_GOURAUD
SL_INTERP in vec3 slGouraudFrontVSOut;
SL_INTERP in vec3 slGouraudBackVSOut;
SL_INTERP in vec3 slGouraudFrontRhoVSOut;
SL_INTERP in vec3 slGouraudBackRhoVSOut;
#endif
#if SL_MODE == SL_MODE_FLAT || SL_MODE == SL_MODE_FAST_PHONG
flat in vec4 slProvokingVCVSOut;
#endif
#if SL_MODE == SL_MODE_FAST_PHONG
noperspective in vec3 slNormalVCVSOut;
flat in vec2 slProvokingXYVSOut;
#endif
