// io::writeStaged: a whole file written under its partial name and renamed when complete
// (the window's saves use it). What a reader of the final name can see while the write lasts,
// and what a failed write leaves.
#include "fosssim/io/staged_file.h"

#include "support/temp_dir_test.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fosssim::io {
namespace {

namespace fs = std::filesystem;

class StagedWrite : public fosssim::testing::TempDirTest {
 protected:
  static std::string read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  static void put(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }
  /// The folder's entries, by name, sorted.
  std::string entries() const {
    std::string names;
    std::vector<std::string> all;
    for (const auto& e : fs::directory_iterator(dir_)) all.push_back(e.path().filename().string());
    std::sort(all.begin(), all.end());
    for (const std::string& n : all) names += n + ";";
    return names;
  }
};

TEST_F(StagedWrite, TheFinalNameHoldsTheOldFileUntilTheNewOneIsWholeThenTheNewOne) {
  const std::string path = this->path("shot.png");
  put(path, "old");
  std::string seenDuringWrite, writtenTo;
  const Status s = writeStaged(path, "test", [&](const std::string& to) {
    writtenTo = to;
    put(to, "first half ");
    seenDuringWrite = read(path);  // what a script polling the final name finds now
    std::ofstream(to, std::ios::binary | std::ios::app) << "second half";
    return Status::ok();
  });
  ASSERT_TRUE(s.isOk()) << s.message();
  EXPECT_EQ(writtenTo, this->path("shot.partial.png"));
  EXPECT_EQ(seenDuringWrite, "old");
  EXPECT_EQ(read(path), "first half second half");
  EXPECT_EQ(entries(), "shot.png;");  // no partial file left
}

TEST_F(StagedWrite, AFailedWriteLeavesTheOldFileAndNoPartialFileAndSaysTheFinalNameWasNotWritten) {
  const std::string path = this->path("frame.svg");
  put(path, "old picture");
  const Status s = writeStaged(path, "test", [&](const std::string& to) {
    put(to, "<svg cut sh");  // a disk that filled up half way
    return Status::error("cannot write SVG file \"" + to + "\": No space left on device");
  });
  ASSERT_FALSE(s.isOk());
  EXPECT_NE(s.message().find("No space left on device"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("\"" + path + "\" was not written"), std::string::npos) << s.message();
  EXPECT_EQ(read(path), "old picture");
  EXPECT_EQ(entries(), "frame.svg;");
}

TEST_F(StagedWrite, AFirstFileAppearsOnlyWhenWhole) {
  const std::string path = this->path("new.svg");
  bool existedDuringWrite = true;
  ASSERT_TRUE(writeStaged(path, "test", [&](const std::string& to) {
                put(to, "<svg/>");
                existedDuringWrite = fs::exists(path);
                return Status::ok();
              }).isOk());
  EXPECT_FALSE(existedDuringWrite);
  EXPECT_EQ(read(path), "<svg/>");
}

TEST_F(StagedWrite, ALinkKeepsPointingAtTheNewFile) {
  const std::string target = path("target.png"), link = path("link.png");
  put(target, "old");
  fs::create_symlink(target, link);
  ASSERT_TRUE(writeStaged(link, "test", [&](const std::string& to) {
                put(to, "new");
                return Status::ok();
              }).isOk());
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(read(target), "new");
}

TEST_F(StagedWrite, ADeviceIsWrittenDirectly) {
  std::string writtenTo;
  ASSERT_TRUE(writeStaged("/dev/null", "test", [&](const std::string& to) {
                writtenTo = to;
                return Status::ok();
              }).isOk());
  EXPECT_EQ(writtenTo, "/dev/null");
}

TEST_F(StagedWrite, AStalePartialFileOfAnEarlierCrashIsReplaced) {
  const std::string path = this->path("shot.png");
  put(this->path("shot.partial.png"), "left by a crash, longer than the new file");
  ASSERT_TRUE(writeStaged(path, "test", [&](const std::string& to) {
                std::ofstream(to, std::ios::binary | std::ios::app) << "new";  // appends: sees a fresh file
                return Status::ok();
              }).isOk());
  EXPECT_EQ(read(path), "new");
  EXPECT_EQ(entries(), "shot.png;");
}

TEST_F(StagedWrite, AWholeFileIsWrittenAndAFailedWriteToADeviceLeavesTheDevice) {
  const std::string file = path("a.svg");
  ASSERT_TRUE(writeWholeFile(file, "<svg/>", "SVG").isOk());
  EXPECT_EQ(read(file), "<svg/>");
  // A device that refuses every write, as /dev/full does (1, 7), made here so that nothing of the
  // machine's is at stake if the writer removes it.
  const std::string full = path("full");
  if (mknod(full.c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0) GTEST_SKIP() << "mknod is not allowed here";
  const Status s = writeWholeFile(full, "<svg/>", "SVG");
  ASSERT_FALSE(s.isOk());
  EXPECT_EQ(s.message(), "cannot write SVG file \"" + full + "\": No space left on device");
  EXPECT_TRUE(fs::is_character_file(full)) << "the writer removed the device it could not write";
}

}  // namespace
}  // namespace fosssim::io
