// JWildfire's obj_mesh_primitive_wf draws random points on the surface of one of a list of built-in
// meshes (JWildfire ships them as Wavefront files). voxflame builds the same shapes from their
// geometry (variations_jwildfire_mesh.cpp): the Platonic and Archimedean solids, box, ring ("wedge"),
// ball, torus, cone, capsule and diamond, with JWildfire's size, orientation and tessellation. The
// gears, the Mandelbulb and the drop are not reproduced. Exposed for the importer's warnings and
// the tests.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace voxflame::core {

// JWildfire's list, in its order: the `primitive` parameter indexes it.
inline constexpr std::size_t kObjMeshPrimitiveCount = 26;
const char* objMeshPrimitiveName(std::size_t index);
// Whether voxflame builds the primitive (false for the gears, mandelbulb and drop: they draw nothing).
bool objMeshPrimitiveReproduced(std::size_t index);

// The primitive a parameter value means: JWildfire rounds it (Tools.FTOI, half away from 0; NaN is
// 0). Values outside the list give kObjMeshPrimitiveCount: JWildfire then draws its stand-in mesh,
// a cube from −1 to 1.
std::size_t objMeshPrimitiveIndex(double value);

// A triangle mesh as obj_mesh_primitive_wf samples it: vertices as JWildfire keeps them (floats),
// three vertex indices per face, and how often each face is picked. JWildfire repeats a face in its
// list by round(area / smallest area), at most 5000 times (distributeFaces), when the areas differ;
// `cumulative[i]` is the sum of those counts of faces 0 … i. Empty: every face alike (equal areas,
// or a subdivided mesh, which JWildfire does not weight).
struct PrimitiveMesh {
  std::vector<float> vertices;  // x, y, z of each vertex
  std::vector<std::uint32_t> faces;
  std::vector<std::uint64_t> cumulative;
  std::size_t faceCount() const { return faces.size() / 3; }
};

// The mesh of `index` (objMeshPrimitiveIndex's value), subdivided `subdivLevel` times (0–6), each
// time followed by `smoothPasses` passes of Taubin smoothing with lambda and mu (JWildfire's
// SimpleMesh.interpolate and taubinSmooth). An index not reproduced gives an empty mesh.
PrimitiveMesh buildObjMeshPrimitive(std::size_t index, int subdivLevel, int smoothPasses, double lambda, double mu);

}  // namespace voxflame::core
