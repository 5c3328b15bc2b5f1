  // ShadingLab: per-vertex work of the mode.
#if SL_MODE == SL_MODE_GOURAUD
  {
    // Gouraud 1971: the model at the vertex; both sides, chosen per fragment.
    vec3 slP = vertexVCVSOutput.xyz;
    vec3 slN = normalize(normalVCVSOutput);
    vec3 slV = slCameraParallel == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-slP);
#ifdef SL_VERTEX_RHO
    // Colours per vertex: the whole model at the vertex, as the CPU renderer.
    slGouraudFrontVSOut = Shade(SL_VERTEX_RHO, slP, slN, slV);
    slGouraudBackVSOut = Shade(SL_VERTEX_RHO, slP, -slN, slV);
    slGouraudFrontRhoVSOut = vec3(0.0);
    slGouraudBackRhoVSOut = vec3(0.0);
#else
    // The colour is known per fragment only (a uniform colour, colours
    // mapped through a texture with Interpolate Scalars Before Mapping, or
    // cell colours): Shade is linear in rho, so the vertex carries
    // Shade(0) and the factor Shade(1) - Shade(0) that rho multiplies.
    slGouraudFrontVSOut = Shade(vec3(0.0), slP, slN, slV);
    slGouraudBackVSOut = Shade(vec3(0.0), slP, -slN, slV);
    slGouraudFrontRhoVSOut = Shade(vec3(1.0), slP, slN, slV) - slGouraudFrontVSOut;
    slGouraudBackRhoVSOut = Shade(vec3(1.0), slP, -slN, slV) - slGouraudBackVSOut;
#endif
  }
#endif
#if SL_MODE == SL_MODE_FLAT || SL_MODE == SL_MODE_FAST_PHONG
  slProvokingVCVSOut = vertexVCVSOutput;
#endif
#if SL_MODE == SL_MODE_FAST_PHONG
  slNormalVCVSOut = normalVCVSOutput;
  slProvokingXYVSOut = (gl_Position.xy / gl_Position.w * 0.5 + 0.5) * slViewport.zw + slViewport.xy;
#endif
