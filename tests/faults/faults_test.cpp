// Faults end to end through the camcov binary: an --out that cannot be written (a path through
// a file, a read-only file system), a disk that fills up in the middle of a batch, and a scene
// that breaks while its batch runs. Each must end in a clear error, leave no half-written or
// temporary file behind, and, in a batch, not stop the other jobs.
//
// The file-system cases mount small tmpfs folders, which needs root (CAP_SYS_ADMIN); without
// it they are skipped with the reason.
#include <gtest/gtest.h>
#include <sys/mount.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

const std::string kShortRun = " --duration 2 --set global.K=30 --set planner.T2=0.05";

fs::path tinyStatic() {
  return testDataDir() / "scenes" / "tiny_static.json";
}

// Every file under `dir`: no temporary left over, and every JSON file parses whole.
void expectNoPartialFiles(const fs::path& dir) {
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    EXPECT_EQ(name.find(".tmp-"), std::string::npos) << entry.path();
    if (entry.is_regular_file() && entry.path().extension() == ".json") {
      EXPECT_TRUE(nlohmann::json::accept(readFile(entry.path()))) << entry.path();
    }
  }
}

// A tmpfs mounted for one test and unmounted when it ends.
class TmpfsMount {
 public:
  TmpfsMount(fs::path dir, const std::string& options) : dir_(std::move(dir)) {
    fs::create_directories(dir_);
    if (::mount("tmpfs", dir_.c_str(), "tmpfs", 0, options.c_str()) != 0) {
      error_ = std::strerror(errno);
    }
  }
  ~TmpfsMount() {
    if (error_.empty()) ::umount2(dir_.c_str(), MNT_DETACH);
  }
  TmpfsMount(const TmpfsMount&) = delete;
  TmpfsMount& operator=(const TmpfsMount&) = delete;

  // Empty when mounted, else why not.
  const std::string& error() const { return error_; }
  bool remount(const std::string& options, unsigned long flags = 0) {
    return ::mount("tmpfs", dir_.c_str(), "tmpfs", MS_REMOUNT | flags, options.c_str()) == 0;
  }

 private:
  fs::path dir_;
  std::string error_;
};

#define CAMCOV_REQUIRE_MOUNT(mount) \
  if (!(mount).error().empty())     \
  GTEST_SKIP() << "cannot mount a tmpfs (needs root): " << (mount).error()

// Writes zeros until the file system refuses: the disk is then full.
void fillUp(const fs::path& file) {
  std::ofstream out(file, std::ios::binary);
  const std::string block(4096, '\0');
  while (out.write(block.data(), static_cast<std::streamsize>(block.size())) && out.flush()) {
  }
}

TEST(Faults, RunIntoAnOutPathThroughAFileFailsWithExitTwoAndWritesNothing) {
  const fs::path dir = freshDir("through_file");
  std::ofstream(dir / "plain_file") << "not a folder";
  const fs::path out = dir / "plain_file" / "results";
  const auto r = runCamcov("run " + tinyStatic().string() + kShortRun + " --out " + out.string());
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("error: cannot create folder " + out.string()), std::string::npos) << r.err;
  EXPECT_EQ(readFile(dir / "plain_file"), "not a folder");
}

TEST(Faults, RunAndBenchIntoAReadOnlyFileSystemFailWithExitTwoAndWriteNothing) {
  const fs::path dir = freshDir("read_only");
  TmpfsMount mount(dir, "size=1m");
  CAMCOV_REQUIRE_MOUNT(mount);
  fs::create_directories(dir / "out");
  ASSERT_TRUE(mount.remount("size=1m", MS_RDONLY)) << std::strerror(errno);

  const auto run =
      runCamcov("run " + tinyStatic().string() + kShortRun + " --out " + (dir / "out").string());
  EXPECT_EQ(run.exitCode, 2) << run.err;
  EXPECT_NE(run.err.find("Read-only file system"), std::string::npos) << run.err;

  const auto bench = runCamcov("bench --scenes " + tinyStatic().string() + " --seeds 1" +
                               kShortRun + " --out " + (dir / "out").string());
  EXPECT_EQ(bench.exitCode, 2) << bench.err;
  EXPECT_NE(bench.err.find("Read-only file system"), std::string::npos) << bench.err;
  EXPECT_TRUE(fs::is_empty(dir / "out"));
}

TEST(Faults, RunOnAFullDiskFailsClearlyAndKeepsThePreviousResults) {
  const fs::path dir = freshDir("full_run");
  const TmpfsMount mount(dir, "size=256k");
  CAMCOV_REQUIRE_MOUNT(mount);
  const std::string run =
      "run " + tinyStatic().string() + " --method local" + kShortRun + " --out " + dir.string();
  ASSERT_EQ(runCamcov(run).exitCode, 0);
  const fs::path json = dir / "tiny_static-local-seed1.json";
  const std::string before = readFile(json);

  fillUp(dir / "filler");
  const auto full = runCamcov(run);
  EXPECT_NE(full.exitCode, 0);
  EXPECT_NE(full.err.find("No space left on device"), std::string::npos) << full.err;
  EXPECT_EQ(readFile(json), before) << "the results of the earlier run are intact";
  expectNoPartialFiles(dir);
}

TEST(Faults, BenchOnADiskThatFillsUpKeepsWholeFilesAndResumesOnceThereIsRoom) {
  const fs::path dir = freshDir("full_bench");
  const fs::path reference = freshDir("full_bench_reference");
  TmpfsMount mount(dir, "size=96k");
  CAMCOV_REQUIRE_MOUNT(mount);
  // 2 scenes x 2 methods x 2 seeds: about 25 kB per job, so the disk fills a few jobs in.
  const std::string bench = "bench --scenes " + (testDataDir() / "scenes").string() +
                            " --seeds 2 --jobs 1 --no-report" + kShortRun + " --out ";
  const auto full = runCamcov(bench + dir.string());
  EXPECT_NE(full.exitCode, 0);
  EXPECT_NE(full.err.find("No space left on device"), std::string::npos) << full.err;
  expectNoPartialFiles(dir);

  ASSERT_TRUE(mount.remount("size=8m"));
  const auto resumed = runCamcov(bench + dir.string());
  ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
  ASSERT_EQ(runCamcov(bench + reference.string()).exitCode, 0);
  EXPECT_EQ(readFile(dir / "summary.json"), readFile(reference / "summary.json"));
  expectNoPartialFiles(dir);
}

TEST(Faults, SceneThatBreaksMidBatchIsRecordedAsFailedAndTheOtherJobsFinish) {
  // Two scenes, run in name order by one worker. Every scene is validated before the batch
  // writes batch.json; once that file appears, the second scene's file is overwritten with
  // garbage, as an edit during a long batch would. Its jobs, which run after all four of the
  // first scene's (long runs of the cheap local method: about a second in all), must fail, be
  // recorded, and not stop the others.
  const fs::path dir = freshDir("breaks");
  fs::create_directories(dir / "scenes");
  fs::copy_file(tinyStatic(), dir / "scenes" / "a_good.json");
  fs::copy_file(testDataDir() / "scenes" / "tiny_dynamic.json", dir / "scenes" / "b_breaks.json");
  const fs::path out = dir / "out";
  const std::string bench = camcovBinary() + " bench --scenes " + (dir / "scenes").string() +
                            " --methods local --seeds 4 --jobs 1 --duration 300 --out " +
                            out.string();
  const auto r =
      runShell(bench + " > " + (dir / "stdout.txt").string() + " & pid=$!; " + "until [ -e " +
               (out / "batch.json").string() + " ]; do sleep 0.005; done; echo '{ broken' > " +
               (dir / "scenes" / "b_breaks.json").string() + "; wait $pid");
  const std::string stdoutText = readFile(dir / "stdout.txt");
  EXPECT_EQ(r.exitCode, 1) << "a batch with failed jobs exits 1\n" << r.err;

  for (int seed = 1; seed <= 4; ++seed) {
    const std::string s = std::to_string(seed);
    EXPECT_TRUE(fs::exists(out / "runs" / ("a_good-local-seed" + s + ".json"))) << seed;
    const fs::path error = out / "runs" / ("b_breaks-local-seed" + s + ".error.json");
    ASSERT_TRUE(fs::exists(error)) << seed;
    const auto j = nlohmann::json::parse(readFile(error));
    EXPECT_NE(j["error"].get<std::string>().find("b_breaks.json: (top level): invalid JSON"),
              std::string::npos)
        << j["error"];
  }
  const auto summary = nlohmann::json::parse(readFile(out / "summary.json"));
  ASSERT_EQ(summary["failures"].size(), 4u);
  EXPECT_EQ(summary["failures"][0]["scene"], "b_breaks");
  EXPECT_NE(stdoutText.find("4 failed jobs"), std::string::npos) << stdoutText;
  EXPECT_NE(stdoutText.find("failed: b_breaks local seed 1"), std::string::npos) << stdoutText;
  const std::string report = readFile(out / "report.html");
  EXPECT_NE(report.find("Failed jobs (4)"), std::string::npos);
  EXPECT_NE(report.find("invalid JSON"), std::string::npos);
  expectNoPartialFiles(out);
}

}  // namespace
}  // namespace camcov::testing
