#include "xvfb_explorer.h"

#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
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

namespace {

// A window may go between the listing of the windows and a request about it (BadWindow): Xlib's
// default handler would end the process.
int ignoreXErrors(Display*, XErrorEvent*) {
  return 0;
}

// Whether a title property (WM_NAME or _NET_WM_NAME, whatever its encoding) of `window` holds
// `text`; the request's round trip also sends the requests queued before it.
bool titleHolds(Display* display, Window window, Atom property, const std::string& text) {
  Atom type = None;
  int format = 0;
  unsigned long count = 0, after = 0;
  unsigned char* data = nullptr;
  if (XGetWindowProperty(display, window, property, 0, 1024, False, AnyPropertyType, &type, &format, &count, &after,
                         &data) != Success)
    return false;
  const bool holds =
      data && format == 8 && std::string(reinterpret_cast<char*>(data), count).find(text) != std::string::npos;
  if (data) XFree(data);
  return holds;
}

}  // namespace

bool XvfbServer::waitForTitle(const std::string& text, std::chrono::milliseconds limit) const {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  char name[32];
  std::snprintf(name, sizeof name, ":%d", display_);
  Display* display = XOpenDisplay(name);
  if (!display) return false;
  const auto previousHandler = XSetErrorHandler(ignoreXErrors);
  const Window root = DefaultRootWindow(display);
  const Atom netName = XInternAtom(display, "_NET_WM_NAME", False);
  XSelectInput(display, root, SubstructureNotifyMask);  // windows created (and mapped) from now on
  // Asks for every top-level window's property changes, then reads its title: a title set after
  // the read is an event on the connection.
  const auto anyTitleHolds = [&] {
    Window rootReturn = 0, parent = 0, *children = nullptr;
    unsigned count = 0;
    bool holds = false;
    if (XQueryTree(display, root, &rootReturn, &parent, &children, &count)) {
      for (unsigned i = 0; i < count && !holds; ++i) {
        XSelectInput(display, children[i], PropertyChangeMask);
        holds = titleHolds(display, children[i], XA_WM_NAME, text) || titleHolds(display, children[i], netName, text);
      }
      if (children) XFree(children);
    }
    return holds;
  };
  bool found = anyTitleHolds();
  while (!found) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left <= std::chrono::milliseconds(0)) break;
    if (XPending(display) == 0) {
      pollfd connection{ConnectionNumber(display), POLLIN, 0};
      if (poll(&connection, 1, static_cast<int>(left.count())) <= 0) continue;
    }
    while (XPending(display) > 0) {  // what happened matters less than that something did
      XEvent event;
      XNextEvent(display, &event);
    }
    found = anyTitleHolds();
  }
  XCloseDisplay(display);
  XSetErrorHandler(previousHandler);
  return found;
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
