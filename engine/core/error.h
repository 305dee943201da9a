// Errors a user can cause (a bad file, a bad value) are reported as voxflame::core::Error,
// whose message is written for that user: it names the file, the key or the value and says why.
// The UI shows it; the CLI prints it and exits non-zero. Programming errors stay asserts.
#pragma once

#include <stdexcept>
#include <string>

namespace voxflame::core {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace voxflame::core
