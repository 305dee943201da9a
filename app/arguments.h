// Command-line parsing shared by every subcommand: `--name value` options and positional
// arguments; every option must be known, so a typo is an error rather than silently ignored.
#pragma once

#include <algorithm>
#include <cctype>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"

namespace voxflame::app {

// A mistake in how voxflame was called: the CLI prints it followed by the usage text.
class UsageError : public core::Error {
 public:
  using core::Error::Error;
};

// Reads `--name value` pairs and positional arguments; every option must be known.
class Arguments {
 public:
  // Reads args[first..]. Options listed in `flags` take no value (e.g. "--json").
  Arguments(const std::vector<std::string>& args, std::size_t first, std::vector<std::string> flags = {}) {
    for (std::size_t i = first; i < args.size(); ++i) {
      const std::string& a = args[i];
      if (a.size() > 1 && a[0] == '-' && !(a.size() > 1 && std::isdigit(static_cast<unsigned char>(a[1])))) {
        if (std::find(flags.begin(), flags.end(), a) != flags.end()) {
          options_.push_back({a, "", false});
          continue;
        }
        if (i + 1 >= args.size()) throw UsageError("option " + a + " needs a value");
        options_.push_back({a, args[++i], false});
      } else {
        positional_.push_back(a);
      }
    }
  }

  std::optional<std::string> take(const std::string& name, const std::string& alias = "") {
    std::optional<std::string> value;
    for (auto& option : options_)
      if (option.name == name || (!alias.empty() && option.name == alias)) {
        value = option.value;
        option.used = true;
      }
    return value;
  }

  // Every value of a repeatable option (e.g. --param a=1 --param b=2), in command-line order.
  std::vector<std::string> takeAll(const std::string& name) {
    std::vector<std::string> values;
    for (auto& option : options_)
      if (option.name == name) {
        values.push_back(option.value);
        option.used = true;
      }
    return values;
  }

  long long integer(const std::string& name, long long fallback, long long min, long long max) {
    const auto text = take(name);
    if (!text) return fallback;
    std::size_t used = 0;
    long long value = 0;
    try {
      value = std::stoll(*text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != text->size()) throw UsageError(name + " expects a whole number, not '" + *text + "'");
    if (value < min || value > max)
      throw UsageError(name + " is " + *text + "; allowed: " + std::to_string(min) + " to " + std::to_string(max));
    return value;
  }

  bool flag(const std::string& name) { return take(name).has_value(); }

  double real(const std::string& name, double fallback, double min, double max) {
    const auto text = take(name);
    if (!text) return fallback;
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(*text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != text->size() || !(value >= min && value <= max))
      throw UsageError(name + " expects a number from " + std::to_string(min) + " to " + std::to_string(max) +
                       ", not '" + *text + "'");
    return value;
  }

  const std::vector<std::string>& positional() const { return positional_; }

  void finish(std::size_t maxPositional) const {
    for (const auto& option : options_)
      if (!option.used) throw UsageError("unknown option " + option.name);
    if (positional_.size() > maxPositional) throw UsageError("unexpected argument '" + positional_.back() + "'");
  }

 private:
  struct Option {
    std::string name;
    std::string value;
    bool used;
  };
  std::vector<Option> options_;
  std::vector<std::string> positional_;
};

}  // namespace voxflame::app
