  // ShadingLab: the illumination model replaces VTK's lighting.
  // rho: VTK's diffuse colour (property or scalars) without the Diffuse
  // coefficient; kd comes from the material.
  vec3 slRho = diffuseColor * slInvDiffuseIntensity;
  vec3 slColor;
#if SL_MODE == 0
  {
    // Flat: VTK's face normal (cell normal, else the plane of the
    // triangle from position derivatives), lit at the provoking vertex:
    // one intensity per triangle.
    vec3 slP = slProvokingVCVSOut.xyz;
    vec3 slV = slCameraParallel == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-slP);
    slColor = Shade(slRho, slP, normalize(normalVCVSOutput), slV);
  }
#elif SL_MODE == 1
  slColor = gl_FrontFacing ? slGouraudFrontVSOut : slGouraudBackVSOut;
#elif SL_MODE == 3
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
    float slCosSpread = dot(slN0, slNf) * inversesqrt(max(dot(slN0, slN0) * dot(slNf, slNf), 1e-24));
    bool slExact = slCosSpread < slFastPhongMinCos;
    vec3 slNexact = normalize(slNf);
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
      vec3 slF = slRho * (slKd * Fd_Lambert());
#if SL_SPECULAR
      vec3 slH = HalfVector(slL, slV0, normalize(slN0));
      float slNoH = slExact ? dot(slH, slNexact) : FastPhongQuadratic(slH, slN0, slA, slB, slUV);
      slF += slSpecularColor * (slKs * Fs_BlinnPhong(slNoH, slShininess));
#endif
      slColor += slIrr * slF * slNoL;
    }
  }
#else
  {
    // Phong / Cook-Torrance: the interpolated normal, renormalized and
    // flipped for back faces by VTK's //VTK::Normal::Impl.
    vec3 slP = vertexVC.xyz;
    vec3 slV = slCameraParallel == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-slP);
    slColor = Shade(slRho, slP, normalVCVSOutput, slV);
  }
#endif
  gl_FragData[0] = vec4(slColor, opacity);
