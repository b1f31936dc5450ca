// The bench stage (src/bench/run_bench.h) prints nothing: everything it has to say reaches its
// observer, in order — the plan, one item per job in a stretch, the summary table, the videos'
// own stretch, what was written — and a merge of its folder says the same table. (Beside the
// batch's tests: tests/bench holds the benchmark programs.)
#include <gtest/gtest.h>

#include <algorithm>
#include <mutex>

#include "bench/run_bench.h"
#include "support/scratch.h"
#include "support/test_paths.h"
#include "util/input_error.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

struct Said {
  std::vector<std::string> notes, reports, items;
  std::vector<std::pair<std::size_t, std::size_t>> stretches;
  int stretchesDone = 0;
};

class RecordingObserver final : public bench::BenchObserver {
 public:
  void note(const std::string& line) override {
    with([&](Said& s) { s.notes.push_back(line); });
  }
  void report(const std::string& line) override {
    with([&](Said& s) { s.reports.push_back(line); });
  }
  void stretchStarted(std::size_t total, std::size_t done) override {
    with([&](Said& s) { s.stretches.emplace_back(total, done); });
  }
  void itemFinished(const std::string& what) override {
    with([&](Said& s) { s.items.push_back(what); });
  }
  void stretchDone() override {
    with([&](Said& s) { ++s.stretchesDone; });
  }
  Said said;

 private:
  template <class F>
  void with(F f) {
    const std::lock_guard lock(mutex_);
    f(said);
  }
  std::mutex mutex_;
};

bool anyStartsWith(const std::vector<std::string>& lines, const std::string& start) {
  return std::any_of(lines.begin(), lines.end(),
                     [&](const std::string& l) { return l.rfind(start, 0) == 0; });
}

bench::BenchRequest tinyRequest(const fs::path& out) {
  bench::BenchRequest request;
  request.scenes = {(testDataDir() / "scenes" / "tiny_dynamic.json").string()};
  request.methods = {"local", "paper"};  // the table's own (the examples are not linked here)
  request.seeds = 2;
  request.duration = 2.0;
  request.jobs = 1;
  request.out = out.string();
  request.outputs.explorer = "none";
  return request;
}

TEST(RunBench, ListsMethodsInTheOneOrderOfMethodsWhateverOrderTheyWereAskedIn) {
  const ScratchDir dir;
  RecordingObserver observer;
  bench::BenchRequest request = tinyRequest(dir / "b");  // local, then paper
  request.seeds = 1;
  request.outputs.videos = "none";
  const bench::BenchResult result = bench::runBench(request, observer);
  const auto& lines = observer.said.reports;
  const auto header = std::find_if(lines.begin(), lines.end(), [](const std::string& l) {
    return l.rfind("scene (average coverage)", 0) == 0;
  });
  ASSERT_NE(header, lines.end());
  EXPECT_LT(header->find(" paper"), header->find(" local")) << *header;
  ASSERT_EQ(result.summary.methods.size(), 2u);
  EXPECT_EQ(result.summary.methods[0].method, "paper") << "the paper's method leads";
  EXPECT_EQ(result.summary.methods[1].method, "local");
}

TEST(RunBench, PrintsNothingAndSaysEverythingToItsObserverInOrder) {
  const ScratchDir dir;
  RecordingObserver observer;
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  const bench::BenchResult result = bench::runBench(tinyRequest(dir / "b"), observer);
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  const Said& s = observer.said;
  EXPECT_EQ(result.jobs, 4u);
  EXPECT_EQ(result.failedJobs, 0u);
  EXPECT_FALSE(result.shard);
  EXPECT_EQ(result.summary.scenes, std::vector<std::string>{"tiny_dynamic"});
  ASSERT_FALSE(s.notes.empty());
  EXPECT_EQ(s.notes.front().rfind("camcov bench: 1 scene x 2 methods x 2 seeds = 4 jobs", 0), 0u)
      << s.notes.front();
  // The jobs' stretch (4, none from before), then the videos' (the median seed of 2 methods).
  ASSERT_EQ(s.stretches.size(), 2u);
  EXPECT_EQ(s.stretches[0], (std::pair<std::size_t, std::size_t>{4, 0}));
  EXPECT_EQ(s.stretches[1], (std::pair<std::size_t, std::size_t>{2, 0}));
  EXPECT_EQ(s.stretchesDone, 2);
  ASSERT_EQ(s.items.size(), 6u);
  EXPECT_EQ(s.items[0].rfind("tiny_dynamic-local-seed1: coverage ", 0), 0u) << s.items[0];
  EXPECT_EQ(s.items[4].rfind("videos/", 0), 0u) << s.items[4];
  EXPECT_TRUE(anyStartsWith(s.reports, "scene (average coverage)"));
  EXPECT_TRUE(anyStartsWith(s.reports, "0 failed jobs"));
  EXPECT_TRUE(anyStartsWith(s.reports, "wrote 2 videos"));
  EXPECT_EQ(s.reports.back(), "wrote " + (dir / "b" / "report.html").string());
  EXPECT_TRUE(fs::exists(dir / "b" / "summary.json"));

  // Run again: every job is reused, and the observer is told so before the stretch.
  RecordingObserver again;
  bench::runBench(tinyRequest(dir / "b"), again);
  EXPECT_TRUE(anyStartsWith(again.said.notes, "4 of 4 jobs already done in "));
  EXPECT_EQ(again.said.stretches.front(), (std::pair<std::size_t, std::size_t>{4, 4}));

  // A merge of the folder into another says the same table.
  RecordingObserver merged;
  bench::BenchOutputOptions none;
  none.videos = none.explorer = "none";
  none.noReport = true;
  const bench::BenchResult m =
      bench::mergeBench({(dir / "b").string()}, (dir / "m").string(), none, {"test"}, merged);
  EXPECT_EQ(m.jobs, 4u);
  const auto table = [](const std::vector<std::string>& lines) {
    return std::vector<std::string>(
        lines.begin(), std::find(lines.begin(), lines.end(), std::string("0 failed jobs")));
  };
  EXPECT_EQ(table(merged.said.reports), table(s.reports));
}

TEST(RunBench, ABadRequestIsRefusedBeforeAnyFolderIsMade) {
  const ScratchDir dir;
  RecordingObserver observer;
  bench::BenchRequest request = tinyRequest(dir / "never");
  request.outputs.videos = "some";
  EXPECT_THROW(bench::runBench(request, observer), InputError);
  request = tinyRequest(dir / "never");
  request.shard = "3/2";
  EXPECT_THROW(bench::runBench(request, observer), InputError);
  request = tinyRequest(dir / "never");
  request.outputs.reference = "camcov";  // not among the methods
  EXPECT_THROW(bench::runBench(request, observer), InputError);
  EXPECT_FALSE(fs::exists(dir / "never"));
  EXPECT_TRUE(observer.said.notes.empty());
}

}  // namespace
}  // namespace camcov::testing
