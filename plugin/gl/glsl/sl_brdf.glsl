// SPDX-License-Identifier: BSD-3-Clause
// BRDF terms of the shading model: the GLSL twin of
// plugin/model/include/shadinglab/model/{Constants,Fresnel,Brdf}.h. Same
// names, same guards, same constants; the CPU/GPU parity test keeps them
// together. Directions are unit vectors pointing away from the surface.

// SL_PI, SL_INV_PI and the guards (SL_MIN_COS_THETA, ...) are #defines
// generated from Constants.h at build time (GenerateGlslDefines.cpp).

// Lambert 1760; docs/model.md eq. 1.2: Rd = 1/pi.
float Fd_Lambert()
{
  return SL_INV_PI;
}

// Lommel-Seeliger (Seeliger 1888; Hapke 1981), scaled to equal Lambert at
// normal incidence and view; docs/model.md eq. 1.12.
float Fd_LommelSeeliger(float NoL, float NoV)
{
  return 2.0 * SL_INV_PI / max(NoL + NoV, SL_MIN_COS_THETA);
}

// Phong 1975, (R.V)^n, normalized by (n+2)/(2 pi) (Lewis 1994);
// docs/model.md eq. 1.3.
float Fs_Phong(float RoV, float shininess)
{
  float lobe = (shininess + 2.0) * (0.5 * SL_INV_PI) * pow(clamp(RoV, 0.0, 1.0), shininess);
  return RoV > 0.0 ? lobe : 0.0;
}

// Blinn 1977, (N.H)^n, normalized by (n+8)/(8 pi).
float Fs_BlinnPhong(float NoH, float shininess)
{
  float lobe = (shininess + 8.0) * (0.125 * SL_INV_PI) * pow(clamp(NoH, 0.0, 1.0), shininess);
  return NoH > 0.0 ? lobe : 0.0;
}

// Beckmann distribution, Cook & Torrance 1982 (docs/model.md eq. 1.6), without 1/pi.
float D_Beckmann(float NoH, float m)
{
  float c = clamp(NoH, 0.0, 1.0);
  m = clamp(m, SL_MIN_ROUGHNESS, SL_MAX_ROUGHNESS);
  float cos2Alpha = c * c;
  float cos4Alpha = cos2Alpha * cos2Alpha;
  float tan2Alpha = (1.0 - cos2Alpha) / max(cos2Alpha, SL_TINY_DENOMINATOR);
  float m2 = m * m;
  float D = exp(-tan2Alpha / m2) / (m2 * max(cos4Alpha, SL_MIN_COS4_ALPHA));
  return (NoH > 0.0 && cos4Alpha >= SL_MIN_COS4_ALPHA) ? D : 0.0;
}

// D = sum_k w_k D(m_k) (docs/model.md eq. 1.7).
float D_BeckmannMixture(float NoH, float weights[SL_MAX_LOBES], float ms[SL_MAX_LOBES], int count)
{
  float D = 0.0;
  for (int k = 0; k < count; ++k)
  {
    D += weights[k] * D_Beckmann(NoH, ms[k]);
  }
  return D;
}

// Torrance & Sparrow 1967 V-groove attenuation (docs/model.md eq. 1.10):
// min(1, Gs, Gm) = min(1, 2 (N.H) min(N.L, N.V) / (V.H)); V.H -> 0 gives 1.
float G_CookTorrance(float NoH, float NoV, float NoL, float VoH)
{
  float G = min(1.0, 2.0 * NoH * min(NoL, NoV) / max(VoH, SL_MIN_VOH));
  G = VoH < SL_MIN_VOH ? 1.0 : G;
  return (NoL > 0.0 && NoV > 0.0 && NoH > 0.0) ? G : 0.0;
}

// Cook & Torrance 1982 unpolarized Fresnel (docs/model.md eq. 1.8), cosine form (finite
// at normal incidence; equal in value to the slide's form).
float F_Dielectric(float cosTheta_i, float eta)
{
  cosTheta_i = clamp(cosTheta_i, 0.0, 1.0);
  float sin2Theta_i = max(0.0, 1.0 - cosTheta_i * cosTheta_i);
  float sin2Theta_t = sin2Theta_i / (eta * eta);
  // Handle total internal reflection case (selected below).
  bool tir = sin2Theta_t >= 1.0;
  float cosTheta_t = sqrt(max(1.0 - sin2Theta_t, 0.0));
  float rs = (cosTheta_i - eta * cosTheta_t) / (cosTheta_i + eta * cosTheta_t);
  float rp = (eta * cosTheta_i - cosTheta_t) / (eta * cosTheta_i + cosTheta_t);
  float F = 0.5 * (rs * rs + rp * rp);
  // eta == 1: an invisible interface (the cosine form is 0/0 at grazing).
  return eta == 1.0 ? 0.0 : (tir ? 1.0 : F);
}

// Exact Fresnel of a conductor with complex index eta + i k (Born & Wolf
// sec. 14.2; docs/model.md eq. 1.9), in real arithmetic: a^2 + b^2, a and
// b with n cos(theta_t) = a + i b: Rs and Rp (eq. 8.1; k = 0 a dielectric)
// and C + i D = rs rp* (eq. 8.2), F_ConductorMueller in Fresnel.h;
// F_Conductor below is the mean of Rs and Rp.
void F_ConductorMueller(float cosTheta_i, float eta, float k, out float Rs, out float Rp,
  out float C, out float D)
{
  cosTheta_i = clamp(cosTheta_i, 0.0, 1.0);
  float cos2Theta_i = cosTheta_i * cosTheta_i;
  float sin2Theta_i = max(0.0, 1.0 - cos2Theta_i);
  float t0 = eta * eta - k * k - sin2Theta_i;
  float etaK = eta * k;
  float a2plusb2 = sqrt(t0 * t0 + 4.0 * etaK * etaK);
  float sum = a2plusb2 + abs(t0);
  bool positive = t0 >= 0.0;
  float a = sqrt(positive ? 0.5 * sum : 2.0 * etaK * etaK / max(sum, SL_TINY_DENOMINATOR));
  float b = positive ? etaK / max(a, SL_TINY_DENOMINATOR) : sqrt(0.5 * sum);
  float t1 = a2plusb2 + cos2Theta_i;
  float t2 = 2.0 * cosTheta_i * a;
  Rs = (t1 - t2) / max(t1 + t2, SL_TINY_DENOMINATOR);
  float t3 = cos2Theta_i * a2plusb2 + sin2Theta_i * sin2Theta_i;
  float t4 = t2 * sin2Theta_i;
  float invP = 1.0 / (t3 + t4);
  Rp = Rs * (t3 - t4) * invP;
  C = -Rs * (cos2Theta_i * a2plusb2 - sin2Theta_i * sin2Theta_i) * invP;
  D = Rs * (2.0 * b * cosTheta_i * sin2Theta_i) * invP;
}

// Rs and Rp alone: F_ConductorSP (the compiler drops C and D).
void F_ConductorSP(float cosTheta_i, float eta, float k, out float Rs, out float Rp)
{
  float C, D;
  F_ConductorMueller(cosTheta_i, eta, k, Rs, Rp, C, D);
}

float F_Conductor(float cosTheta_i, float eta, float k)
{
  if (k == 0.0)
  {
    return F_Dielectric(cosTheta_i, eta);
  }
  float Rs, Rp;
  F_ConductorSP(cosTheta_i, eta, k, Rs, Rp);
  return 0.5 * (Rs + Rp);
}

// Fresnel's Mueller matrix per channel (eq. 8.2): A = (Rs + Rp) / 2,
// B = (Rs - Rp) / 2, C + i D = rs rp*: F_RGB_Mueller.
void F_RGB_Mueller(float cosTheta_i, vec3 eta, vec3 k, out vec3 A, out vec3 B, out vec3 C,
  out vec3 D)
{
  for (int c = 0; c < 3; ++c)
  {
    float Rs, Rp, Cc, Dc;
    F_ConductorMueller(cosTheta_i, eta[c], k[c], Rs, Rp, Cc, Dc);
    A[c] = 0.5 * (Rs + Rp);
    B[c] = 0.5 * (Rs - Rp);
    C[c] = Cc;
    D[c] = Dc;
  }
}

vec3 F_RGB(float cosTheta_i, vec3 eta, vec3 k)
{
  return vec3(F_Conductor(cosTheta_i, eta.x, k.x), F_Conductor(cosTheta_i, eta.y, k.y),
    F_Conductor(cosTheta_i, eta.z, k.z));
}

// Fresnel per wavelength reduced to linear sRGB (docs/model.md eq. 7.3):
// F_rgb = sum_i w_i F(cos theta_i; eta_i, k_i). The same as F_Spectral in
// Fresnel.h.
vec3 F_Spectral(float cosTheta_i, float eta[SL_SPECTRAL_SAMPLES], float k[SL_SPECTRAL_SAMPLES],
  vec3 weight[SL_SPECTRAL_SAMPLES])
{
  vec3 F = vec3(0.0);
  for (int i = 0; i < SL_SPECTRAL_SAMPLES; ++i)
  {
    F += weight[i] * F_Conductor(cosTheta_i, eta[i], k[i]);
  }
  return F;
}

#if SL_SPECTRAL
// The same per wavelength, weighted as F_Spectral: F_Spectral_Mueller.
void F_Spectral_Mueller(float cosTheta_i, float eta[SL_SPECTRAL_SAMPLES],
  float k[SL_SPECTRAL_SAMPLES], vec3 weight[SL_SPECTRAL_SAMPLES], out vec3 A, out vec3 B,
  out vec3 C, out vec3 D)
{
  A = vec3(0.0);
  B = vec3(0.0);
  C = vec3(0.0);
  D = vec3(0.0);
  for (int i = 0; i < SL_SPECTRAL_SAMPLES; ++i)
  {
    float Rs, Rp, Ci, Di;
    F_ConductorMueller(cosTheta_i, eta[i], k[i], Rs, Rp, Ci, Di);
    A += weight[i] * (0.5 * (Rs + Rp));
    B += weight[i] * (0.5 * (Rs - Rp));
    C += weight[i] * Ci;
    D += weight[i] * Di;
  }
}
#endif

// Rs of Cook & Torrance 1982 (jacobian 1) or Walter et al. 2007 (jacobian 4).
float Fs_CookTorrance(float F, float D, float G, float NoL, float NoV, float jacobian)
{
  float denominator = max(NoL, SL_MIN_COS_THETA) * max(NoV, SL_MIN_COS_THETA);
  float Rs = F * D * G * SL_INV_PI / (jacobian * denominator);
  return (NoL > 0.0 && NoV > 0.0) ? Rs : 0.0;
}

// Blinn 1977 half vector; N when L = -V (see Constants.h).
vec3 HalfVector(vec3 L, vec3 V, vec3 N)
{
  vec3 s = L + V;
  float lengthSq = dot(s, s);
  bool defined = lengthSq >= SL_MIN_HALF_VECTOR_LENGTH * SL_MIN_HALF_VECTOR_LENGTH;
  return defined ? s * inversesqrt(max(lengthSq, SL_TINY_DENOMINATOR)) : N;
}

// glTF 2.0's metallic convention on the exact Fresnel term (docs/model.md
// eq. 9.4; Shading.h F_Tinted): the data colour c at normal incidence,
// rising to white as the metal's own F rises from its F0.
vec3 F_Tinted(vec3 F, vec3 F0, vec3 c)
{
  vec3 w = clamp((F - F0) / max(vec3(1.0) - F0, vec3(SL_MIN_FRESNEL_GAP)), 0.0, 1.0);
  return c + (vec3(1.0) - c) * w;
}
