// The volume in the form the renderer uploads: a half-float density per voxel, relative to the
// mesh's mean (what the march tests and integrates), and a half-float RGBA texel per colour cell
// holding the cell's mean colour premultiplied by its density, so trilinear filtering blends colour
// by density and empty neighbours never darken an edge. Colour cells are voxels, or 2×2×2 voxels
// on grids above 256³ (ColourLayout): there the colour takes an eighth of the memory and upload.
// Per brick of 4³ voxels, the distance to the nearest brick with density lets the ray-marcher leap
// over empty space, far in one step where it is wide. Packing runs on whichever thread reads the
// grid, so the main thread only uploads.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "core/refinement/refinement_backend.h"
#include "grid.h"

namespace voxflame::core {

// Small bricks skip more: in bench raymarch's 1280×720 frame of the default preset at 256³, rays
// take 12 M steps in bricks with density at 4³ against 20 M at 8³, of which 5 M see any.
inline constexpr int kBrickShift = 2;
inline constexpr int kBrickSize = 1 << kBrickShift;
// Empty distances stop here (an R8UI texel): a ray in the middle of nothing leaps at most this
// many bricks at once.
inline constexpr int kMaxEmptyDistance = 255;

// A packed volume that lives in the GPU's memory instead of the host's: what a GPU refinement backend
// packs where the renderer can read it (gl/gpu_volume.h). Opaque here: core knows no GL.
class DeviceVolume {
 public:
  virtual ~DeviceVolume() = default;
};

struct PackedVolume {
  GridGeometry geometry;
  std::vector<std::uint16_t> density;  // a half float per voxel, x fastest: the march tests it first,
                                       // and one channel filters far faster than four in software GL
  ColourLayout colour;                 // how colour cells divide the voxels
  std::vector<std::uint16_t> colours;  // 4 half floats per colour cell: its mean colour times a,
                                       // a = its voxels' mean density (what blends neighbours)
  glm::ivec3 brickCount{0};
  std::vector<std::uint8_t> occupancy;  // 1 where a brick, grown by one voxel, holds density
  // Per brick, 0 where it is occupied, else the Chebyshev distance in bricks to the nearest
  // occupied one (at most kMaxEmptyDistance): the cube of bricks within distance − 1 of it is
  // empty, so a ray inside it leaps to its far side in one step.
  std::vector<std::uint8_t> emptyDistance;
  float maxDensity = 0.0f;
  // Hits one unit of texel density stands for: referenceDensity, so texels hold density relative
  // to the mesh's mean. Two snapshots of one pattern then agree voxel by voxel whatever their point
  // counts, and slabs of both can share a texture while a new one streams in without a seam (a
  // normalisation by the densest voxel would jump with that one noisy voxel).
  float texelDensity = 1.0f;
  float meanDensity = 0.0f;  // over voxels with any density: the scale of a "typical" voxel
  // Hits in the grid over the voxels inside the mesh: the mean density a uniformly filled mesh
  // would have. Densities relative to it do not change with the point count or the grid.
  double referenceDensity = 1.0;
  double insideVoxels = 0.0;  // voxels inside the mesh (or, when unknown, those with any density)
  std::uint64_t version = 0;
  std::uint64_t generation = 0;
  std::uint64_t points = 0;
  // The accumulator last packed into this buffer (GridReading::gridId; 0: none): a buffer it
  // packed before already holds zeros wherever its mask has no voxel, so those rows are skipped.
  std::uint64_t packedFromGrid = 0;
  // Set where the volume was packed on the GPU (RefinementBackend::packOnDevice): the textures are
  // there, and density, colours, occupancy and emptyDistance above are empty (maxDensity and
  // meanDensity are not measured). The renderer copies it on the GPU instead of uploading.
  std::shared_ptr<DeviceVolume> device;
  bool onDevice() const { return device != nullptr; }
};

// From a snapshot (stills, tests): a colour cell per voxel.
void packVolume(const VolumeSnapshot& snapshot, PackedVolume& out);
// Straight from a running accumulator, slab by slab, in its colour layout: no full-size copy of the
// grid exists in between (what the explorer's snapshot thread does). Once `cancel` (when given)
// reads true the remaining slabs are skipped and false is returned: `out` is then not a volume to
// show (its packedFromGrid still says whether its outside rows are zero). A pack at 512³ takes
// half a second of a core, which the frames of a drag that began meanwhile need more.
// A backend that packs on the GPU for the renderer (RefinementBackend::packOnDevice) packs there.
bool packVolume(const RefinementBackend& accumulator, PackedVolume& out, const std::atomic<bool>* cancel = nullptr);
// The same pack into host memory whatever the backend (a still's, a test's).
bool packVolumeOnHost(const RefinementBackend& accumulator, PackedVolume& out,
                      const std::atomic<bool>* cancel = nullptr);

// The bytes a packed volume of this grid holds (and the renderer's textures, which mirror it).
std::size_t packedVolumeBytes(const GridGeometry& grid);

// IEEE 754 binary16 bits, through Imath::half: round to nearest even, overflow to infinity.
std::uint16_t floatToHalf(float value);
float halfToFloat(std::uint16_t bits);

}  // namespace voxflame::core
