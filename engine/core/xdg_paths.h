// Where voxflame keeps its files in the user's home, following the XDG Base Directory
// specification: the mask cache ($XDG_CACHE_HOME), settings ($XDG_CONFIG_HOME), the autosave
// ($XDG_STATE_HOME) and the user's presets ($XDG_DATA_HOME), each in a `voxflame` folder. A
// variable that is unset, empty or relative is ignored (the specification says so) and the
// documented fallback under $HOME is used instead.
#pragma once

#include <filesystem>

namespace voxflame::core {

enum class XdgKind {
  Cache,   // $XDG_CACHE_HOME, else ~/.cache
  Config,  // $XDG_CONFIG_HOME, else ~/.config
  State,   // $XDG_STATE_HOME, else ~/.local/state
  Data,    // $XDG_DATA_HOME, else ~/.local/share
};

// <base>/voxflame for this kind; empty when neither the variable nor $HOME is usable. Nothing
// is created on disk.
std::filesystem::path xdgFolder(XdgKind kind);

}  // namespace voxflame::core
