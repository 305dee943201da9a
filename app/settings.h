// What the explorer remembers between sessions: the window's size and place, the last preset,
// recent presets and meshes, the user's preset folder and the last export's settings. They live
// in $XDG_CONFIG_HOME/voxflame/settings.json (else ~/.config/voxflame/settings.json).
//
// Settings are a convenience, never a reason to stop: loading a missing file gives defaults, and
// a malformed or hostile one (not JSON, absurdly nested or large, values of the wrong type or out
// of range) gives defaults for what is wrong plus one message for the window; the file is copied
// to settings.json.bad first, so saving later cannot silently destroy what the user wrote. Saving
// is atomic (a temporary beside the file, then a rename). Load and save are small synchronous
// file operations: call them at start, on exit and after a user action, not every frame.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "export_job.h"
#include "refinement_backends.h"

namespace voxflame::app {

inline constexpr std::size_t kMaxRecentFiles = 10;  // per kind

enum class RecentKind { Preset, Mesh };

// Where a default scene's volume stops changing visibly: the last percent or two of voxel noise
// hides under the ray-marcher's averaging along each ray.
inline constexpr double kDefaultRefineUntilNoisePercent = 1.5;

struct RecentFile {
  std::filesystem::path path;  // absolute
  RecentKind kind = RecentKind::Preset;
};

struct WindowGeometry {
  int width = 1600;         // 200–32768
  int height = 900;         // 200–32768
  std::optional<int> x, y;  // the window's position on the desktop; none: the system's choice
  bool maximized = false;
};

struct Settings {
  WindowGeometry window;
  std::filesystem::path lastPreset;        // empty: none
  std::vector<RecentFile> recent;          // most recent first, at most kMaxRecentFiles per kind
  std::filesystem::path userPresetFolder;  // empty: defaultUserPresetFolder()
  ExportSettings lastExport;
  std::filesystem::path lastExportFolder;  // empty: none yet
  // The explorer stops refining once the volume's estimated noise (core/refinement/convergence.h) is this
  // many percent, and the process rests; 0: never stop (refine until the next edit). 0–100.
  double refineUntilNoisePercent = kDefaultRefineUntilNoisePercent;
  // What refines the explorer's volume ("refinement_backend": cpu, gpu or auto;
  // refinement_backends.h): auto takes the GPU where the GL renderer is a hardware one. The CPU by
  // default, as render's --backend.
  BackendChoice refinementBackend = BackendChoice::Cpu;

  // Puts `path` (made absolute) first among its kind, removing an earlier mention and the
  // oldest beyond kMaxRecentFiles.
  void addRecent(RecentKind kind, const std::filesystem::path& path);
  std::vector<std::filesystem::path> recentOf(RecentKind kind) const;  // most recent first
  std::filesystem::path presetFolder() const;                          // userPresetFolder or the default
};

// $XDG_CONFIG_HOME/voxflame/settings.json, else ~/.config/voxflame/settings.json; empty when
// neither $XDG_CONFIG_HOME nor $HOME is set.
std::filesystem::path defaultSettingsPath();
// $XDG_DATA_HOME/voxflame/presets, else ~/.local/share/voxflame/presets.
std::filesystem::path defaultUserPresetFolder();

struct SettingsLoad {
  Settings settings;
  std::string message;  // empty when the file was missing or fine; otherwise for the window
};

// Never throws. Recent files that no longer exist are dropped.
SettingsLoad loadSettings(const std::filesystem::path& file = defaultSettingsPath());

// Writes atomically, creating the folder. Throws core::Error naming the file when it cannot.
void saveSettings(const Settings& settings, const std::filesystem::path& file = defaultSettingsPath());

}  // namespace voxflame::app
