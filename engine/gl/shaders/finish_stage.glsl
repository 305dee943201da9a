// The stage of a finishing pass that is built as either (flame_finisher.cpp's withStage): the pass
// defines FINISH_PIXEL as its vec4 function of one pixel (bottom-left origin); as a fragment stage
// each fragment is its pixel, as a compute stage (COMPUTE_STAGE) each invocation stores one pixel
// of uOutput.
#ifdef COMPUTE_STAGE
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f) writeonly uniform image2D uOutput;
uniform ivec2 uOutputSize;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (pixel.x >= uOutputSize.x || pixel.y >= uOutputSize.y) return;
  imageStore(uOutput, pixel, FINISH_PIXEL(pixel));
}
#else
out vec4 fragColor;

void main() { fragColor = FINISH_PIXEL(ivec2(gl_FragCoord.xy)); }
#endif
