// The ray marcher as a compute stage (march_common.glsl): one invocation per pixel of a region,
// which folds its sample into the running average itself. GPUs built for compute (H100/H200 run
// fragment work on a few of their multiprocessors only) march many times faster this way.
layout(local_size_x = 8, local_size_y = 8) in;

layout(rgba32f) uniform image2D uTarget;
uniform ivec4 uRegion;  // x, y, width, height of the pixels written
uniform float uWeight;  // 1 / (samples before + 1): this sample's share of the average

void main() {
  ivec2 offset = ivec2(gl_GlobalInvocationID.xy);
  if (offset.x >= uRegion.z || offset.y >= uRegion.w) return;
  ivec2 pixel = uRegion.xy + offset;
  vec4 value = marchRay(vec2(pixel) + 0.5);
  // As the blend does it: this sample times w, plus the average so far times 1 − w. The first
  // sample ignores what is there (an uninitialised texel may hold NaN).
  if (uWeight < 1.0) value = value * uWeight + imageLoad(uTarget, pixel) * (1.0 - uWeight);
  imageStore(uTarget, pixel, value);
}
