#version 460
// One colour over the scissor's rectangle: the HUD's bars and frames, and the black bars beside
// a picture that does not fill the window (the presenter's render pass, over fullscreen.vert).
layout(push_constant) uniform Fill { vec4 colour; }
fill;
layout(location = 0) out vec4 colour;

void main() { colour = fill.colour; }
