#version 430 core
// Density estimation, scattered (finish_scatter.vert.glsl): each covered pixel gets its share of
// the centre pixel's log value, flam3's Gaussian exp(-2 (1.5 d / width)²) over the discrete disc,
// normalised so the shares sum to the value. Added up by blending (GL_ONE, GL_ONE).

flat in vec4 vValue;
flat in vec2 vCentre;
flat in vec3 vKernel;  // the Gaussian's exponent per squared pixel, 1 / sum of weights, largest dx² + dy² inside
out vec4 fragColor;

void main() {
  vec2 d = gl_FragCoord.xy - vCentre;  // whole pixels
  float d2 = dot(d, d);
  // Compared as integers so the disc has exactly the pixels core::estimateDensity gives it.
  if (d2 > vKernel.z) discard;
  fragColor = vValue * (exp(d2 * vKernel.x) * vKernel.y);
}
