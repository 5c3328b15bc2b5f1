  // ShadingLab: per-vertex work of the mode.
#if SL_MODE == 1
  {
    // Gouraud 1971: the model at the vertex; both sides, chosen per fragment.
    vec3 slP = vertexVCVSOutput.xyz;
    vec3 slN = normalize(normalVCVSOutput);
    vec3 slV = slCameraParallel == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-slP);
    slGouraudFrontVSOut = Shade(slDiffuseColor, slP, slN, slV);
    slGouraudBackVSOut = Shade(slDiffuseColor, slP, -slN, slV);
  }
#endif
#if SL_MODE == 0 || SL_MODE == 3
  slProvokingVCVSOut = vertexVCVSOutput;
#endif
#if SL_MODE == 3
  slNormalVCVSOut = normalVCVSOutput;
  slProvokingXYVSOut = (gl_Position.xy / gl_Position.w * 0.5 + 0.5) * slViewport.zw + slViewport.xy;
#endif
