// The rest of the finish (flame_finisher.h), one output pixel each: flam3's spatial filter from the
// supersampled log image, gamma with a linear threshold, vibrancy, highlight power, background,
// the mesh overlay (ghost or silhouette), contrast, exposure, and the display encoding or linear
// light. A port of core::finishImage's per-pixel code; alpha carries the pattern's opacity. Its
// stage (fragment or compute) comes from finish_stage.glsl, which calls tonePixel.

uniform sampler2D uLog;      // log image of a region of the supersampled image
uniform ivec2 uLogOrigin;    // its lower-left pixel in the full supersampled image
uniform ivec2 uFullSize;     // of the full supersampled image
uniform ivec2 uOutOrigin;    // this pass's lower-left output pixel in the full output image
uniform ivec2 uOutFullSize;  // of the full output image
uniform int uOversample;
uniform int uTaps;
uniform int uTapOffset;
const int kMaxTaps = 128;
uniform float uFilter[kMaxTaps];  // 1D weights; the 2D ones are their products

uniform float uGamma;
uniform float uGammaThreshold;
uniform float uVibrancy;
uniform float uHighlightPower;
uniform float uExposure;  // linear factor
uniform float uContrast;
uniform vec3 uBackground;  // display-encoded
// LINEAR_OUTPUT: linear light (for EXR), else display-encoded and clamped.

// The overlay is compiled in by OVERLAY_GHOST or OVERLAY_SILHOUETTE (FlameFinisher::toneProgram).
uniform sampler2D uOverlay;
uniform ivec2 uOverlayOrigin;  // of the overlay region in the full output image
uniform float uOverlayStrength;
uniform vec3 uLineColor;  // display-encoded

float gammaAlpha(float density, float g, float threshold) {
  if (density <= 0.0) return 0.0;
  if (density < threshold) {
    float fraction = density / threshold;
    return (1.0 - fraction) * density * pow(threshold, g) / threshold + fraction * pow(density, g);
  }
  return pow(density, g);
}

vec3 rgbToHsv(vec3 c) {
  float maxC = max(c.r, max(c.g, c.b)), minC = min(c.r, min(c.g, c.b));
  float delta = maxC - minC;
  float h = 0.0;
  if (delta > 0.0) {
    if (maxC == c.r)
      h = (c.g - c.b) / delta;
    else if (maxC == c.g)
      h = 2.0 + (c.b - c.r) / delta;
    else
      h = 4.0 + (c.r - c.g) / delta;
    h /= 6.0;
    if (h < 0.0) h += 1.0;
  }
  return vec3(h, maxC > 0.0 ? delta / maxC : 0.0, maxC);
}

vec3 hsvToRgb(vec3 c) {
  vec3 offset = vec3(1.0, 2.0 / 3.0, 1.0 / 3.0);
  vec3 k = c.x + offset;
  k = abs((k - floor(k)) * 6.0 - 3.0);
  return c.z * (1.0 + (clamp(k - 1.0, 0.0, 1.0) - 1.0) * c.y);
}

// flam3's calc_newrgb (core::scaledColor).
vec3 scaledColor(vec3 c, float ls, float highlightPower) {
  float maxChannel = max(c.r, max(c.g, c.b));
  if (ls <= 0.0 || maxChannel <= 0.0) return vec3(0.0);
  float maxScaled = ls * maxChannel;
  if (maxScaled > 1.0 && highlightPower >= 0.0) {
    float newScale = 1.0 / maxChannel;
    float saturationKept = pow(newScale / ls, highlightPower);
    vec3 hsv = rgbToHsv(newScale * c);
    hsv.y *= saturationKept;
    return hsvToRgb(hsv);
  }
  float blend = maxScaled <= 1.0 ? 1.0 : min(1.0, -highlightPower);
  return ((1.0 - blend) + blend * ls) * c;
}

vec4 overlayAt(ivec2 full) {
  full = clamp(full, ivec2(0), uOutFullSize - 1);
  return texelFetch(uOverlay, full - uOverlayOrigin, 0);
}

// The finished pixel `local` of this pass (bottom-left origin).
vec4 tonePixel(ivec2 local) {
  ivec2 pixel = local + uOutOrigin;
  vec4 v = vec4(0.0);
  for (int j = 0; j < uTaps; ++j) {
    int sy = pixel.y * uOversample - uTapOffset + j;
    if (sy < 0 || sy >= uFullSize.y) continue;
    vec4 row = vec4(0.0);
    for (int i = 0; i < uTaps; ++i) {
      int sx = pixel.x * uOversample - uTapOffset + i;
      if (sx < 0 || sx >= uFullSize.x) continue;
      row += uFilter[i] * texelFetch(uLog, ivec2(sx, sy) - uLogOrigin, 0);
    }
    v += uFilter[j] * row;
  }

  float g = 1.0 / uGamma;
  vec3 c = max(v.rgb, vec3(0.0)) * uExposure;
  float density = max(0.0, v.a * uExposure);
  // An empty pixel (most of a typical frame) is the background: the tone's math gives 0 for it.
  float alpha = 0.0;
  vec3 color = vec3(0.0);
  if (density > 0.0 || any(greaterThan(c, vec3(0.0)))) {
    alpha = gammaAlpha(density, g, uGammaThreshold);
    float ls = density > 0.0 ? uVibrancy * alpha / density : 0.0;
    color = scaledColor(c, ls, uHighlightPower);
    if (uVibrancy != 1.0) color += (1.0 - uVibrancy) * pow(c, vec3(g));
  }
  // The contrast is the pattern's, around mid grey where it covers the pixel; the background
  // (as chosen, whatever the gamma) shows through where it does not, and the mesh's overlay goes
  // on top: an empty pixel is exactly the background's colour.
  float covered = min(alpha, 1.0);
  color = (color - 0.5 * covered) * uContrast + 0.5 * covered;
  color += (1.0 - covered) * uBackground;
#if defined(OVERLAY_GHOST)
  color += uOverlayStrength * overlayAt(pixel).rgb;
#elif defined(OVERLAY_SILHOUETTE)
  {
    float centre = overlayAt(pixel).a;
    float edge = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) edge = max(edge, abs(overlayAt(pixel + ivec2(dx, dy)).a - centre));
    color = mix(color, uLineColor, clamp(edge * uOverlayStrength * 2.5, 0.0, 1.0));
  }
#endif
#ifdef LINEAR_OUTPUT
  color = pow(max(color, vec3(0.0)), vec3(uGamma));
#else
  color = clamp(color, 0.0, 1.0);
#endif
  return vec4(color, min(alpha, 1.0));
}
