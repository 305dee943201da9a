// Density estimation, scattered (flame_finisher.h): one sprite per entry of the list that
// finish_compact.comp.glsl made and finish_pack.comp.glsl packed (pixels whose kernel is wider
// than a pixel), drawn as a point (or, where the kernel is wider than the driver's points, a quad
// of six vertices) the size of its kernel, centred on the pixel in a target padded by the widest
// kernel's radius.

uniform sampler2D uDensity;  // sums: red·D, green·D, blue·D, D
uniform usamplerBuffer uSprites;
uniform ivec2 uSize;  // of the density image
uniform int uPad;     // the widest kernel's radius
uniform float uBrightness;
uniform bool uQuads;
// Per kernel: the Gaussian's exponent per squared pixel, 1 / (sum of its weights), radius, largest
// dx² + dy² inside it.
const int kMaxKernels = 192;
uniform vec4 uKernels[kMaxKernels];

flat out vec4 vValue;
flat out vec2 vCentre;
flat out vec3 vKernel;

void main() {
  uvec2 sprite = texelFetch(uSprites, uQuads ? gl_VertexID / 6 : gl_VertexID).xy;
  if (sprite.y == 0xFFFFFFFFu) {  // a pixel that scatters nothing: outside the clip volume
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    gl_PointSize = 1.0;
    return;
  }
  ivec2 p = ivec2(int(sprite.x) % uSize.x, int(sprite.x) / uSize.x);
  vec4 sums = texelFetch(uDensity, p, 0);
  vec4 kernel = uKernels[sprite.y];
  int radius = int(kernel.z);
  vValue = sums * logScale(sums.a, uBrightness);
  vKernel = vec3(kernel.x, kernel.y, kernel.w);
  vCentre = vec2(p + uPad) + 0.5;
  vec2 padded = vec2(uSize + 2 * uPad);
  vec2 position = vCentre;
  if (uQuads) {
    int corner = gl_VertexID % 6;
    vec2 side = vec2((corner == 1 || corner == 4 || corner == 5) ? 1.0 : -1.0,
                     (corner == 2 || corner == 3 || corner == 5) ? 1.0 : -1.0);
    position += side * (float(radius) + 0.5);
  }
  gl_Position = vec4(position / padded * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = float(2 * radius + 1);
}
