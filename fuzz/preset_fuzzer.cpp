// libFuzzer target of the preset reader: any text given to core::sceneFromJson either loads or is
// refused with a core::Error; anything else (a crash, another exception, undefined behaviour, a
// hang, a huge allocation) is a bug. A preset that loads must also save and load back to the same
// preset, as the explorer's save does, and its animation must evaluate (or refuse a time with a
// core::Error) as `voxflame animate` and the explorer's timeline evaluate it.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/error.h"
#include "core/keyframes.h"
#include "core/scene.h"
#include "core/scene_io.h"

namespace {

using namespace voxflame::core;

[[noreturn]] void bug(const std::string& what) {
  std::fprintf(stderr, "preset_fuzzer: %s\n", what.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  Scene scene;
  try {
    scene = sceneFromJson(text, "fuzz.json");
  } catch (const Error&) {
    return 0;  // refused with a message for the user: fine
  }
  std::string saved;
  try {
    saved = sceneToJson(scene);
    const Scene back = sceneFromJson(saved, "saved.json");
    if (sceneToJson(back) != saved) bug("a loaded preset does not load back as saved:\n" + saved);
  } catch (const Error& e) {
    bug(std::string("a loaded preset saves as one that does not load: ") + e.what() + "\n" + saved);
  }
  if (!scene.keyframes.empty()) {
    const double duration = animationDuration(scene);
    if (animationFrameCount(scene, animationFps(scene)) < 1) bug("an animation without frames");
    for (const double seconds : {0.0, duration * 0.37, duration, -1.0}) {
      try {
        (void)sceneAtTime(scene, seconds);
      } catch (const Error&) {
        // An interpolated value out of its range at that time: refused with a message.
      }
    }
  }
  return 0;
}
