#include "records/atomic_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "support/scratch.h"
#include "util/input_error.h"

namespace camcov::records {
namespace {

namespace fs = std::filesystem;

TEST(WriteFileAtomically, CreatesFoldersReplacesContentAndLeavesNoTemporaries) {
  const fs::path dir = fs::path(CAMCOV_TEST_TMP) / "atomic";
  fs::remove_all(dir);
  const fs::path file = dir / "sub" / "x.json";
  writeFileAtomically(file, "first");
  writeFileAtomically(file, "second");
  EXPECT_EQ(testing::readFile(file), "second");
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(file.parent_path()))
    ++entries;
  EXPECT_EQ(entries, 1);
}

TEST(CopyFileAtomically, CopiesBytesExactlyAndNamesItsTemporaryAsSuch) {
  const fs::path dir = fs::path(CAMCOV_TEST_TMP) / "atomic-copy";
  fs::remove_all(dir);
  const std::string bytes("a\0b\n\xff", 5);
  writeFileAtomically(dir / "from.csv", bytes);
  copyFileAtomically(dir / "from.csv", dir / "to" / "to.csv");
  EXPECT_EQ(testing::readFile(dir / "to" / "to.csv"), bytes);
  EXPECT_THROW(copyFileAtomically(dir / "missing.csv", dir / "x.csv"), InputError);
  EXPECT_TRUE(isTemporaryFile(dir / "run.json.tmp-1234"));
  EXPECT_FALSE(isTemporaryFile(dir / "run.json"));
  EXPECT_FALSE(isTemporaryFile(fs::path("a.tmp-dir") / "run.json")) << "the name, not the folder";
}

TEST(WriteFileAtomically, UnwritableFolderIsAnInputError) {
  EXPECT_THROW(writeFileAtomically("/proc/camcov/x.json", "x"), InputError);
}

TEST(WriteFileAtomically, FullDiskIsAnErrorAndKeepsTheOldFile) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  // Writing through a symlink to /dev/full fails with ENOSPC at write time; the rename never
  // happens, so whatever was there stays.
  const fs::path dir = fs::path(CAMCOV_TEST_TMP) / "full";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path file = dir / "x.json";
  writeFileAtomically(file, "old");
  const fs::path temporary = file.string() + ".tmp-" + std::to_string(::getpid());
  fs::create_symlink("/dev/full", temporary);
  EXPECT_THROW(writeFileAtomically(file, std::string(1 << 16, 'x')), std::runtime_error);
  EXPECT_EQ(testing::readFile(file), "old");
  EXPECT_FALSE(fs::exists(fs::symlink_status(temporary)));
}

}  // namespace
}  // namespace camcov::records
