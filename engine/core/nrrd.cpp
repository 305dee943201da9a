#include "nrrd.h"
#include "file_output.h"

#include <cstdio>
#include <memory>
#include <sstream>

#include "error.h"

namespace voxflame::core {

std::string nrrdMaskHeader(const InsideMask& mask) {
  const GridGeometry& g = mask.geometry;
  const glm::dvec3 firstCentre = g.voxelCenter(0, 0, 0);
  std::ostringstream header;
  header.precision(17);
  header << "NRRD0004\n"
         << "# voxflame inside mask: 1 inside the mesh, 0 outside\n"
         << "type: uchar\n"
         << "dimension: 3\n"
         << "space: 3D-right-handed\n"
         << "sizes: " << g.size.x << " " << g.size.y << " " << g.size.z << "\n"
         << "space directions: (" << g.voxelSize << ",0,0) (0," << g.voxelSize << ",0) (0,0," << g.voxelSize << ")\n"
         << "kinds: domain domain domain\n"
         << "encoding: raw\n"
         << "space origin: (" << firstCentre.x << "," << firstCentre.y << "," << firstCentre.z << ")\n"
         << "\n";
  return header.str();
}

void writeNrrdMask(const std::filesystem::path& path, const InsideMask& mask) {
  if (mask.inside.size() != mask.geometry.voxelCount())
    throw Error("cannot write '" + path.string() + "': the mask does not match its grid");
  const std::string header = nrrdMaskHeader(mask);
  writeFileAtomicallyWith(path, [&](const std::filesystem::path& temporary) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(temporary.c_str(), "wb"), &std::fclose);
    if (!file) throw Error("cannot write '" + path.string() + "': the folder is missing or not writable");
    bool ok = std::fwrite(header.data(), 1, header.size(), file.get()) == header.size() &&
              std::fwrite(mask.inside.data(), 1, mask.inside.size(), file.get()) == mask.inside.size();
    ok = std::fclose(file.release()) == 0 && ok;
    if (!ok) throw Error("cannot write '" + path.string() + "': disk full?");
  });
}

}  // namespace voxflame::core
