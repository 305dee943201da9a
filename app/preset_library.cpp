#include "preset_library.h"

#include <algorithm>
#include <chrono>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/file_output.h"
#include "core/image_io.h"
#include "json_guard.h"
#include "pipeline.h"
#include "version.h"

namespace voxflame::app {

namespace {

constexpr std::uintmax_t kMaxPresetBytes = 4 << 20;  // a preset is a few kilobytes
constexpr int kMaxPresetNesting = 64;
// A thumbnail is decoded whole, as floats: this bounds that to a quarter of a gigabyte.
constexpr std::uint64_t kMaxThumbnailPixels = 4096ull * 4096ull;
constexpr std::size_t kMaxStemBytes = 80;

// RGBA8 from display-ready floats in [0, 1].
Thumbnail toThumbnail(const core::ImageRGBA& image) {
  Thumbnail thumbnail;
  thumbnail.width = image.width;
  thumbnail.height = image.height;
  thumbnail.rgba.resize(image.pixels.size());
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    thumbnail.rgba[i] = static_cast<std::uint8_t>(std::lround(std::clamp(image.pixels[i], 0.0f, 1.0f) * 255.0f));
  return thumbnail;
}

std::string lowercase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// Length of the valid UTF-8 sequence starting at text[i] (2–4 bytes), or 0.
std::size_t utf8SequenceLength(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  std::size_t length = 0;
  if (lead >= 0xc2 && lead <= 0xdf)
    length = 2;
  else if (lead >= 0xe0 && lead <= 0xef)
    length = 3;
  else if (lead >= 0xf0 && lead <= 0xf4)
    length = 4;
  else
    return 0;
  if (i + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k)
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
  // Overlong three- and four-byte forms, UTF-16 surrogates and code points past U+10FFFF.
  if (lead == 0xe0 && byte(i + 1) < 0xa0) return 0;
  if (lead == 0xed && byte(i + 1) >= 0xa0) return 0;
  if (lead == 0xf0 && byte(i + 1) < 0x90) return 0;
  if (lead == 0xf4 && byte(i + 1) >= 0x90) return 0;
  return length;
}

PresetEntry readEntry(const std::filesystem::path& path, PresetSource source,
                      const std::filesystem::path& thumbnailPath) {
  PresetEntry entry;
  entry.path = path;
  entry.source = source;
  entry.displayName = path.stem().string();
  entry.thumbnailPath = thumbnailPath;
  std::error_code ec;
  entry.thumbnailState =
      std::filesystem::is_regular_file(thumbnailPath, ec) ? ThumbnailState::Pending : ThumbnailState::Missing;
  try {
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw core::Error("cannot read preset file '" + path.string() + "': " + ec.message());
    if (size > kMaxPresetBytes)
      throw core::Error("preset file '" + path.string() + "' is " + std::to_string(size) +
                        " bytes, too large for a preset");
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw core::Error("cannot read preset file '" + path.string() + "'");
    if (jsonNestingDepth(text.str(), kMaxPresetNesting) > kMaxPresetNesting)
      throw core::Error(path.string() + ": nests deeper than any preset");
    const core::Scene scene = core::sceneFromJson(text.str(), path.string());
    entry.displayName = scene.name;
    entry.attractor = scene.layers.empty() ? std::string() : scene.layers.front().patternName();
    entry.loads = true;
  } catch (const std::exception& e) {
    entry.loads = false;
    entry.error = e.what();
  }
  return entry;
}

std::vector<PresetEntry> scanFolder(const std::filesystem::path& folder, PresetSource source) {
  std::vector<PresetEntry> entries;
  if (folder.empty()) return entries;
  std::error_code ec;
  for (const auto& item : std::filesystem::directory_iterator(folder, ec)) {
    const std::filesystem::path& path = item.path();
    const std::string name = path.filename().string();
    if (name.empty() || name[0] == '.' || path.extension() != ".json" || !item.is_regular_file(ec)) continue;
    const std::filesystem::path thumbnail = source == PresetSource::Shipped
                                                ? folder / "gallery" / (path.stem().string() + ".png")
                                                : folder / (path.stem().string() + ".png");
    entries.push_back(readEntry(path, source, thumbnail));
  }
  std::sort(entries.begin(), entries.end(), [](const PresetEntry& a, const PresetEntry& b) {
    const std::string left = lowercase(a.displayName), right = lowercase(b.displayName);
    return left != right ? left < right : a.path < b.path;
  });
  return entries;
}

}  // namespace

std::vector<std::filesystem::path> shippedPresetFolderCandidates(const std::filesystem::path& executable) {
  std::vector<std::filesystem::path> candidates;
  std::error_code ec;
  const std::filesystem::path exe =
      executable.empty() ? std::filesystem::read_symlink("/proc/self/exe", ec) : executable;
  if (!exe.empty() && !ec) {
    const std::filesystem::path folder = exe.parent_path();
    candidates.push_back((folder / ".." / "share" / "voxflame" / "presets").lexically_normal());
    candidates.push_back(folder / "presets");
  }
#ifdef VOXFLAME_SOURCE_PRESETS
  candidates.push_back(VOXFLAME_SOURCE_PRESETS);
#endif
  return candidates;
}

std::filesystem::path findShippedPresetFolder(const std::filesystem::path& executable) {
  for (const auto& candidate : shippedPresetFolderCandidates(executable)) {
    std::error_code ec;
    if (std::filesystem::is_directory(candidate, ec)) return candidate;
  }
  return {};
}

std::vector<PresetEntry> listPresets(const std::filesystem::path& shippedFolder,
                                     const std::filesystem::path& userFolder) {
  std::vector<PresetEntry> entries = scanFolder(shippedFolder, PresetSource::Shipped);
  std::error_code ec;
  // The same folder configured as both is listed once, as shipped.
  if (!userFolder.empty() &&
      !(std::filesystem::exists(shippedFolder, ec) && std::filesystem::equivalent(shippedFolder, userFolder, ec))) {
    std::vector<PresetEntry> user = scanFolder(userFolder, PresetSource::User);
    entries.insert(entries.end(), std::make_move_iterator(user.begin()), std::make_move_iterator(user.end()));
  }
  return entries;
}

Thumbnail decodeThumbnail(const std::filesystem::path& path, int maxWidth) {
  return toThumbnail(core::downscaleToWidth(core::readPng(path, kMaxThumbnailPixels).image, std::max(1, maxWidth)));
}

std::string sanitizePresetName(std::string_view displayName) {
  std::string stem;
  bool pendingDash = false;
  const auto append = [&](std::string_view piece) {
    if (pendingDash && !stem.empty()) stem += '-';
    pendingDash = false;
    if (stem.size() + piece.size() <= kMaxStemBytes) stem += piece;
  };
  for (std::size_t i = 0; i < displayName.size() && stem.size() < kMaxStemBytes;) {
    const auto c = static_cast<unsigned char>(displayName[i]);
    if (std::isalnum(c) || c == '_') {
      append(displayName.substr(i, 1));
      ++i;
    } else if (c >= 0x80) {
      const std::size_t length = utf8SequenceLength(displayName, i);
      if (length == 0) {
        ++i;  // not UTF-8: dropped
        continue;
      }
      const std::size_t before = stem.size();
      append(displayName.substr(i, length));
      if (stem.size() == before) break;  // would not fit whole
      i += length;
    } else {
      // Spaces, '-', punctuation, separators and control characters all become one dash, and
      // only between kept characters: no leading dot or dash, no "..", no path.
      pendingDash = true;
      ++i;
    }
  }
  return stem.empty() ? "preset" : stem;
}

std::filesystem::path savePresetAs(const core::Scene& scene, const std::string& displayName, const Thumbnail& thumbnail,
                                   const std::filesystem::path& userFolder, bool overwrite) {
  if (userFolder.empty()) throw core::Error("no folder for user presets: neither $XDG_DATA_HOME nor $HOME is set");
  std::error_code ec;
  std::filesystem::create_directories(userFolder, ec);
  if (ec) throw core::Error("cannot create the preset folder '" + userFolder.string() + "': " + ec.message());
  const std::string stem = sanitizePresetName(displayName);
  const std::filesystem::path path = userFolder / (stem + ".json");
  const std::filesystem::path thumbnailPath = userFolder / (stem + ".png");
  if (!overwrite && std::filesystem::exists(path, ec))
    throw core::Error("a preset '" + path.filename().string() + "' already exists in '" + userFolder.string() +
                      "'; choose another name or replace it");
  if (thumbnail.width < 0 || thumbnail.height < 0 ||
      thumbnail.rgba.size() !=
          4 * static_cast<std::size_t>(thumbnail.width) * static_cast<std::size_t>(thumbnail.height))
    throw core::Error("the thumbnail for preset '" + displayName + "' has the wrong number of pixels");

  core::Scene stored = scene;
  stored.name = displayName.empty() ? stem : displayName;
  if (!stored.embedded)
    stored.meshPath = std::filesystem::absolute(scene.resolvedMeshPath()).lexically_normal().string();
  const std::string json = core::sceneToJson(stored);
  // The thumbnail first: a preset that appears has its picture, or a stale one is replaced.
  if (thumbnail.width > 0 && thumbnail.height > 0) {
    core::ImageRGBA image;
    image.width = thumbnail.width;
    image.height = thumbnail.height;
    image.pixels.resize(thumbnail.rgba.size());
    for (std::size_t i = 0; i < thumbnail.rgba.size(); ++i)
      image.pixels[i] = static_cast<float>(thumbnail.rgba[i]) / 255.0f;
    core::writePng(thumbnailPath, core::downscaleToWidth(image, kSavedThumbnailWidth), 8,
                   {{kPresetChunkKey, json}, {"Software", std::string("voxflame ") + kVersion}});
  } else if (overwrite) {
    std::filesystem::remove(thumbnailPath, ec);  // it would show the replaced preset
  }
  core::writeFileAtomically(path, json, {.what = "cannot write preset"});
  return path;
}

PresetLibrary::PresetLibrary(std::filesystem::path shippedFolder, std::filesystem::path userFolder)
    : shippedFolder_(std::move(shippedFolder)),
      userFolder_(std::move(userFolder)),
      entries_(std::make_shared<const std::vector<PresetEntry>>()) {
  worker_ = std::jthread([this](std::stop_token stop) { run(stop); });
}

PresetLibrary::~PresetLibrary() {
  worker_.request_stop();
  worker_.join();
}

void PresetLibrary::refresh() {
  {
    const std::lock_guard lock(mutex_);
    refreshRequested_ = true;
    busy_ = true;
  }
  wake_.notify_one();
}

bool PresetLibrary::waitUntilIdle(double timeoutSeconds) const {
  std::unique_lock lock(mutex_);
  return idle_.wait_for(lock, std::chrono::duration<double>(timeoutSeconds), [this] { return !busy_.load(); });
}

PresetLibrary::Entries PresetLibrary::entries() const {
  const std::lock_guard lock(mutex_);
  return entries_;
}

std::filesystem::path PresetLibrary::saveAs(const core::Scene& scene, const std::string& displayName,
                                            const Thumbnail& thumbnail, bool overwrite) {
  const std::filesystem::path path = savePresetAs(scene, displayName, thumbnail, userFolder_, overwrite);
  refresh();
  return path;
}

void PresetLibrary::publish(const std::vector<PresetEntry>& entries) {
  auto copy = std::make_shared<const std::vector<PresetEntry>>(entries);
  const std::lock_guard lock(mutex_);
  entries_ = std::move(copy);
  ++version_;
}

void PresetLibrary::run(std::stop_token stop) {
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      if (!refreshRequested_) {
        busy_ = false;
        idle_.notify_all();
      }
      wake_.wait(lock, stop, [this] { return refreshRequested_; });
      if (stop.stop_requested()) return;
      refreshRequested_ = false;
    }
    std::vector<PresetEntry> entries = listPresets(shippedFolder_, userFolder_);
    for (auto& entry : entries) {
      if (entry.thumbnailState != ThumbnailState::Pending) continue;
      std::error_code ec;
      const auto time = std::filesystem::last_write_time(entry.thumbnailPath, ec);
      const auto cached = thumbnailCache_.find(entry.thumbnailPath);
      if (!ec && cached != thumbnailCache_.end() && cached->second.first == time) {
        entry.thumbnail = cached->second.second;
        entry.thumbnailState = ThumbnailState::Ready;
      }
    }
    publish(entries);
    for (auto& entry : entries) {
      if (stop.stop_requested()) return;
      {
        const std::lock_guard lock(mutex_);
        if (refreshRequested_) break;  // rescan first; what was decoded stays cached
      }
      if (entry.thumbnailState != ThumbnailState::Pending) continue;
      std::error_code ec;
      const auto time = std::filesystem::last_write_time(entry.thumbnailPath, ec);
      try {
        auto thumbnail = std::make_shared<const Thumbnail>(decodeThumbnail(entry.thumbnailPath));
        thumbnailCache_[entry.thumbnailPath] = {time, thumbnail};
        entry.thumbnail = std::move(thumbnail);
        entry.thumbnailState = ThumbnailState::Ready;
      } catch (const std::exception& e) {
        entry.thumbnailState = ThumbnailState::Failed;
        entry.thumbnailError = e.what();
      }
      publish(entries);
    }
  }
}

}  // namespace voxflame::app
