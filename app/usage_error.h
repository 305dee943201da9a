// A mistake in how voxflame was called, found after the command line parsed (a missing output, a
// value that does not fit the preset): the CLI prints it with a pointer to --help and exits 2.
#pragma once

#include "core/error.h"

namespace voxflame::app {

class UsageError : public core::Error {
 public:
  using core::Error::Error;
};

}  // namespace voxflame::app
