// Shared by the finishing passes (flame_finisher.h): flam3's log density and the kernel choice of
// its density estimation, written to give what core/flame_image.cpp gives, in float.

// k1 · log(1 + k2 · D) / D: what a pixel's sums are scaled by (0 for an empty pixel). log1p in
// float: log(1 + x) alone loses the faint pixels' precision.
float logScale(float density, float brightness) {
  if (density <= 0.0) return 0.0;
  float x = 1.5 * density;
  float u = 1.0 + x;
  float log1p = u == 1.0 ? x : log(u) * x / (u - 1.0);
  return brightness * log1p / density;
}

// The kernel of a pixel with `hits` points: widths (radius · oversample + 1) / (hits + 1)^curve,
// never below the minimum, quantised in 4% steps from the widest (index 0).
uniform float uMaxWidth;
uniform float uMinWidth;
uniform float uCurve;
uniform int uKernelCount;
int kernelIndex(float hits) {
  float width = max(uMinWidth, uMaxWidth / pow(hits + 1.0, uCurve));
  int index = int(floor(log(uMaxWidth / width) / log(1.04) + 0.5));
  return clamp(index, 0, uKernelCount - 1);
}
