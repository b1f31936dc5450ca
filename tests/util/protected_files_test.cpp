// Which files a command refuses to write: those it read as inputs, by identity, not by path.
#include "util/protected_files.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "support/scratch.h"

namespace camcov {
namespace {

namespace fs = std::filesystem;

ino_t inodeOf(const fs::path& file) {
  struct stat s {};
  return ::stat(file.c_str(), &s) == 0 ? s.st_ino : 0;
}

TEST(ProtectedFiles, AnInputIsProtectedUnderAnyPathAndALinkToIt) {
  const testing::ScratchDir dir;
  std::ofstream(dir / "input.json") << "{}";
  fs::create_symlink(dir / "input.json", dir / "link.json");
  std::ofstream(dir / "other.json") << "{}";
  ProtectedFiles::protect(dir / "input.json");
  EXPECT_TRUE(ProtectedFiles::isProtected(dir / "input.json"));
  EXPECT_TRUE(ProtectedFiles::isProtected(dir.path() / "." / "input.json"));
  EXPECT_TRUE(ProtectedFiles::isProtected(dir / "link.json"));
  EXPECT_FALSE(ProtectedFiles::isProtected(dir / "other.json"));
  EXPECT_FALSE(ProtectedFiles::isProtected(dir / "missing.json"));
}

// A long-lived process (a Python session, a test program) reads an input, which is deleted;
// the file system soon gives its inode to a new file, which is not that input.
TEST(ProtectedFiles, ANewFileGivenTheInodeOfADeletedInputIsNotProtected) {
  const testing::ScratchDir dir;
  const fs::path input = dir / "input.json";
  std::ofstream(input) << "{}";
  const ino_t inode = inodeOf(input);
  ProtectedFiles::protect(input);
  fs::remove(input);
  // Files are made until one is given the freed inode (ext4 and tmpfs give it at once).
  for (int i = 0; i < 64; ++i) {
    const fs::path made = dir / ("made" + std::to_string(i));
    std::ofstream(made) << "{}";
    if (inodeOf(made) != inode) continue;
    struct statx s {};
    ASSERT_EQ(::statx(AT_FDCWD, made.c_str(), 0, STATX_BTIME, &s), 0);
    if ((s.stx_mask & STATX_BTIME) == 0)
      GTEST_SKIP() << "this file system keeps no birth times; inodes alone tell files apart";
    EXPECT_FALSE(ProtectedFiles::isProtected(made));
    return;
  }
  GTEST_SKIP() << "the file system gave the freed inode to none of 64 new files";
}

}  // namespace
}  // namespace camcov
