#include "frame_pattern.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <fstream>

#include "usage_error.h"

namespace voxflame::app {

void checkFramePattern(const std::string& pattern) {
  int conversions = 0;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') continue;
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < pattern.size() && pattern[j] == '0') ++j;
    const std::size_t widthStart = j;
    while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) ++j;
    if (j >= pattern.size()) throw UsageError("-o '" + pattern + "' ends in an unfinished % conversion");
    if (j - widthStart > 2) throw UsageError("-o '" + pattern + "': a frame number wider than 99 digits is not useful");
    if (pattern[j] == 's')
      throw UsageError("-o '" + pattern + "': %s is not allowed; the frame number is an integer, e.g. frames/%04d.png");
    if (pattern[j] != 'd')
      throw UsageError("-o '" + pattern + "': '" + pattern.substr(i, j - i + 1) +
                       "' is not a frame number; use %d or %04d (and %% for a percent sign)");
    ++conversions;
    i = j;
  }
  if (conversions == 0)
    throw UsageError("-o '" + pattern + "' has no frame number; give a printf pattern such as frames/%04d.png");
  if (conversions > 1)
    throw UsageError("-o '" + pattern + "' has " + std::to_string(conversions) +
                     " conversions; it needs exactly one frame number such as %04d");
  frameKind(pattern);  // throws for any other extension
}

FrameKind frameKind(const std::string& pattern) {
  std::string extension = std::filesystem::path(pattern).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".png") return FrameKind::Png;
  if (extension == ".vdb") return FrameKind::Vdb;
  if (extension == ".nrrd") return FrameKind::Nrrd;
  throw UsageError("-o '" + pattern +
                   "' must end in .png (PNG images) or .vdb or .nrrd (the accumulated volume of each frame)");
}

std::string framePath(const std::string& pattern, int frame) {
  // checkFramePattern allows exactly one %d: the format is safe with one int.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
  const int length = std::snprintf(nullptr, 0, pattern.c_str(), frame);
  std::string path(static_cast<std::size_t>(length) + 1, '\0');
  std::snprintf(path.data(), path.size(), pattern.c_str(), frame);
#pragma GCC diagnostic pop
  path.resize(static_cast<std::size_t>(length));
  return path;
}

std::filesystem::path frameFolder(const std::string& pattern, int frame) {
  return std::filesystem::path(framePath(pattern, frame)).parent_path();
}

FrameRange parseFrameRange(const std::string& text, int frameCount, double fps) {
  const auto number = [&](const std::string& part) {
    if (part.empty() || part.size() > 9 ||
        !std::all_of(part.begin(), part.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
      throw UsageError("--frames expects A-B or N (frame numbers from 0), not '" + text + "'");
    return std::stoi(part);
  };
  const std::size_t dash = text.find('-');
  FrameRange range;
  range.first = number(text.substr(0, dash));
  range.last = dash == std::string::npos ? range.first : number(text.substr(dash + 1));
  if (range.first > range.last) throw UsageError("--frames " + text + ": the first frame comes after the last");
  if (range.last >= frameCount) {
    char fpsText[32];
    std::snprintf(fpsText, sizeof fpsText, "%g", fps);
    throw UsageError("--frames " + text + ": the animation has " + std::to_string(frameCount) + " frames (0-" +
                     std::to_string(frameCount - 1) + ") at " + fpsText + " fps");
  }
  return range;
}

std::string describeFrames(const std::vector<int>& frames) {
  std::vector<int> sorted = frames;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  std::string text;
  for (std::size_t i = 0; i < sorted.size();) {
    std::size_t j = i;
    while (j + 1 < sorted.size() && sorted[j + 1] == sorted[j] + 1) ++j;
    if (!text.empty()) text += ", ";
    text += std::to_string(sorted[i]);
    if (j > i) {
      text += '-';
      text += std::to_string(sorted[j]);
    }
    i = j + 1;
  }
  return text;
}

bool frameExists(const std::string& pattern, int frame) {
  std::ifstream in(framePath(pattern, frame), std::ios::binary);
  std::array<char, 8> head{};
  if (!in.read(head.data(), head.size())) return false;
  // PNG's signature; OpenVDB's magic number (" BDV", a little-endian 64-bit integer); NRRD's.
  constexpr std::array<unsigned char, 8> kPngSignature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  constexpr std::array<unsigned char, 8> kVdbMagic{' ', 'B', 'D', 'V', 0, 0, 0, 0};
  constexpr std::array<unsigned char, 8> kNrrdMagic{'N', 'R', 'R', 'D', '0', '0', '0', '0'};
  const std::array<unsigned char, 8>& expected = frameKind(pattern) == FrameKind::Png   ? kPngSignature
                                                 : frameKind(pattern) == FrameKind::Vdb ? kVdbMagic
                                                                                        : kNrrdMagic;
  const std::size_t compared = frameKind(pattern) == FrameKind::Nrrd ? 4 : 8;  // NRRD0004, NRRD0005, ...
  return std::equal(head.begin(), head.begin() + static_cast<std::ptrdiff_t>(compared), expected.begin(),
                    [](char a, unsigned char b) { return static_cast<unsigned char>(a) == b; });
}

}  // namespace voxflame::app
