// `camcov bench` and `camcov merge` end to end: outputs, resume after SIGKILL, shards plus
// merge equal to one process, parameter guard, and OMPL's own tools reading our logs.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

// 2 scenes x 2 methods x 3 seeds = 12 short jobs; without videos unless a test asks.
std::string benchArgs(const fs::path& out, int seeds = 3, const std::string& videos = "none") {
  return "bench --scenes " + (testDataDir() / "scenes").string() + " --seeds " +
         std::to_string(seeds) + " --duration 2 --set global.K=30 --set planner.T2=0.05 --videos " +
         videos + " --out " + out.string();
}

std::set<std::string> runFiles(const fs::path& out) {
  std::set<std::string> names;
  if (!fs::exists(out / "runs")) return names;
  for (const auto& e : fs::directory_iterator(out / "runs"))
    names.insert(e.path().filename().string());
  return names;
}

TEST(CliBench, WritesRunsSummaryAndLogs) {
  const fs::path out = freshDir("plain");
  const auto r = runCamcov(benchArgs(out) + " --jobs 2");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_EQ(runFiles(out).size(), 36u) << "2 scenes x 3 methods x 3 seeds, JSON and CSV each";
  const auto summary = nlohmann::json::parse(readFile(out / "summary.json"));
  EXPECT_EQ(summary["methods"].size(), 6u);
  EXPECT_EQ(summary["scenes"].size(), 2u);
  EXPECT_EQ(summary["methods"][0]["runs"], 3);
  EXPECT_TRUE(fs::exists(out / "summary.csv"));
  EXPECT_TRUE(fs::exists(out / "ompl" / "tiny_static.log"));
  EXPECT_TRUE(fs::exists(out / "batch.json"));
  EXPECT_NE(r.out.find("tiny_dynamic"), std::string::npos) << "the table names each scene";
}

TEST(CliBench, SearchesTheOptimumOfScenesThatHoldStillOnceAndTheReportSetsRunsAgainstIt) {
  const fs::path out = freshDir("optimum");
  const auto first = runCamcov(benchArgs(out, 2) + " --optimum-budget 5000");
  ASSERT_EQ(first.exitCode, 0) << first.out << first.err;
  EXPECT_TRUE(fs::exists(out / "optimum" / "tiny_static.json"));
  EXPECT_FALSE(fs::exists(out / "optimum" / "tiny_dynamic.json")) << "its targets move";
  const auto optimum = nlohmann::json::parse(readFile(out / "optimum" / "tiny_static.json"));
  EXPECT_EQ(optimum["budget"], 5000);
  EXPECT_NE(first.out.find("wrote 1 offline optimum in "), std::string::npos) << first.out;
  EXPECT_NE(first.out.find("camcov against paper: wins"), std::string::npos) << first.out;
  const std::string report = readFile(out / "report.html");
  EXPECT_NE(report.find("id=\"optimum\""), std::string::npos);
  EXPECT_NE(report.find("id=\"pairs\""), std::string::npos);

  const auto again = runCamcov(benchArgs(out, 2) + " --optimum-budget 5000");
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_NE(again.out.find("wrote 0 offline optima in " + out.string() + "/optimum (1 up to date)"),
            std::string::npos)
      << again.out;
  EXPECT_EQ(readFile(out / "optimum" / "tiny_static.json"), optimum.dump(1) + "\n");

  const fs::path none = freshDir("no-optimum");
  ASSERT_EQ(runCamcov(benchArgs(none, 1) + " --optimum-budget 0").exitCode, 0);
  EXPECT_FALSE(fs::exists(none / "optimum"));
  EXPECT_EQ(readFile(none / "report.html").find("id=\"optimum\""), std::string::npos);
}

std::set<std::string> videoFiles(const fs::path& out) {
  std::set<std::string> names;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(out / "videos", ec))
    names.insert(e.path().filename().string());
  return names;
}

// The median-seed run per (scene, method), found from the runs' own results files: order by
// (average coverage, seed), take the lower middle one.
std::set<std::string> medianRunVideos(const fs::path& out) {
  std::map<std::string, std::vector<std::pair<double, int>>> byGroup;
  for (const auto& name : runFiles(out)) {
    if (fs::path(name).extension() != ".json") continue;
    const auto run = nlohmann::json::parse(readFile(out / "runs" / name));
    byGroup[run["scene"]["name"].get<std::string>() + "-" + run["method"].get<std::string>()]
        .push_back({run["summary"]["averageCoverage"].get<double>(), run["seed"].get<int>()});
  }
  std::set<std::string> names;
  for (auto& [group, runs] : byGroup) {
    std::sort(runs.begin(), runs.end());
    names.insert(group + "-seed" + std::to_string(runs[(runs.size() - 1) / 2].second) + ".mp4");
  }
  return names;
}

TEST(CliBench, VideosShowTheMedianSeedRunOfEachMethodAndAreNotMadeTwice) {
  const fs::path out = freshDir("videos");
  const auto first = runCamcov(benchArgs(out, 3, "median") + " --jobs 2");
  ASSERT_EQ(first.exitCode, 0) << first.out << first.err;
  const std::set<std::string> expected = medianRunVideos(out);
  ASSERT_EQ(expected.size(), 6u) << "2 scenes x 3 methods";
  EXPECT_EQ(videoFiles(out), expected);
  const std::string report = readFile(out / "report.html");
  for (const auto& name : expected) {
    EXPECT_NE(report.find("src=\"videos/" + name + "\""), std::string::npos) << name;
    EXPECT_EQ(readFile(out / "videos" / name).substr(4, 4), "ftyp") << name << " is an MP4";
  }

  const auto before = fs::last_write_time(out / "videos" / *expected.begin());
  const auto again = runCamcov(benchArgs(out, 3, "median") + " --jobs 2");
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_NE(again.out.find("wrote 0 videos"), std::string::npos) << again.out;
  EXPECT_EQ(fs::last_write_time(out / "videos" / *expected.begin()), before);
}

TEST(CliBench, NotesAndResultsKeepTheOrderTheyWereSaidInOnOnePipe) {
  // Results go to stdout, notes to stderr; `2>&1 | cat` merges them into one pipe, where a
  // block-buffered stdout would hold every result back until exit.
  const fs::path out = freshDir("one_pipe");
  const auto r = runCamcov(benchArgs(out, 1, "median") + " --explorer none --jobs 1 2>&1 | cat");
  ASSERT_EQ(r.exitCode, 0) << r.out;
  const auto summary = r.out.find("wrote " + (out / "summary.json").string());  // a result
  const auto videos = r.out.find("videos: 6 to write");                         // then a note
  const auto written = r.out.find("wrote 6 videos");                            // then a result
  ASSERT_NE(summary, std::string::npos) << r.out;
  ASSERT_NE(videos, std::string::npos) << r.out;
  ASSERT_NE(written, std::string::npos) << r.out;
  EXPECT_LT(summary, videos) << r.out;
  EXPECT_LT(videos, written) << r.out;
}

TEST(CliBench, VideosNoneWritesNoVideosAndAllWritesOnePerRun) {
  const fs::path none = freshDir("videos_none");
  ASSERT_EQ(runCamcov(benchArgs(none, 2, "none")).exitCode, 0);
  EXPECT_FALSE(fs::exists(none / "videos"));
  const fs::path all = freshDir("videos_all");
  ASSERT_EQ(runCamcov(benchArgs(all, 2, "all") + " --methods local").exitCode, 0);
  EXPECT_EQ(videoFiles(all),
            (std::set<std::string>{"tiny_dynamic-local-seed1.mp4", "tiny_dynamic-local-seed2.mp4",
                                   "tiny_static-local-seed1.mp4", "tiny_static-local-seed2.mp4"}));
}

TEST(CliBench, KilledBatchResumesWithoutRedoingFinishedJobs) {
  const fs::path reference = freshDir("uninterrupted"), out = freshDir("killed");
  ASSERT_EQ(runCamcov(benchArgs(reference) + " --jobs 1").exitCode, 0);

  // Start the batch, wait until two jobs have finished, then SIGKILL it.
  const std::string start =
      camcovBinary() + " " + benchArgs(out) + " --jobs 1 >/dev/null 2>&1 & pid=$!; " +
      "while [ $(ls " + (out / "runs").string() +
      "/*.json 2>/dev/null | wc -l) -lt 2 ]; do sleep 0.02; done; kill -9 $pid; wait $pid";
  runShell(start);
  const auto before = runFiles(out);
  std::map<std::string, fs::file_time_type> stamps;
  for (const auto& name : before)
    stamps[name] = fs::last_write_time(out / "runs" / name);
  ASSERT_GE(before.size(), 2u);

  const auto r = runCamcov(benchArgs(out) + " --jobs 1");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("already done"), std::string::npos) << r.err;
  // A job is finished once its JSON exists (its CSV is written first); those are kept.
  int kept = 0;
  for (const auto& [name, stamp] : stamps) {
    const fs::path json = out / "runs" / (fs::path(name).stem().string() + ".json");
    if (name.find(".tmp-") != std::string::npos || !before.contains(json.filename().string()))
      continue;
    EXPECT_EQ(fs::last_write_time(out / "runs" / name), stamp) << name << " was redone";
    ++kept;
  }
  EXPECT_GE(kept, 4) << "at least two finished jobs, JSON and CSV each";
  for (const auto& name : runFiles(out))
    EXPECT_EQ(name.find(".tmp-"), std::string::npos) << name;
  EXPECT_EQ(readFile(out / "summary.json"), readFile(reference / "summary.json"));
  EXPECT_EQ(readFile(out / "summary.csv"), readFile(reference / "summary.csv"));
}

TEST(CliBench, ShardsPlusMergeEqualOneProcess) {
  const fs::path one = freshDir("one"), base = freshDir("shards");
  ASSERT_EQ(runCamcov(benchArgs(one) + " --jobs 2").exitCode, 0);
  // Three shard processes side by side, as GNU parallel or a job array would start them.
  const auto r = runShell("printf '1\\n2\\n3\\n' | xargs -P 3 -I @ " + camcovBinary() + " " +
                          benchArgs(base / "shard@") + " --jobs 1 --shard @/3 >/dev/null");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_FALSE(fs::exists(base / "shard1" / "summary.json")) << "a shard alone is not the batch";
  const auto merged =
      runCamcov("merge " + (base / "shard1").string() + " " + (base / "shard2").string() + " " +
                (base / "shard3").string() + " --out " + (base / "merged").string());
  ASSERT_EQ(merged.exitCode, 0) << merged.err;
  EXPECT_EQ(readFile(base / "merged" / "summary.json"), readFile(one / "summary.json"));
  EXPECT_EQ(readFile(base / "merged" / "summary.csv"), readFile(one / "summary.csv"));
  // And every run file, byte for byte, whatever process made it.
  for (const auto& name : runFiles(one)) {
    EXPECT_EQ(readFile(base / "merged" / "runs" / name), readFile(one / "runs" / name)) << name;
  }
}

TEST(CliBench, SlurmArrayRecipeShardsAndMerges) {
  // scripts/slurm_bench.sh as Slurm would start it: one task per shard, environment set; then
  // task 2 resubmitted alone (an array of one), which must run shard 2 of 3 again, not the
  // whole batch. tests/cluster does the same on a real Slurm cluster.
  const fs::path one = freshDir("slurm_one"), base = freshDir("slurm");
  ASSERT_EQ(runCamcov(benchArgs(one, 2)).exitCode, 0);
  const std::string script = std::string(CAMCOV_SOURCE_DIR) + "/scripts/slurm_bench.sh";
  const std::string options = benchArgs(base, 2).substr(std::string("bench").size());
  const std::string optionsWithoutOut = options.substr(0, options.find(" --out "));
  const auto task = [&](int id, int count) {
    return runShell("CAMCOV=" + camcovBinary() + " SLURM_ARRAY_TASK_ID=" + std::to_string(id) +
                    " SLURM_ARRAY_TASK_COUNT=" + std::to_string(count) + " SLURM_CPUS_PER_TASK=1 " +
                    script + " " + base.string() + optionsWithoutOut);
  };
  for (int id = 1; id <= 3; ++id) {
    const auto r = task(id, 3);
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  }
  const auto again = task(2, 1);
  ASSERT_EQ(again.exitCode, 0) << again.out << again.err;
  EXPECT_NE(again.out.find("shard 2/3 done"), std::string::npos) << again.out;
  EXPECT_FALSE(fs::exists(base / "shard-1" / "runs" / "tiny_static-paper-seed1.json") &&
               fs::exists(base / "shard-2" / "runs" / "tiny_static-paper-seed1.json"))
      << "a run belongs to one shard";
  const auto wrongSize = task(1, 5);
  EXPECT_EQ(wrongSize.exitCode, 2) << "the same folder as another number of shards";
  const auto merged =
      runCamcov("merge " + (base / "shard-1").string() + " " + (base / "shard-2").string() + " " +
                (base / "shard-3").string() + " --out " + (base / "merged").string());
  ASSERT_EQ(merged.exitCode, 0) << merged.err;
  EXPECT_EQ(readFile(base / "merged" / "summary.json"), readFile(one / "summary.json"));
}

TEST(CliBench, RefusesOtherParametersInTheSameFolderUnlessForced) {
  const fs::path out = freshDir("guard");
  ASSERT_EQ(runCamcov(benchArgs(out, 1)).exitCode, 0);
  const auto refused = runCamcov(benchArgs(out, 1) + " --set local.alpha=0.25");
  EXPECT_EQ(refused.exitCode, 2);
  EXPECT_NE(refused.err.find("--force"), std::string::npos) << refused.err;
  EXPECT_EQ(runCamcov(benchArgs(out, 1) + " --set local.alpha=0.25 --force").exitCode, 0);
}

TEST(CliBench, BadArgumentsExitTwoBeforeRunningAnything) {
  const fs::path out = freshDir("bad");
  EXPECT_EQ(runCamcov("bench --scenes /nonexistent --out " + out.string()).exitCode, 2);
  EXPECT_EQ(runCamcov(benchArgs(out) + " --methods paper,magic").exitCode, 2);
  EXPECT_EQ(runCamcov(benchArgs(out) + " --shard 4/3").exitCode, 2);
  EXPECT_EQ(runCamcov(benchArgs(out, 3, "sometimes")).exitCode, 2);
  EXPECT_EQ(runCamcov(benchArgs(out, 0)).exitCode, 2);
  const auto badScene =
      runCamcov("bench --scenes " + (testDataDir() / "bad" / "no_cameras.json").string() +
                " --out " + out.string());
  EXPECT_EQ(badScene.exitCode, 2);
  EXPECT_FALSE(fs::exists(out / "runs"));
}

TEST(CliBench, OmplBenchmarkStatisticsReadsOurLogs) {
  const fs::path out = freshDir("ompl");
  ASSERT_EQ(runCamcov(benchArgs(out, 2)).exitCode, 0);
  const fs::path db = out / "benchmark.db";
  const auto r =
      runShell("ompl_benchmark_statistics " + (out / "ompl" / "tiny_static.log").string() + " " +
               (out / "ompl" / "tiny_dynamic.log").string() + " -d " + db.string());
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  // 2 scenes x 3 methods x 2 seeds runs, 21 progress samples each.
  const auto count = runShell("python3 -c \"import sqlite3; c = sqlite3.connect('" + db.string() +
                              "'); print(c.execute('select count(*) from runs').fetchone()[0], "
                              "c.execute('select count(*) from progress').fetchone()[0], "
                              "c.execute('select count(*) from plannerConfigs').fetchone()[0])\"");
  EXPECT_EQ(count.out, "12 252 3\n") << count.err;
}

// A --set with a list of values makes a study: one batch per setting in OUT/<key=value>, and
// the settings side by side in OUT/report.html with coverage against the value; a list that
// cannot be meant writes nothing.
TEST(CliBench, AListOfValuesRunsOneBatchPerSettingAndReportsThemSideBySide) {
  const ScratchDir dir;
  const fs::path out = dir / "study";
  const auto r = runCamcov(benchArgs(out, 1) + " --methods local --set global.T1=1,2,5");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const auto& [setting, t1] : {std::pair{"global.T1=1", 1.0}, std::pair{"global.T1=2", 2.0},
                                    std::pair{"global.T1=5", 5.0}}) {
    ASSERT_TRUE(fs::exists(out / setting / "summary.json")) << setting;
    const auto batch = nlohmann::json::parse(readFile(out / setting / "batch.json"));
    EXPECT_EQ(batch["parameters"]["global"]["T1"].get<double>(), t1) << setting;
    EXPECT_EQ(batch["parameters"]["planner"]["T2"].get<double>(), 0.05) << "the single --set too";
  }
  const std::string report = readFile(out / "report.html");
  EXPECT_NE(report.find("data-figure=\"settings-trend\" data-order=\"1,2,5\""), std::string::npos);
  // Run again: every setting resumes with nothing left.
  const auto again = runCamcov(benchArgs(out, 1) + " --methods local --set global.T1=1,2,5");
  EXPECT_EQ(again.exitCode, 0) << again.err;
  for (const std::string bad : {"global.T1=1,,5", "global.T1=1,x"}) {
    const auto refused = runCamcov(benchArgs(dir / "bad", 1) + " --set " + bad);
    EXPECT_EQ(refused.exitCode, 2) << bad << refused.err;
    EXPECT_FALSE(fs::exists(dir / "bad")) << bad;
  }
}

}  // namespace
}  // namespace camcov::testing
