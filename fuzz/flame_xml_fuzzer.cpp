// libFuzzer target of the flame importer: any bytes given to core::readFlameXml either import or
// are refused with a core::Error; anything else (a crash, another exception, undefined behaviour,
// a hang, a huge allocation) is a bug. A flame that imports must also make a scene that saves as
// a preset and loads back unchanged, as the explorer's import does.
//
// The input's last byte also picks the import options, so the fuzzer explores them with the same
// mutations that change the XML; the byte stays in the text. Real files end in a newline or the
// root's closing '>': those bytes mean the default options, so every seed imports as the user's
// file would.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/error.h"
#include "core/flame/xml.h"
#include "core/scene.h"
#include "core/scene_io.h"

namespace {

using namespace voxflame::core;

[[noreturn]] void bug(const std::string& what) {
  std::fprintf(stderr, "flame_xml_fuzzer: %s\n", what.c_str());
  std::abort();
}

FlameImportOptions optionsFrom(std::uint8_t control) {
  static constexpr std::array<double, 4> kDepths = {kDefaultFlameDepth, 0.0, kMaxFlameDepth, 1.0};
  FlameImportOptions options;
  options.index = control & 3u;
  options.depth = kDepths[(control >> 2) & 3u];
  // The fallback palette when flam3's table cannot be read.
  if (control & 0x10u) options.paletteTable = "/nonexistent/flam3-palettes.xml";
  // Picking by name instead of by index.
  if (control & 0x20u) options.name = (control & 0x40u) ? "flame 2" : "fuzz";
  return options;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const Scene base = defaultScene();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::uint8_t last = data[size - 1];
  const bool plainEnd = last == '\n' || last == '\r' || last == ' ' || last == '\t' || last == '>';
  const FlameImportOptions options = optionsFrom(plainEnd ? 0 : last);
  FlameFileContents contents;
  try {
    contents = readFlameXml(text, "fuzz.flame", options);
  } catch (const Error&) {
    return 0;  // refused with a message for the user: fine
  }
  if (contents.index >= contents.names.size()) bug("the imported flame's index is not among the names");
  if (contents.flame.palette.size() != kFlamePaletteSize) bug("the palette does not have 256 colours");
  const Scene scene = sceneFromImportedFlame(contents.flame, base);
  std::string saved;
  try {
    saved = sceneToJson(scene);
    const Scene back = sceneFromJson(saved, "imported.json");
    if (sceneToJson(back) != saved) bug("the imported flame's preset does not load back as saved:\n" + saved);
  } catch (const Error& e) {
    bug(std::string("an imported flame makes a preset that does not load: ") + e.what() + "\n" + saved);
  }
  return 0;
}
