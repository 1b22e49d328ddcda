#version 460
// The renderer's picture in its rectangle of the window (the presenter's render pass, over
// fullscreen.vert with the viewport on that rectangle), filtered as the sampler says. Its bytes
// are sRGB-encoded already and the window's format is UNORM, so they pass through unchanged.
layout(set = 0, binding = 0) uniform sampler2D picture;
layout(push_constant) uniform Placement {
  vec2 origin;      // the rectangle's top-left corner, in window pixels
  vec2 uvPerPixel;  // the picture's texture coordinates per window pixel
}
placement;
layout(location = 0) out vec4 colour;

void main() {
  vec2 uv = (gl_FragCoord.xy - placement.origin) * placement.uvPerPixel;
  colour = vec4(texture(picture, uv).rgb, 1.0);
}
