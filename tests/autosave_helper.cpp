// A stand-in for an explorer session, for the autosave tests: autosaves the edited scene into
// the folder given, writes a line to READY_FILE (the tests pass a pipe's end, /dev/fd/N, and wait
// for the line), then waits to be killed. A separate program rather than a fork, so that the
// tests also run under ThreadSanitizer (which refuses threads started in a forked child).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>

#include "autosave.h"
#include "autosave_helper.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: autosave_helper FOLDER READY_FILE\n");
    return 2;
  }
  voxflame::app::Autosave::Options options;
  options.folder = argv[1];
  options.interval = std::chrono::milliseconds(0);
  voxflame::app::Autosave autosave(options);
  autosave.update(voxflame::core::defaultScene());  // the session's start: not written
  autosave.update(voxflame::test::editedScene());
  autosave.flush();
  if (!autosave.lastError().empty()) {
    std::fprintf(stderr, "%s\n", autosave.lastError().c_str());
    return 1;
  }
  std::ofstream(argv[2]) << "ready\n";
  for (;;) pause();
}
