// core::writeFileAtomically: the one way voxflame replaces a file.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "core/file_output.h"
#include "test_support.h"

using namespace voxflame::core;
using voxflame::test::TemporaryFolder;

namespace {

std::string contentOf(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> namesIn(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& item : std::filesystem::directory_iterator(folder)) names.push_back(item.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string messageOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no core::Error)";
}

}  // namespace

TEST(AtomicFile, WritesTheWholeContentAndLeavesNothingElse) {
  TemporaryFolder folder;
  std::string big(3 << 20, '\0');
  for (std::size_t i = 0; i < big.size(); ++i) big[i] = static_cast<char>(i * 7919 % 251);
  writeFileAtomically(folder / "out.bin", big);
  EXPECT_EQ(contentOf(folder / "out.bin"), big);
  writeFileAtomically(folder / "out.bin", "replaced");  // over an existing file
  EXPECT_EQ(contentOf(folder / "out.bin"), "replaced");
  writeFileAtomically(folder / "empty.txt", "");
  EXPECT_EQ(std::filesystem::file_size(folder / "empty.txt"), 0u);
  EXPECT_EQ(namesIn(folder.path()), (std::vector<std::string>{"empty.txt", "out.bin"}));
}

TEST(AtomicFile, HonoursModeAndCreatesTheFolderWhenAsked) {
  TemporaryFolder folder;
  writeFileAtomically(folder / "a" / "b" / "private.json", "{}", {.mode = 0600, .createFolder = true});
  struct stat info {};
  ASSERT_EQ(::stat((folder / "a" / "b" / "private.json").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0600u);
  // Without createFolder a missing folder is an error naming the file.
  const std::string message = messageOf([&] { writeFileAtomically(folder / "missing" / "x.txt", "x"); });
  EXPECT_NE(message.find((folder / "missing" / "x.txt").string()), std::string::npos) << message;
  EXPECT_NE(message.find("cannot write"), std::string::npos) << message;
}

TEST(AtomicFile, AFailedWriterLeavesTheOldFileAndNoTemporary) {
  TemporaryFolder folder;
  writeFileAtomically(folder / "keep.txt", "old");
  std::filesystem::path seen;
  const std::string message = messageOf([&] {
    writeFileAtomicallyWith(folder / "keep.txt",
                            [&](const std::filesystem::path& temporary) {
                              seen = temporary;
                              // In the same folder: the rename cannot cross file systems.
                              EXPECT_EQ(temporary.parent_path(), folder.path());
                              EXPECT_TRUE(std::filesystem::exists(temporary));
                              std::ofstream(temporary) << "half of the ne";
                              throw std::runtime_error("the writer gave up");
                            },
                            {.what = "cannot save"});
  });
  EXPECT_EQ(message, "cannot save '" + (folder / "keep.txt").string() + "': the writer gave up");
  EXPECT_FALSE(seen.empty());
  EXPECT_FALSE(std::filesystem::exists(seen));
  EXPECT_EQ(contentOf(folder / "keep.txt"), "old");
  EXPECT_EQ(namesIn(folder.path()), (std::vector<std::string>{"keep.txt"}));

  // A core::Error from the writer passes through as it is.
  EXPECT_EQ(messageOf([&] {
              writeFileAtomicallyWith(folder / "other.txt",
                                      [](const std::filesystem::path&) { throw Error("the writer's own words"); });
            }),
            "the writer's own words");
  EXPECT_EQ(namesIn(folder.path()), (std::vector<std::string>{"keep.txt"}));
}

TEST(AtomicFile, AFailedRenameRemovesTheTemporary) {
  TemporaryFolder folder;
  // A non-empty folder where the file should go: everything succeeds but the rename.
  std::filesystem::create_directories(folder / "taken" / "inside");
  const std::string message = messageOf([&] { writeFileAtomically(folder / "taken", "content"); });
  EXPECT_NE(message.find((folder / "taken").string()), std::string::npos) << message;
  EXPECT_EQ(namesIn(folder.path()), (std::vector<std::string>{"taken"}));
}

TEST(AtomicFile, WriterGetsAFreshTemporaryItsOwnerCanRecognise) {
  TemporaryFolder folder;
  std::vector<std::filesystem::path> temporaries;
  for (int i = 0; i < 2; ++i)
    writeFileAtomicallyWith(folder / "render.png", [&](const std::filesystem::path& temporary) {
      EXPECT_EQ(std::filesystem::file_size(temporary), 0u);
      temporaries.push_back(temporary);
      std::ofstream(temporary) << "frame " << i;
    });
  EXPECT_NE(temporaries[0], temporaries[1]);  // never shared, even within a process
  EXPECT_EQ(contentOf(folder / "render.png"), "frame 1");
  EXPECT_EQ(atomicTemporaryTarget(temporaries[0].filename().string()), "render.png");
  EXPECT_EQ(atomicTemporaryTarget("render.png"), "");
  EXPECT_EQ(atomicTemporaryTarget("render.png.part"), "");
  EXPECT_EQ(atomicTemporaryTarget("render.png.12-x.part"), "");
  EXPECT_EQ(atomicTemporaryTarget("autosave-12-3.json.12-0.part"), "autosave-12-3.json");
}
