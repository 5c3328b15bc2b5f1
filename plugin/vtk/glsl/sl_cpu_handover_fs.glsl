//VTK::System::Dec
// The CPU backend's hand-over (vtkShadingLabPolyDataMapper with Backend
// CPU, plugin/gl/CpuBackend.cxx): the software renderer's image and depth,
// drawn as one quad over the renderer's viewport. Pixels it did not cover
// are discarded; the others write their colour and their depth, so the
// framebuffer's depth test orders them against every other actor.
in vec2 texCoord;
uniform sampler2D slCpuColor; // RGBA8: display values, alpha 1 where covered
uniform sampler2D slCpuDepth; // R32F: normalized device depth z/w in [-1, 1]
//VTK::Output::Dec
void main()
{
  // The textures' first row is the rectangle's top row (the image's order).
  vec2 at = vec2(texCoord.x, 1.0 - texCoord.y);
  vec4 color = texture(slCpuColor, at);
  if (color.a < 0.5)
  {
    discard;
  }
  gl_FragData[0] = vec4(color.rgb, 1.0);
  // Window depth with glDepthRange(0, 1), as VTK keeps it.
  gl_FragDepth = 0.5 * texture(slCpuDepth, at).r + 0.5;
}
