  // ShadingLab: per-vertex work of the mode.
#if SL_MODE == SL_MODE_GOURAUD
  {
    // Gouraud 1971: the model at the vertex; both sides, chosen per fragment.
    vec3 slP = vertexVCVSOutput.xyz;
    vec3 slN = normalize(normalVCVSOutput);
    vec3 slV = slCameraParallel == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-slP);
    slGouraudFrontVSOut = Shade(slDiffuseColor, slP, slN, slV);
    slGouraudBackVSOut = Shade(slDiffuseColor, slP, -slN, slV);
  }
#endif
#if SL_MODE == SL_MODE_FLAT || SL_MODE == SL_MODE_FAST_PHONG
  slProvokingVCVSOut = vertexVCVSOutput;
#endif
#if SL_MODE == SL_MODE_FAST_PHONG
  slNormalVCVSOut = normalVCVSOutput;
  slProvokingXYVSOut = (gl_Position.xy / gl_Position.w * 0.5 + 0.5) * slViewport.zw + slViewport.xy;
#endif
