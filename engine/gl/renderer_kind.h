// What kind of OpenGL implementation the current context runs on, for the choices that are
// fastest on one kind and slow on the other: a software rasteriser (Mesa's llvmpipe) draws
// fragments as fast as it runs compute work and blends cheaply, while a compute GPU such as
// NVIDIA's H100 or H200 runs fragment work and blending on a few of its multiprocessors only.
// Main (GL) thread only, with a current context.
#pragma once

namespace voxflame::gl {

// True when GL_RENDERER names a software rasteriser: llvmpipe, softpipe, SwiftShader or
// Microsoft's GDI renderer.
bool softwareRasteriser();

}  // namespace voxflame::gl
