#include "volume_export.h"
#include "file_output.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "error.h"

namespace voxflame::core {

std::vector<float> normalisedDensity(const VolumeSnapshot& snapshot) {
  double sum = 0.0;
  std::size_t occupied = 0;
  for (float hits : snapshot.density)
    if (hits > 0.0f) {
      sum += hits;
      ++occupied;
    }
  std::vector<float> density(snapshot.density.size(), 0.0f);
  if (occupied == 0 || snapshot.maxDensity <= 0.0f) return density;
  const double mean = sum / static_cast<double>(occupied);
  const double normaliser = 1.0 / std::log1p(snapshot.maxDensity / mean);
  for (std::size_t v = 0; v < density.size(); ++v)
    if (snapshot.density[v] > 0.0f)
      density[v] = static_cast<float>(std::log1p(snapshot.density[v] / mean) * normaliser);
  return density;
}

std::string nrrdVolumeHeader(const VolumeSnapshot& snapshot, const std::string& presetJson) {
  const GridGeometry& g = snapshot.geometry;
  const glm::dvec3 firstCentre = g.voxelCenter(0, 0, 0);
  // A key/value line ends at the newline: the preset goes in as compact JSON with newlines escaped.
  std::string preset = nlohmann::json::parse(presetJson).dump();
  std::ostringstream header;
  header.precision(17);
  header << "NRRD0004\n"
         << "# voxflame volume: per voxel normalised density (log scale, 1 in the densest voxel) and mean linear "
            "RGB colour\n"
         << "type: float\n"
         << "dimension: 4\n"
         << "space: 3D-right-handed\n"
         << "sizes: 4 " << g.size.x << " " << g.size.y << " " << g.size.z << "\n"
         << "space directions: none (" << g.voxelSize << ",0,0) (0," << g.voxelSize << ",0) (0,0," << g.voxelSize
         << ")\n"
         << "kinds: 4-vector domain domain domain\n"
         << "labels: \"density;red;green;blue\" \"x\" \"y\" \"z\"\n"
         << "endian: little\n"
         << "encoding: raw\n"
         << "space origin: (" << firstCentre.x << "," << firstCentre.y << "," << firstCentre.z << ")\n"
         << "voxflame_preset:=" << preset << "\n"
         << "\n";
  return header.str();
}

void writeNrrdVolume(const std::filesystem::path& path, const VolumeSnapshot& snapshot, const std::string& presetJson) {
  const std::size_t voxels = snapshot.geometry.voxelCount();
  if (snapshot.density.size() != voxels || snapshot.rgba.size() != 4 * voxels)
    throw Error("cannot write '" + path.string() + "': the volume does not match its grid");
  const std::string header = nrrdVolumeHeader(snapshot, presetJson);
  const std::vector<float> density = normalisedDensity(snapshot);
  writeFileAtomicallyWith(path, [&](const std::filesystem::path& temporary) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(temporary.c_str(), "wb"), &std::fclose);
    if (!file) throw Error("cannot write '" + path.string() + "': the folder is missing or not writable");
    bool ok = std::fwrite(header.data(), 1, header.size(), file.get()) == header.size();
    // Written a z-slab at a time: four floats a voxel would double the memory of a large grid.
    const std::size_t slab = static_cast<std::size_t>(snapshot.geometry.size.x) * snapshot.geometry.size.y;
    std::vector<float> samples(4 * slab);
    for (std::size_t begin = 0; ok && begin < voxels; begin += slab) {
      const std::size_t count = std::min(slab, voxels - begin);
      for (std::size_t i = 0; i < count; ++i) {
        const std::size_t v = begin + i;
        samples[4 * i] = density[v];
        for (int c = 0; c < 3; ++c) samples[4 * i + 1 + c] = snapshot.rgba[4 * v + c] / 255.0f;
      }
      ok = std::fwrite(samples.data(), sizeof(float), 4 * count, file.get()) == 4 * count;
    }
    ok = std::fclose(file.release()) == 0 && ok;
    if (!ok) throw Error("cannot write '" + path.string() + "': disk full?");
  });
}

}  // namespace voxflame::core
