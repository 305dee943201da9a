#include "json_reader.h"

#include <cmath>
#include <sstream>

#include "color.h"
#include "error.h"

namespace voxflame::core {

using nlohmann::json;

std::string outsideRange(double value, double min, double max) {
  std::ostringstream text;
  text << "is " << value << ", outside the allowed range [" << min << ", " << max << "]";
  return text.str();
}

std::string outsideRange(std::int64_t value, std::int64_t min, std::int64_t max) {
  return "is " + std::to_string(value) + ", outside the allowed range [" + std::to_string(min) + ", " +
         std::to_string(max) + "]";
}

ObjectReader::ObjectReader(const json& object, std::string source, std::string path)
    : object_(object), source_(std::move(source)), path_(std::move(path)) {
  if (!object_.is_object()) fail(path_.empty() ? "the preset must be a JSON object" : "must be an object");
}

void ObjectReader::fail(const std::string& reason, const std::string& key) const {
  const std::string where = key.empty() ? path_ : keyPath(key);
  throw Error(source_ + ": " + (where.empty() ? "" : "'" + where + "' ") + reason);
}

const json* ObjectReader::find(const std::string& key) {
  seen_.insert(key);
  auto it = object_.find(key);
  return it == object_.end() ? nullptr : &*it;
}

std::optional<ObjectReader> ObjectReader::child(const std::string& key) {
  const json* value = find(key);
  if (!value) return std::nullopt;
  return ObjectReader(*value, source_, keyPath(key));
}

double ObjectReader::number(const std::string& key, double fallback, double min, double max) {
  const json* value = find(key);
  if (!value) return fallback;
  return checkNumber(*value, key, min, max);
}

double ObjectReader::checkNumber(const json& value, const std::string& key, double min, double max) const {
  if (!value.is_number()) fail("must be a number", key);
  const double v = value.get<double>();
  if (!std::isfinite(v) || v < min || v > max) fail(outsideRange(v, min, max), key);
  return v;
}

std::int64_t ObjectReader::integer(const std::string& key, std::int64_t fallback, std::int64_t min, std::int64_t max) {
  const json* value = find(key);
  if (!value) return fallback;
  if (!value->is_number_integer()) fail("must be a whole number", key);
  // An unsigned number beyond int64 reads as negative; it is out of every range we allow anyway.
  if (value->is_number_unsigned() && value->get<std::uint64_t>() > static_cast<std::uint64_t>(max)) {
    std::ostringstream text;
    text << "is " << value->get<std::uint64_t>() << ", outside the allowed range [" << min << ", " << max << "]";
    fail(text.str(), key);
  }
  const auto v = value->get<std::int64_t>();
  if (v < min || v > max) fail(outsideRange(v, min, max), key);
  return v;
}

std::string ObjectReader::string(const std::string& key, const std::string& fallback) {
  const json* value = find(key);
  if (!value) return fallback;
  if (!value->is_string()) fail("must be a string", key);
  return value->get<std::string>();
}

std::string ObjectReader::requiredString(const std::string& key) {
  if (!object_.contains(key)) fail("is missing", key);
  return string(key, "");
}

glm::vec3 ObjectReader::color(const std::string& key, glm::vec3 fallback) {
  const json* value = find(key);
  if (!value) return fallback;
  if (!value->is_string()) fail("must be a colour string like \"#ff8800\"", key);
  try {
    return parseHexColor(value->get<std::string>());
  } catch (const Error& e) {
    fail(e.what(), key);
  }
}

bool ObjectReader::boolean(const std::string& key, bool fallback) {
  const json* value = find(key);
  if (!value) return fallback;
  if (!value->is_boolean()) fail("must be true or false", key);
  return value->get<bool>();
}

glm::dvec3 ObjectReader::vector(const std::string& key, glm::dvec3 fallback, double min, double max) {
  const json* value = find(key);
  if (!value) return fallback;
  if (!value->is_array() || value->size() != 3) fail("must be an array of three numbers", key);
  glm::dvec3 v;
  for (int i = 0; i < 3; ++i) v[i] = checkNumber((*value)[static_cast<std::size_t>(i)], key, min, max);
  return v;
}

void ObjectReader::finish() const {
  for (auto it = object_.begin(); it != object_.end(); ++it)
    if (!seen_.count(it.key())) fail("is not a known key", it.key());
}

}  // namespace voxflame::core
