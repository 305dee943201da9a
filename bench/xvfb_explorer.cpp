#include "xvfb_explorer.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

extern char** environ;

namespace voxflame::bench {

XvfbServer::XvfbServer(const std::string& screen) {
  int fds[2];
  if (pipe(fds) != 0) return;
  pid_ = fork();
  if (pid_ == 0) {
    close(fds[0]);
    const std::string fd = std::to_string(fds[1]);
    execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", screen.c_str(), "-nolisten", "tcp", nullptr);
    _exit(127);
  }
  close(fds[1]);
  std::string number;
  char c = 0;
  while (read(fds[0], &c, 1) == 1 && c != '\n') number += c;
  close(fds[0]);
  if (!number.empty()) display_ = std::stoi(number);
  for (int i = 0; i < 100 && !running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
}

XvfbServer::~XvfbServer() {
  stop();
}

void XvfbServer::stop() {
  if (pid_ > 0) {
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }
}

bool XvfbServer::running() const {
  return display_ >= 0 && std::filesystem::exists("/tmp/.X11-unix/X" + std::to_string(display_));
}

int XvfbServer::xdotool(const std::string& arguments) const {
  return std::system(("env " + environment() + " timeout 120 xdotool " + arguments + " >/dev/null").c_str());
}

bool haveXvfbAndXdotool() {
  return std::system("command -v xdotool >/dev/null && command -v Xvfb >/dev/null") == 0;
}

BackgroundExplorer::BackgroundExplorer(const XvfbServer& server, const std::filesystem::path& binary,
                                       const std::filesystem::path& folder, std::vector<std::string> arguments)
    : log_(folder / "explorer.log") {
  std::vector<std::string> environment = {server.environment(), "LIBGL_ALWAYS_SOFTWARE=1"};
  for (const char* kind : {"CONFIG", "STATE", "DATA", "CACHE"})
    environment.push_back(std::string("XDG_") + kind + "_HOME=" + (folder / kind).string());
  for (char** variable = environ; *variable; ++variable) {
    const std::string entry = *variable;
    if (entry.rfind("DISPLAY=", 0) != 0 && entry.rfind("WAYLAND_DISPLAY=", 0) != 0 && entry.rfind("XDG_", 0) != 0 &&
        entry.rfind("LIBGL_ALWAYS_SOFTWARE=", 0) != 0)
      environment.push_back(entry);
  }
  arguments.insert(arguments.begin(), binary.string());
  std::vector<char*> argv, envp;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  for (std::string& entry : environment) envp.push_back(entry.data());
  argv.push_back(nullptr);
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
  if (posix_spawn(&pid_, binary.c_str(), &actions, nullptr, argv.data(), envp.data()) != 0) pid_ = -1;
  posix_spawn_file_actions_destroy(&actions);
}

BackgroundExplorer::~BackgroundExplorer() {
  if (pid_ > 0) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
}

void BackgroundExplorer::signal(int number) const {
  if (pid_ > 0) kill(pid_, number);
}

std::optional<int> BackgroundExplorer::exitStatus(std::chrono::seconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (pid_ > 0) {
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      status_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    } else if (std::chrono::steady_clock::now() > deadline) {
      break;
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }
  return status_;
}

std::string BackgroundExplorer::output() const {
  std::ifstream in(log_);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace voxflame::bench
