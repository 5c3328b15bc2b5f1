// SPDX-License-Identifier: BSD-3-Clause
// Fast Phong (Bishop & Weimer 1986): the GLSL twin of
// FastPhongTriangle::ExpandAbout + FastPhongQuadratic::Evaluate in
// plugin/model/include/shadinglab/model/FastPhong.h (derivation there).
// The affine normal field N(x, y) = A x + B y + C is reconstructed per
// fragment: N0 (the field at the expansion point), A = dN/dx, B = dN/dy
// (screen derivatives of the screen-linear interpolated normal, exact for an
// affine field). A GPU has no scanline to step along, so the quadratic is
// evaluated directly instead of by forward differences.

// (L.N)/|N| by its second-order Taylor expansion about (x0, y0), evaluated
// at offset (u, v) = (x - x0, y - y0).
float FastPhongQuadratic(vec3 L, vec3 N0, vec3 A, vec3 B, vec2 uv)
{
  float q0 = dot(N0, N0);
  // No direction, intensity 0.
  if (!(q0 >= SL_MIN_NORMAL_LENGTH_SQ))
  {
    return 0.0;
  }
  float a = dot(L, A), b = dot(L, B), n0 = dot(L, N0);
  float d = dot(A, A), e = 2.0 * dot(A, B), f = dot(B, B);
  float qx = 2.0 * dot(A, N0), qy = 2.0 * dot(B, N0);
  float r = inversesqrt(q0);
  float px = qx / q0, py = qy / q0;
  float T0 = r * n0;
  float T2 = r * (a - 0.5 * n0 * px);
  float T1 = r * (b - 0.5 * n0 * py);
  float T5 = r * (-0.5 * a * px - 0.5 * n0 * d / q0 + 0.375 * n0 * px * px);
  float T4 = r * (-0.5 * (a * py + b * px) - 0.5 * n0 * e / q0 + 0.75 * n0 * px * py);
  float T3 = r * (-0.5 * b * py - 0.5 * n0 * f / q0 + 0.375 * n0 * py * py);
  float u = uv.x, v = uv.y;
  return ((T5 * u + T4 * v + T2) * u) + ((T3 * v + T1) * v) + T0;
}
