#version 430 core
// Vertex shader of the full-screen passes (march.frag.glsl, blit.frag.glsl): one triangle that
// covers the whole viewport, its corners made from gl_VertexID, so no vertex buffer is needed.
// The fragment shaders do the work.

void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
