// The one translation unit that includes OpenVDB: its headers are heavy, so nothing else does.
#include <openvdb/openvdb.h>

#include <filesystem>

#include "error.h"
#include "file_output.h"
#include "volume_export.h"

namespace voxflame::core {

void writeVdbVolume(const std::filesystem::path& path, const VolumeSnapshot& snapshot, const std::string& presetJson) {
  const GridGeometry& g = snapshot.geometry;
  const std::size_t voxels = g.voxelCount();
  if (snapshot.density.size() != voxels || snapshot.rgba.size() != 4 * voxels)
    throw Error("cannot write '" + path.string() + "': the volume does not match its grid");
  openvdb::initialize();
  const std::vector<float> density = normalisedDensity(snapshot);

  // Index (i, j, k) sits at the centre of voxel (i, j, k): scale by the voxel edge, then move to
  // the centre of voxel (0, 0, 0).
  const auto transform = openvdb::math::Transform::createLinearTransform(g.voxelSize);
  const glm::dvec3 firstCentre = g.voxelCenter(0, 0, 0);
  transform->postTranslate(openvdb::Vec3d(firstCentre.x, firstCentre.y, firstCentre.z));

  const auto densityGrid = openvdb::FloatGrid::create(0.0f);
  densityGrid->setName("density");
  densityGrid->setGridClass(openvdb::GRID_FOG_VOLUME);
  densityGrid->setTransform(transform);
  const auto colorGrid = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
  colorGrid->setName("color");
  colorGrid->setVectorType(openvdb::VEC_INVARIANT);
  colorGrid->setTransform(transform->copy());

  // Sparse: only voxels that received points become active; the tree stores nothing for the rest.
  auto densityAccessor = densityGrid->getAccessor();
  auto colorAccessor = colorGrid->getAccessor();
  for (int k = 0; k < g.size.z; ++k)
    for (int j = 0; j < g.size.y; ++j)
      for (int i = 0; i < g.size.x; ++i) {
        const std::size_t v = g.index(i, j, k);
        if (snapshot.density[v] <= 0.0f) continue;
        const openvdb::Coord xyz(i, j, k);
        densityAccessor.setValue(xyz, density[v]);
        const std::uint8_t* rgba = &snapshot.rgba[4 * v];
        colorAccessor.setValue(xyz, openvdb::Vec3s(rgba[0] / 255.0f, rgba[1] / 255.0f, rgba[2] / 255.0f));
      }

  for (const openvdb::GridBase::Ptr& grid : {openvdb::GridBase::Ptr(densityGrid), openvdb::GridBase::Ptr(colorGrid)})
    grid->insertMeta("voxflame_preset", openvdb::StringMetadata(presetJson));
  openvdb::MetaMap fileMeta;
  fileMeta.insertMeta("voxflame_preset", openvdb::StringMetadata(presetJson));
  fileMeta.insertMeta("creator", openvdb::StringMetadata("voxflame"));

  writeFileAtomicallyWith(path, [&](const std::filesystem::path& temporary) {
    openvdb::io::File file(temporary.string());
    file.write({densityGrid, colorGrid}, fileMeta);
    file.close();
  });
}

}  // namespace voxflame::core
