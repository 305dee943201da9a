// Frame files of `voxflame animate`: a printf pattern with one integer conversion names every
// frame (`frames/%04d.png`), and a range of frame numbers says which of them a run renders.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace voxflame::app {

// Frames first..last, both included.
struct FrameRange {
  int first = 0;
  int last = 0;
  int count() const { return last - first + 1; }
};

// Throws UsageError unless the pattern holds exactly one integer conversion (%d, with an optional
// 0 flag and width; %% is a literal percent sign) and ends in .png, .vdb or .nrrd, so snprintf
// with the frame number is safe and ffmpeg reads the same pattern.
void checkFramePattern(const std::string& pattern);

// What the frames are: PNG images, or the accumulated volume of each frame (OpenVDB or NRRD, as
// `render -o OUT.vdb|OUT.nrrd` writes a still's). Throws UsageError for any other extension.
enum class FrameKind { Png, Vdb, Nrrd };
FrameKind frameKind(const std::string& pattern);

// The file of one frame; the pattern must have passed checkFramePattern.
std::string framePath(const std::string& pattern, int frame);

// The folder the frames go to ("" when they go to the working directory).
std::filesystem::path frameFolder(const std::string& pattern, int frame);

// "A-B" or "N" (frame numbers from 0); throws UsageError naming --frames when the text is not
// that or the range does not fit an animation of frameCount frames at fps.
FrameRange parseFrameRange(const std::string& text, int frameCount, double fps);

// "2-3, 7" for the frames 2, 3 and 7 (sorted, without repeats).
std::string describeFrames(const std::vector<int>& frames);

// True when the frame's file is there and starts like its kind (PNG, VDB or NRRD). Frames are
// written to a temporary file and moved into place, so a file that is there is complete.
bool frameExists(const std::string& pattern, int frame);

}  // namespace voxflame::app
