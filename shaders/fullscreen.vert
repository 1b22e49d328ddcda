#version 460
// One triangle that covers the whole viewport (its corners at -1, 3 on each axis), for a
// fragment shader that runs once a pixel; it draws three vertices and no vertex buffer.
void main() {
  vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
