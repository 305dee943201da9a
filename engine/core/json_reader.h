// Strict reading of one JSON object of a preset. Every key that is read is remembered, and
// finish() reports any key that was not, so a misspelt key is an error instead of a silent
// no-op. Messages carry the source (a file name) and the key path in the form users see in
// presets/SCHEMA.md ("layers[0].color.scale"). The schema tables (scene_schema.h) and the
// keyframe reader (keyframes.h) both read through it.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

namespace voxflame::core {

class ObjectReader {
 public:
  // Throws core::Error when `object` is not a JSON object.
  ObjectReader(const nlohmann::json& object, std::string source, std::string path);

  // Throws core::Error "SOURCE: 'PATH.KEY' REASON" (or the object's own path without a key).
  [[noreturn]] void fail(const std::string& reason, const std::string& key = "") const;
  std::string keyPath(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  const std::string& source() const { return source_; }
  const std::string& path() const { return path_; }

  // The value of `key`, or nullptr; either way the key counts as read.
  const nlohmann::json* find(const std::string& key);
  bool has(const std::string& key) const { return object_.contains(key); }
  // The object under `key` as a reader of its own (whose finish() checks its keys), or nothing
  // when the key is absent; either way the key counts as read. Throws when it is not an object.
  std::optional<ObjectReader> child(const std::string& key);

  double number(const std::string& key, double fallback, double min, double max);
  double checkNumber(const nlohmann::json& value, const std::string& key, double min, double max) const;
  std::int64_t integer(const std::string& key, std::int64_t fallback, std::int64_t min, std::int64_t max);
  std::string string(const std::string& key, const std::string& fallback);
  std::string requiredString(const std::string& key);
  glm::vec3 color(const std::string& key, glm::vec3 fallback);
  bool boolean(const std::string& key, bool fallback);
  glm::dvec3 vector(const std::string& key, glm::dvec3 fallback, double min, double max);

  void finish() const;  // fails on the first key that was never read

 private:
  const nlohmann::json& object_;
  std::string source_;
  std::string path_;
  std::set<std::string> seen_;
};

// "is 5, outside the allowed range [0, 1]": the reason every range check gives, so a value typed
// into a preset and one reached by a keyframe are refused with the same words.
std::string outsideRange(double value, double min, double max);
std::string outsideRange(std::int64_t value, std::int64_t min, std::int64_t max);

}  // namespace voxflame::core
