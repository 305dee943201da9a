#version 430 core
// Fragment shader of the mesh overlay: a fresnel rim. Surfaces seen edge-on glow, surfaces facing
// the camera stay clear, so the shape reads without hiding the volume inside.

in vec3 vPosition;
out vec4 fragColor;
uniform vec3 uEye;
uniform vec3 uMeshColor;
uniform bool uOrthographic;
uniform vec3 uViewDirection;
void main() {
  vec3 facet = cross(dFdx(vPosition), dFdy(vPosition));
  float facetLength = length(facet);
  vec3 toEye = uOrthographic ? -uViewDirection : normalize(uEye - vPosition);
  // Sub-pixel triangles have no usable derivative: treat them as seen edge-on.
  float facing = facetLength > 0.0 ? abs(dot(facet / facetLength, toEye)) : 0.0;
  float rim = 0.12 + 0.88 * pow(clamp(1.0 - facing, 0.0, 1.0), 3.0);
  fragColor = vec4(uMeshColor * rim, 1.0);
}
