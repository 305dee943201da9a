// The preset library behind the explorer's preset browser: the presets shipped with voxflame and
// the user's own (Settings::presetFolder()), each with its name, first pattern (attractor or chaos game), whether it
// loads, and a thumbnail decoded off the UI thread into RGBA8 pixels ready for a texture upload.
//
// Where the shipped presets are found, first existing folder wins:
//   1. <executable's folder>/../share/voxflame/presets   (an installed voxflame)
//   2. <executable's folder>/presets                     (a self-contained bundle)
//   3. the source tree's presets/ this binary was built from (a developer build)
// Thumbnails: presets/gallery/<stem>.png for a shipped preset, <stem>.png beside a user preset.
//
// A preset that does not load is listed with its error, never hidden. Only *.json files directly
// in each folder are listed (not hidden ones, not subfolders such as gallery/ and meshes/).
// No GL here: the UI uploads Thumbnail::rgba itself.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "core/scene.h"

namespace voxflame::app {

inline constexpr int kThumbnailWidth = 160;       // decoded thumbnails are at most this wide
inline constexpr int kSavedThumbnailWidth = 320;  // saveAs stores thumbnails at most this wide

// RGBA, 8 bits per channel, rows top to bottom, no padding: glTexImage2D(..., GL_RGBA,
// GL_UNSIGNED_BYTE, rgba.data()) with GL_UNPACK_ALIGNMENT 1.
struct Thumbnail {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
};

enum class PresetSource { Shipped, User };
enum class ThumbnailState { Missing, Pending, Ready, Failed };

struct PresetEntry {
  std::filesystem::path path;
  PresetSource source = PresetSource::Shipped;
  std::string displayName;  // the preset's "name"; the file's stem when it does not load
  std::string attractor;    // layer 0's pattern (attractor id, "flame", ...); empty when it does not load
  bool loads = false;
  std::string error;                    // why it does not load (names the file and the key)
  std::filesystem::path thumbnailPath;  // where its thumbnail is looked for
  ThumbnailState thumbnailState = ThumbnailState::Missing;
  std::shared_ptr<const Thumbnail> thumbnail;  // when Ready
  std::string thumbnailError;                  // when Failed
};

// The folders looked at for shipped presets, in order (see above). `executable` empty: this
// process's own (/proc/self/exe).
std::vector<std::filesystem::path> shippedPresetFolderCandidates(const std::filesystem::path& executable = {});
// The first candidate that exists; empty when none does.
std::filesystem::path findShippedPresetFolder(const std::filesystem::path& executable = {});

// Scans both folders (either may be empty or missing) and reads every preset; thumbnails are not
// decoded (state Pending when the file exists, else Missing). Shipped first, then the user's,
// each sorted by display name. Never throws. Synchronous: PresetLibrary calls it off the UI thread.
std::vector<PresetEntry> listPresets(const std::filesystem::path& shippedFolder,
                                     const std::filesystem::path& userFolder);

// Decodes a PNG (any kind core::readPng reads, up to 4096×4096 pixels in all) into RGBA8,
// area-averaged down to at most `maxWidth` wide (never enlarged; core::downscaleToWidth),
// keeping the aspect ratio. Throws core::Error naming the file.
Thumbnail decodeThumbnail(const std::filesystem::path& png, int maxWidth = kThumbnailWidth);

// A file name stem for a display name: letters, digits (UTF-8 letters included), '-' and '_'
// kept; spaces and anything else become single '-'; no leading dots or dashes; at most 80 bytes;
// "preset" when nothing is left. Never a path: no '/', '\', ':' or "..".
std::string sanitizePresetName(std::string_view displayName);

// Writes <userFolder>/<sanitized name>.json (name set to displayName; a relative mesh path made
// absolute so the preset finds its mesh from the user's folder) and, when the thumbnail is not
// empty, <stem>.png (at most kSavedThumbnailWidth wide) carrying the preset like a render does.
// Refuses (core::Error) to replace an existing preset unless `overwrite`. Returns the .json path.
std::filesystem::path savePresetAs(const core::Scene& scene, const std::string& displayName, const Thumbnail& thumbnail,
                                   const std::filesystem::path& userFolder, bool overwrite = false);

// The library as the UI uses it: a worker thread scans and decodes; every call returns at once.
class PresetLibrary {
 public:
  using Entries = std::shared_ptr<const std::vector<PresetEntry>>;

  // Starts the first scan.
  PresetLibrary(std::filesystem::path shippedFolder, std::filesystem::path userFolder);
  ~PresetLibrary();  // stops the worker (after the thumbnail it is decoding)
  PresetLibrary(const PresetLibrary&) = delete;
  PresetLibrary& operator=(const PresetLibrary&) = delete;

  // Scans again (after a save, or when the user asks); returns at once.
  void refresh();
  // The current list; it grows thumbnails as they are decoded. version() rises with every change,
  // so the UI re-uploads textures only then.
  Entries entries() const;
  std::uint64_t version() const { return version_.load(); }
  bool busy() const { return busy_.load(); }
  // Blocks until a scan and its thumbnails are done (!busy(), true) or `timeoutSeconds` pass
  // (false). For tests and scripted runs: the UI only asks busy().
  bool waitUntilIdle(double timeoutSeconds) const;

  // savePresetAs into the user folder, then refresh(). Throws core::Error for the window.
  std::filesystem::path saveAs(const core::Scene& scene, const std::string& displayName, const Thumbnail& thumbnail,
                               bool overwrite = false);

  const std::filesystem::path& shippedFolder() const { return shippedFolder_; }
  const std::filesystem::path& userFolder() const { return userFolder_; }

 private:
  void run(std::stop_token stop);
  void publish(const std::vector<PresetEntry>& entries);

  const std::filesystem::path shippedFolder_;
  const std::filesystem::path userFolder_;
  mutable std::mutex mutex_;
  std::condition_variable_any wake_;
  mutable std::condition_variable idle_;  // notified when busy_ turns false
  bool refreshRequested_ = true;
  Entries entries_;
  std::atomic<std::uint64_t> version_{0};
  std::atomic<bool> busy_{true};
  // Worker only: decoded thumbnails by file, kept while the file's time stamp is unchanged.
  std::map<std::filesystem::path, std::pair<std::filesystem::file_time_type, std::shared_ptr<const Thumbnail>>>
      thumbnailCache_;
  std::jthread worker_;  // last: started after everything it uses, stopped first
};

}  // namespace voxflame::app
