#include "autosave.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <tuple>
#include <utility>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/file_output.h"
#include "core/xdg_paths.h"
#include "json_guard.h"

namespace voxflame::app {

using nlohmann::json;

namespace {

constexpr const char* kFormat = "voxflame-autosave";
constexpr int kFormatVersion = 1;
constexpr const char* kPrefix = "autosave-";
// A preset is a few kilobytes; a file far larger is not an autosave.
constexpr std::uintmax_t kMaxAutosaveBytes = 16 << 20;
// An autosave nests about six deep (document, preset, layers, layer, colour, gradient).
constexpr int kMaxNesting = 32;

std::string readSmallFile(const std::filesystem::path& path, std::size_t limit) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::string text(limit, '\0');
  in.read(text.data(), static_cast<std::streamsize>(limit));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

// Field 22 of /proc/PID/stat (after the command name, which may hold spaces and parentheses).
std::optional<std::uint64_t> processStartTicks(pid_t pid) {
  const std::string stat = readSmallFile("/proc/" + std::to_string(pid) + "/stat", 4096);
  const auto close = stat.rfind(')');
  if (close == std::string::npos) return std::nullopt;
  std::istringstream fields(stat.substr(close + 1));
  std::string field;
  // Fields after the name start at 3 (state); the start time is field 22.
  for (int index = 3; index <= 22 && fields >> field; ++index)
    if (index == 22) {
      try {
        return std::stoull(field);
      } catch (const std::exception&) {
        return std::nullopt;
      }
    }
  return std::nullopt;
}

std::string currentBootId() {
  std::string id = readSmallFile("/proc/sys/kernel/random/boot_id", 64);
  while (!id.empty() && (id.back() == '\n' || id.back() == ' ')) id.pop_back();
  return id;
}

std::string fileNameOf(const SessionOwner& owner) {
  return kPrefix + std::to_string(owner.pid) + "-" + std::to_string(owner.startTicks) + ".json";
}

// The owner a file name says, for files too broken to read.
std::optional<SessionOwner> ownerFromFileName(const std::string& name) {
  if (name.rfind(kPrefix, 0) != 0) return std::nullopt;
  long long pid = 0;
  unsigned long long ticks = 0;
  char tail[8] = {};
  if (std::sscanf(name.c_str() + std::strlen(kPrefix), "%lld-%llu.%5s", &pid, &ticks, tail) != 3 ||
      std::string(tail) != "json" || pid <= 0 || pid > (1LL << 30))
    return std::nullopt;
  SessionOwner owner;
  owner.pid = static_cast<pid_t>(pid);
  owner.startTicks = ticks;
  return owner;
}

double secondsSinceEpoch(std::chrono::system_clock::time_point time) {
  return std::chrono::duration<double>(time.time_since_epoch()).count();
}

// What an autosave holds: the preset text and the folder its relative paths (a mesh) resolve in.
std::pair<std::string, std::string> presetAndBase(const core::Scene& scene) {
  std::string base;
  if (!scene.embedded && !scene.baseDirectory.empty()) {
    std::error_code ec;
    base = std::filesystem::absolute(scene.baseDirectory, ec).lexically_normal().string();
  }
  return {core::sceneToJson(scene), base};
}

}  // namespace

SessionOwner SessionOwner::current() {
  SessionOwner owner;
  owner.pid = ::getpid();
  owner.startTicks = processStartTicks(owner.pid).value_or(0);
  owner.bootId = currentBootId();
  return owner;
}

bool SessionOwner::alive() const {
  if (pid <= 0) return false;
  if (!bootId.empty() && bootId != currentBootId()) return false;  // saved before a reboot
  if (const auto ticks = processStartTicks(pid)) return *ticks == startTicks;
  // No /proc entry: the process is gone (or /proc is not mounted; then ask the kernel).
  std::error_code ec;
  if (std::filesystem::exists("/proc/self/stat", ec)) return false;
  return ::kill(pid, 0) == 0 || errno == EPERM;
}

std::filesystem::path defaultAutosaveFolder() {
  const std::filesystem::path folder = core::xdgFolder(core::XdgKind::State);
  return folder.empty() ? folder : folder / "autosave";
}

Autosave::Autosave(Options options)
    : owner_(SessionOwner::current()),
      interval_(std::chrono::duration_cast<std::chrono::steady_clock::duration>(options.interval)),
      clock_(std::move(options.clock)) {
  const std::filesystem::path folder = options.folder.empty() ? defaultAutosaveFolder() : options.folder;
  if (!folder.empty()) file_ = folder / fileNameOf(owner_);
  writer_ = std::jthread([this](std::stop_token stop) { writerLoop(stop); });
}

Autosave::~Autosave() {
  writer_.request_stop();
  writer_.join();  // writes what is pending first
}

bool Autosave::update(const core::Scene& scene) {
  if (finished_ || file_.empty()) return true;  // nothing to look for, now or later
  const auto now = clock_ ? clock_() : std::chrono::steady_clock::now();
  if (haveBaseline_ && now - lastCheck_ < interval_) return false;
  lastCheck_ = now;
  std::string preset, base;
  try {
    std::tie(preset, base) = presetAndBase(scene);
  } catch (const std::exception& e) {
    const std::lock_guard lock(mutex_);
    lastError_ = std::string("cannot autosave this scene: ") + e.what();
    return true;
  }
  const std::string key = preset + '\n' + base;
  if (!haveBaseline_) {
    haveBaseline_ = true;
    lastHanded_ = key;
    return true;
  }
  if (key == lastHanded_) return true;
  lastHanded_ = key;
  {
    const std::lock_guard lock(mutex_);
    pending_.emplace(std::move(preset), std::move(base));
  }
  wake_.notify_one();
  return true;
}

std::string Autosave::saveNow(const core::Scene& scene) {
  if (finished_ || file_.empty()) return {};
  finished_ = true;
  std::string preset, base;
  try {
    std::tie(preset, base) = presetAndBase(scene);
  } catch (const std::exception& e) {
    return std::string("cannot autosave this scene: ") + e.what();
  }
  {
    const std::lock_guard lock(mutex_);
    pending_.emplace(std::move(preset), std::move(base));
  }
  wake_.notify_one();
  flush();
  return lastError();
}

void Autosave::flush() {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [this] { return !pending_ && !writing_; });
}

void Autosave::finishCleanly() {
  finished_ = true;
  {
    std::unique_lock lock(mutex_);
    pending_.reset();
    idle_.wait(lock, [this] { return !writing_; });
  }
  if (!file_.empty()) {
    std::error_code ec;
    std::filesystem::remove(file_, ec);
  }
}

std::string Autosave::lastError() const {
  const std::lock_guard lock(mutex_);
  return lastError_;
}

void Autosave::writerLoop(std::stop_token stop) {
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, stop, [this] { return pending_.has_value(); });
    if (!pending_) return;  // stopped with nothing left to write
    const auto [preset, base] = std::move(*pending_);
    pending_.reset();
    writing_ = true;
    lock.unlock();
    std::string error;
    try {
      write(preset, base);
    } catch (const std::exception& e) {
      error = e.what();
    }
    lock.lock();
    writing_ = false;
    lastError_ = error;
    idle_.notify_all();
  }
}

void Autosave::write(const std::string& preset, const std::string& baseDirectory) {
  json document;
  document["format"] = kFormat;
  document["version"] = kFormatVersion;
  document["owner"] = {{"pid", owner_.pid}, {"start_ticks", owner_.startTicks}, {"boot_id", owner_.bootId}};
  document["saved_at"] = secondsSinceEpoch(std::chrono::system_clock::now());
  document["base_directory"] = baseDirectory;
  document["preset"] = json::parse(preset);
  const std::string text = document.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
  core::writeFileAtomically(file_, text, {.mode = 0600, .createFolder = true, .what = "cannot autosave to"});
}

std::vector<Recoverable> findRecoverable(const std::filesystem::path& folder) {
  std::vector<Recoverable> found;
  if (folder.empty()) return found;
  std::error_code ec;
  for (const auto& item : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = item.path().filename().string();
    const auto namedOwner = ownerFromFileName(name);
    if (!namedOwner) {
      // A temporary a dead session left mid-write holds nothing the final file lacks (".json.tmp"
      // is how sessions before core::writeFileAtomically named theirs).
      std::string target = core::atomicTemporaryTarget(name);
      if (target.empty() && name.ends_with(".json.tmp")) target = name.substr(0, name.size() - 4);
      const auto tmpOwner = target.empty() ? std::nullopt : ownerFromFileName(target);
      if (tmpOwner && !tmpOwner->alive()) std::filesystem::remove(item.path(), ec);
      continue;
    }
    Recoverable entry;
    entry.file = item.path();
    entry.savedAt =
        std::chrono::system_clock::time_point(std::chrono::duration_cast<std::chrono::system_clock::duration>(
            std::filesystem::last_write_time(item.path(), ec).time_since_epoch() -
            std::filesystem::file_time_type::clock::now().time_since_epoch() +
            std::chrono::system_clock::now().time_since_epoch()));
    try {
      if (std::filesystem::file_size(item.path(), ec) > kMaxAutosaveBytes || ec)
        throw core::Error("is not a readable autosave (too large or unreadable)");
      const std::string text = readSmallFile(item.path(), kMaxAutosaveBytes);
      if (jsonNestingDepth(text, kMaxNesting) > kMaxNesting) throw core::Error("nests deeper than any autosave");
      const json document = json::parse(text, nullptr, false);
      if (document.is_discarded() || !document.is_object() || document.value("format", "") != kFormat)
        throw core::Error("is not a voxflame autosave (not the JSON it writes)");
      SessionOwner owner = *namedOwner;
      if (const auto o = document.find("owner"); o != document.end() && o->is_object()) {
        if (o->value("pid", 0LL) != owner.pid || o->value("start_ticks", 0ULL) != owner.startTicks)
          throw core::Error("names an owner other than its file name says");
        owner.bootId = o->value("boot_id", "");
      }
      if (owner.alive()) continue;  // a running explorer's: not ours to take
      if (const auto t = document.find("saved_at"); t != document.end() && t->is_number()) {
        const double seconds = t->get<double>();
        if (seconds > 0 && seconds < 1e11)
          entry.savedAt = std::chrono::system_clock::time_point(
              std::chrono::duration_cast<std::chrono::system_clock::duration>(std::chrono::duration<double>(seconds)));
      }
      const auto preset = document.find("preset");
      if (preset == document.end() || !preset->is_object()) throw core::Error("holds no preset");
      core::Scene scene = core::sceneFromJson(preset->dump(), entry.file.string());
      const std::string base = document.value("base_directory", "");
      if (!scene.embedded) scene.baseDirectory = base;
      entry.scene = std::move(scene);
    } catch (const std::exception& e) {
      if (namedOwner->alive()) continue;
      const std::string message = e.what();
      // sceneFromJson's messages already name the file.
      entry.error =
          message.rfind(entry.file.string(), 0) == 0 ? message : "autosave '" + entry.file.string() + "' " + message;
    }
    found.push_back(std::move(entry));
  }
  std::sort(found.begin(), found.end(),
            [](const Recoverable& a, const Recoverable& b) { return a.savedAt > b.savedAt; });
  return found;
}

void dismissRecoverable(const Recoverable& recoverable) {
  std::error_code ec;
  std::filesystem::remove(recoverable.file, ec);
}

}  // namespace voxflame::app
