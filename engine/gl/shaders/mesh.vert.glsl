#version 430 core
// Vertex shader of the mesh overlay (VolumeRenderer::drawMesh): world-space positions through the
// camera's view-projection; the world position travels on for the fragment shader's facets.

layout(location = 0) in vec3 aPosition;
uniform mat4 uViewProjection;
out vec3 vPosition;
void main() {
  vPosition = aPosition;
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
