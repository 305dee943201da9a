// The ray marcher as a fragment stage (march_common.glsl): one pixel per fragment, the running
// average kept by blending. Used where the compute stage is not (VolumeRenderer::MarchStage).

out vec4 fragColor;

void main() { fragColor = marchRay(gl_FragCoord.xy); }
