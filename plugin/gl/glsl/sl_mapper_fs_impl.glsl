  // ShadingLab: the illumination model replaces VTK's lighting.
  // rho: VTK's diffuse colour (property or scalars) without the Diffuse
  // coefficient; kd comes from the material.
  vec3 slRho = diffuseColor * slInvDiffuseIntensity;
  vec3 slColor;
#if SL_MODE == SL_MODE_FLAT
  {
    // Flat: VTK's face normal (cell normal, else the plane of the
    // triangle from position derivatives), lit at the provoking vertex:
    // one intensity per triangle.
    vec3 slP = slProvokingVCVSOut.xyz;
    vec3 slV = slCameraParallel == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-slP);
    slColor = Shade(slRho, slP, normalize(normalVCVSOutput), slV);
  }
#elif SL_MODE == SL_MODE_GOURAUD
  slColor = gl_FrontFacing ? slGouraudFrontVSOut + slRho * slGouraudFrontRhoVSOut
                           : slGouraudBackVSOut + slRho * slGouraudBackRhoVSOut;
#elif SL_MODE == SL_MODE_FAST_PHONG
  {
    // Bishop & Weimer 1986 about the provoking vertex (L, H fixed there).
    vec3 slNf = gl_FrontFacing ? slNormalVCVSOut : -slNormalVCVSOut;
    vec3 slA = dFdx(slNf);
    vec3 slB = dFdy(slNf);
    vec2 slUV = gl_FragCoord.xy - slProvokingXYVSOut;
    vec3 slN0 = slNf - slA * slUV.x - slB * slUV.y;
    vec3 slP0 = slProvokingVCVSOut.xyz;
    vec3 slV0 = slCameraParallel == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-slP0);
    // Where the normal has turned more than the spread limit away from the
    // expansion point's, the quadratic is unreliable: evaluate exactly.
    // (Per fragment here; the CPU decides per triangle from its vertex
    // normals, which a fragment shader cannot see.)
    float slCosSpread = dot(slN0, slNf) * inversesqrt(max(dot(slN0, slN0) * dot(slNf, slNf),
      SL_MIN_NORMAL_LENGTH_SQ * SL_MIN_NORMAL_LENGTH_SQ));
    bool slExact = slCosSpread < slFastPhongMinCos;
    vec3 slNexact = normalize(slNf);
    // Phong's R.V = 2 (N.L)(N.V) - L.V needs N.V as a quadratic too
    // (docs/model.md eq. 2.8).
    float slNoV = slExact ? dot(slV0, slNexact) : FastPhongQuadratic(slV0, slN0, slA, slB, slUV);
    slColor = slAmbient;
    for (int j = 0; j < SL_LIGHT_COUNT; ++j)
    {
      vec3 slL, slIrr;
      if (!LightIncidence(j, slP0, slL, slIrr))
      {
        continue;
      }
      float slNoL = min(slExact ? dot(slL, slNexact) : FastPhongQuadratic(slL, slN0, slA, slB, slUV), 1.0);
      if (!(slNoL > 0.0))
      {
        continue;
      }
      float slNoH = 0.0;
#if SL_SPECULAR && SL_MODEL == SL_MODEL_BLINN_PHONG
      vec3 slH = HalfVector(slL, slV0, normalize(slN0));
      slNoH = slExact ? dot(slH, slNexact) : FastPhongQuadratic(slH, slN0, slA, slB, slUV);
#endif
      float slRoV = 2.0 * slNoL * slNoV - dot(slL, slV0);
      slColor += slIrr * BrdfFromCosines(slRho, slNoH, slRoV) * slNoL;
    }
#if SL_ANALYSER
    slColor *= SL_POLARIZER_TRANSMITTANCE; // no Fresnel term: depolarized, half passes
#endif
  }
#else
  {
    // Phong: the interpolated normal, renormalized and flipped for back
    // faces by VTK's normal implementation tag above. (This comment must
    // not spell the tag: VTK substitutes every occurrence, and a copy here
    // flipped back faces twice, drawing inward-wound meshes black.)
    vec3 slP = vertexVC.xyz;
    vec3 slV = slCameraParallel == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-slP);
    slColor = Shade(slRho, slP, normalVCVSOutput, slV);
  }
#endif
  gl_FragData[0] = vec4(ApplyDisplay(slColor), opacity);
