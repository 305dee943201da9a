#include "settings.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/file_output.h"
#include "core/xdg_paths.h"
#include "json_guard.h"

namespace voxflame::app {

using nlohmann::json;

namespace {

constexpr int kSettingsVersion = 1;
// A settings file is a few hundred bytes; anything far larger is not ours.
constexpr std::uintmax_t kMaxSettingsBytes = 1 << 20;
// Our file nests three deep; a deeper one is not ours either, and nesting costs stack elsewhere.
constexpr int kMaxNesting = 16;

const char* toString(RecentKind kind) {
  return kind == RecentKind::Mesh ? "mesh" : "preset";
}

std::filesystem::path normalised(const std::filesystem::path& path) {
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
  return (ec ? path : absolute).lexically_normal();
}

// Reads keys leniently: a value of the wrong type or out of range keeps the default and is
// noted, so one bad key costs that key only.
class Reader {
 public:
  Reader(std::vector<std::string>& problems) : problems_(problems) {}

  const json* find(const json& object, const char* key) const {
    if (!object.is_object()) return nullptr;
    const auto it = object.find(key);
    return it == object.end() || it->is_null() ? nullptr : &*it;
  }

  template <typename Int>
  void integer(const json& object, const char* key, const std::string& path, Int& value, long long min, long long max) {
    const json* found = find(object, key);
    if (!found) return;
    if (found->is_number_integer()) {
      const long long v =
          found->is_number_unsigned() && found->get<std::uint64_t>() > (1ULL << 62) ? max + 1 : found->get<long long>();
      if (v >= min && v <= max) {
        value = static_cast<Int>(v);
        return;
      }
    }
    problems_.push_back("'" + path + "' must be a whole number from " + std::to_string(min) + " to " +
                        std::to_string(max));
  }

  void number(const json& object, const char* key, const std::string& path, double& value, double min, double max) {
    const json* found = find(object, key);
    if (!found) return;
    if (found->is_number() && found->get<double>() >= min && found->get<double>() <= max) {
      value = found->get<double>();
      return;
    }
    problems_.push_back("'" + path + "' must be a number from " + std::to_string(min) + " to " + std::to_string(max));
  }

  void boolean(const json& object, const char* key, const std::string& path, bool& value) {
    const json* found = find(object, key);
    if (!found) return;
    if (found->is_boolean())
      value = found->get<bool>();
    else
      problems_.push_back("'" + path + "' must be true or false");
  }

  bool string(const json& object, const char* key, const std::string& path, std::string& value) {
    const json* found = find(object, key);
    if (!found) return false;
    if (found->is_string() && found->get_ref<const std::string&>().size() <= 4096) {
      value = found->get<std::string>();
      return true;
    }
    problems_.push_back("'" + path + "' must be a string (at most 4096 bytes)");
    return false;
  }

  void path(const json& object, const char* key, const std::string& where, std::filesystem::path& value) {
    std::string text;
    if (string(object, key, where, text)) value = text;
  }

  void note(std::string problem) { problems_.push_back(std::move(problem)); }

 private:
  std::vector<std::string>& problems_;
};

Settings settingsFromJson(const json& root, std::vector<std::string>& problems) {
  Settings settings;
  Reader reader(problems);
  if (const json* window = reader.find(root, "window")) {
    WindowGeometry& w = settings.window;
    reader.integer(*window, "width", "window.width", w.width, 200, 32768);
    reader.integer(*window, "height", "window.height", w.height, 200, 32768);
    int x = 0, y = 0;
    const bool hasX = reader.find(*window, "x") != nullptr, hasY = reader.find(*window, "y") != nullptr;
    const std::size_t before = problems.size();
    reader.integer(*window, "x", "window.x", x, -65536, 65536);
    reader.integer(*window, "y", "window.y", y, -65536, 65536);
    if (hasX && hasY && problems.size() == before) {
      w.x = x;
      w.y = y;
    }
    reader.boolean(*window, "maximized", "window.maximized", w.maximized);
  }
  reader.path(root, "last_preset", "last_preset", settings.lastPreset);
  reader.number(root, "refine_until_noise_percent", "refine_until_noise_percent", settings.refineUntilNoisePercent, 0.0,
                100.0);
  if (std::string backend; reader.string(root, "refinement_backend", "refinement_backend", backend)) {
    try {
      settings.refinementBackend = backendChoiceFromString(backend);
    } catch (const core::Error& error) {
      reader.note("'refinement_backend': " + std::string(error.what()));
    }
  }
  reader.path(root, "user_preset_folder", "user_preset_folder", settings.userPresetFolder);
  if (const json* recent = reader.find(root, "recent")) {
    if (!recent->is_array()) {
      reader.note("'recent' must be a list");
    } else {
      // Oldest first, so that addRecent leaves the newest in front.
      for (std::size_t i = std::min<std::size_t>(recent->size(), 4 * kMaxRecentFiles); i-- > 0;) {
        const json& entry = (*recent)[i];
        std::string path, kind = "preset";
        const std::string where = "recent[" + std::to_string(i) + "]";
        if (!entry.is_object() || !reader.string(entry, "path", where + ".path", path)) {
          if (!entry.is_object()) reader.note("'" + where + "' must be an object with \"path\" and \"kind\"");
          continue;
        }
        reader.string(entry, "kind", where + ".kind", kind);
        if (kind != "preset" && kind != "mesh") {
          reader.note("'" + where + ".kind' must be \"preset\" or \"mesh\"");
          continue;
        }
        std::error_code ec;
        if (path.empty() || !std::filesystem::exists(path, ec)) continue;  // moved or deleted since
        settings.addRecent(kind == "mesh" ? RecentKind::Mesh : RecentKind::Preset, path);
      }
    }
  }
  if (const json* exported = reader.find(root, "last_export")) {
    ExportSettings& e = settings.lastExport;
    reader.integer(*exported, "width", "last_export.width", e.width, 1, 65536);
    reader.integer(*exported, "height", "last_export.height", e.height, 1, 65536);
    reader.integer(*exported, "samples", "last_export.samples", e.samples, 1, 1024);
    reader.integer(*exported, "points", "last_export.points", e.points, 0, 1LL << 40);
    reader.integer(*exported, "threads", "last_export.threads", e.threads, 0, 1024);
    std::string format;
    if (reader.string(*exported, "format", "last_export.format", format) && !exportFormatFromString(format, e.format))
      reader.note("'last_export.format' must be \"png8\", \"png16\" or \"exr\"");
    reader.path(*exported, "folder", "last_export.folder", settings.lastExportFolder);
  }
  return settings;
}

json settingsToJson(const Settings& settings) {
  json root;
  root["version"] = kSettingsVersion;
  json window = {
      {"width", settings.window.width}, {"height", settings.window.height}, {"maximized", settings.window.maximized}};
  if (settings.window.x && settings.window.y) {
    window["x"] = *settings.window.x;
    window["y"] = *settings.window.y;
  }
  root["window"] = window;
  root["last_preset"] = settings.lastPreset.string();
  root["user_preset_folder"] = settings.userPresetFolder.string();
  root["refine_until_noise_percent"] = settings.refineUntilNoisePercent;
  root["refinement_backend"] = std::string(toString(settings.refinementBackend));
  json recent = json::array();
  for (const auto& file : settings.recent)
    recent.push_back({{"path", file.path.string()}, {"kind", toString(file.kind)}});
  root["recent"] = recent;
  const ExportSettings& e = settings.lastExport;
  root["last_export"] = {{"width", e.width},
                         {"height", e.height},
                         {"samples", e.samples},
                         {"points", e.points},
                         {"format", toString(e.format)},
                         {"threads", e.threads},
                         {"folder", settings.lastExportFolder.string()}};
  return root;
}

// Keeps the user's file as <file>.bad before it can be overwritten; says what happened.
std::string keepAside(const std::filesystem::path& file) {
  std::error_code ec;
  const std::filesystem::path bad = file.string() + ".bad";
  std::filesystem::copy_file(file, bad, std::filesystem::copy_options::overwrite_existing, ec);
  return ec ? " (it could not be kept aside: " + ec.message() + ")" : "; the file was kept as '" + bad.string() + "'";
}

}  // namespace

void Settings::addRecent(RecentKind kind, const std::filesystem::path& path) {
  const std::filesystem::path absolute = normalised(path);
  std::erase_if(recent, [&](const RecentFile& file) { return file.kind == kind && file.path == absolute; });
  recent.insert(recent.begin(), RecentFile{absolute, kind});
  std::size_t ofKind = 0;
  std::erase_if(recent, [&](const RecentFile& file) { return file.kind == kind && ++ofKind > kMaxRecentFiles; });
}

std::vector<std::filesystem::path> Settings::recentOf(RecentKind kind) const {
  std::vector<std::filesystem::path> paths;
  for (const auto& file : recent)
    if (file.kind == kind) paths.push_back(file.path);
  return paths;
}

std::filesystem::path Settings::presetFolder() const {
  return userPresetFolder.empty() ? defaultUserPresetFolder() : userPresetFolder;
}

std::filesystem::path defaultSettingsPath() {
  const std::filesystem::path folder = core::xdgFolder(core::XdgKind::Config);
  return folder.empty() ? folder : folder / "settings.json";
}

std::filesystem::path defaultUserPresetFolder() {
  const std::filesystem::path folder = core::xdgFolder(core::XdgKind::Data);
  return folder.empty() ? folder : folder / "presets";
}

SettingsLoad loadSettings(const std::filesystem::path& file) {
  SettingsLoad result;
  if (file.empty()) return result;
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return result;
  const std::string name = "settings '" + file.string() + "'";
  try {
    const std::uintmax_t size = std::filesystem::file_size(file, ec);
    if (ec || !std::filesystem::is_regular_file(file, ec)) {
      result.message = name + " is not a readable file; using defaults";
      return result;
    }
    if (size > kMaxSettingsBytes) {
      result.message = name + " is " + std::to_string(size) + " bytes, far too large; using defaults" + keepAside(file);
      return result;
    }
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) {
      result.message = name + " could not be read; using defaults";
      return result;
    }
    const std::string content = text.str();
    if (jsonNestingDepth(content, kMaxNesting) > kMaxNesting) {
      result.message = name + " nests deeper than any settings file; using defaults" + keepAside(file);
      return result;
    }
    const json root = json::parse(content, nullptr, /*allow_exceptions=*/false);
    if (root.is_discarded() || !root.is_object()) {
      result.message = name + " is not a JSON object; using defaults" + keepAside(file);
      return result;
    }
    std::vector<std::string> problems;
    result.settings = settingsFromJson(root, problems);
    if (!problems.empty()) {
      result.message = name + ": ";
      for (std::size_t i = 0; i < problems.size() && i < 4; ++i) result.message += (i ? "; " : "") + problems[i];
      if (problems.size() > 4) result.message += "; and " + std::to_string(problems.size() - 4) + " more";
      result.message += " (defaults used for these)" + keepAside(file);
    }
  } catch (const std::exception& e) {
    // Settings never stop the explorer: whatever went wrong, it starts with defaults.
    result = SettingsLoad{};
    result.message = name + " could not be read (" + e.what() + "); using defaults";
  }
  return result;
}

void saveSettings(const Settings& settings, const std::filesystem::path& file) {
  if (file.empty()) throw core::Error("no folder for settings: neither $XDG_CONFIG_HOME nor $HOME is set");
  // Paths that are not valid UTF-8 cannot go into JSON as they are; replacing the odd bytes keeps
  // the rest of the file.
  const std::string text = settingsToJson(settings).dump(2, ' ', false, json::error_handler_t::replace) + "\n";
  // The pid keeps two explorers saving at once from sharing a temporary.
  core::writeFileAtomically(file, text, {.mode = 0644, .createFolder = true, .what = "cannot write settings"});
}

}  // namespace voxflame::app
