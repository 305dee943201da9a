#version 430 core
// Fragment shader that draws a finished image (flame_image.h, uploaded as a texture) into the
// viewport, opaque (VolumeRenderer::resolve).

out vec4 fragColor;
uniform sampler2D uImage;
uniform vec4 uViewport;
void main() {
  vec2 uv = (gl_FragCoord.xy - uViewport.xy) / uViewport.zw;
  fragColor = vec4(texture(uImage, uv).rgb, 1.0);
}
