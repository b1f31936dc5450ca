// The batch stage on its own, without the executable: planning (order, shards, bad input),
// running with resume and failures, and merging shards back into one folder.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <memory>
#include <set>

#include "batch/batch_plan.h"
#include "batch/merge.h"
#include "batch/run_job.h"
#include "control/methods.h"
#include "records/run_files.h"
#include "scene/scene_families.h"
#include "scene/scene_loader.h"
#include "support/scratch.h"
#include "support/test_paths.h"
#include "util/input_error.h"
#include "util/run_threads.h"

namespace camcov::batch {
namespace {

namespace fs = std::filesystem;

BatchRequest tinyRequest(std::uint64_t seeds = 2) {
  BatchRequest r;
  r.scenes = {(testing::testDataDir() / "scenes").string()};
  r.methods = {"paper", "local"};
  r.seeds = seeds;
  r.parameters.sim.duration = 1.0;
  r.parameters.global.K = 20;
  r.parameters.planner.T2 = 0.02;
  return r;
}

// Remembers what the batch told it.
class Recorder final : public BatchObserver {
 public:
  void resuming(const Resumption& r) override {
    alreadyDone = r.alreadyDone;
    total = r.total;
  }
  void finished(const BatchJob& job, const records::JobOutcome&) override {
    ran.push_back(job.stem);
  }
  std::size_t alreadyDone = 0, total = 0;
  std::vector<std::string> ran;
};

TEST(PlanBatch, JobsRunSceneByMethodBySeedAndShardsSplitThemExactlyOnce) {
  const BatchPlan whole = planBatch(tinyRequest(), "test");
  ASSERT_EQ(whole.jobs.size(), 8u);  // 2 scenes x 2 methods x 2 seeds
  EXPECT_EQ(whole.totalJobs, 8u);
  EXPECT_EQ(whole.jobs.front().stem, "tiny_dynamic-paper-seed1");
  EXPECT_EQ(whole.jobs[1].stem, "tiny_dynamic-paper-seed2");
  EXPECT_EQ(whole.jobs[2].stem, "tiny_dynamic-local-seed1");
  EXPECT_EQ(whole.jobs.back().stem, "tiny_static-local-seed2");
  EXPECT_EQ(whole.manifest.scenes.size(), 2u);
  std::multiset<std::string> fromShards;
  for (std::size_t k = 1; k <= 3; ++k) {
    BatchRequest r = tinyRequest();
    r.shard = parseShard(std::to_string(k) + "/3");
    const BatchPlan part = planBatch(r, "test");
    EXPECT_EQ(part.totalJobs, 8u);
    for (const auto& job : part.jobs)
      fromShards.insert(job.stem);
  }
  std::multiset<std::string> all;
  for (const auto& job : whole.jobs)
    all.insert(job.stem);
  EXPECT_EQ(fromShards, all);
}

TEST(PlanBatch, AGeneratedSceneIsGroupedByItsFamilyAnyOtherByItsFolder) {
  const fs::path dir = testing::freshDir("mixed");
  std::ofstream(dir / "drawn.json")
      << scene::generateFamilyScene(scene::sceneFamily("l_rooms"), 3).dump(1) << "\n";
  fs::copy_file(testing::testDataDir() / "scenes" / "tiny_static.json", dir / "own.json");
  BatchRequest r = tinyRequest();
  r.scenes = {dir.string(), (testing::testDataDir() / "scenes" / "tiny_dynamic.json").string()};
  const BatchPlan plan = planBatch(r, "test");
  std::map<std::string, std::string> groupOf;
  for (const auto& s : plan.manifest.scenes)
    groupOf[s.name] = s.group;
  EXPECT_EQ(groupOf, (std::map<std::string, std::string>{
                         {"drawn", "l_rooms"}, {"own", "mixed"}, {"tiny_dynamic", "scenes"}}));
}

TEST(PlanBatch, TwoFoldersOfOneNameAreToldApartByTheirParents) {
  const fs::path root = testing::freshDir("clash");
  for (const char* parent : {"x", "y"}) {
    fs::create_directories(root / parent / "scenes");
    fs::copy_file(testing::testDataDir() / "scenes" / "tiny_static.json",
                  root / parent / "scenes" / (std::string(parent) + ".json"));
  }
  BatchRequest r = tinyRequest();
  r.scenes = {(root / "x" / "scenes").string(), (root / "y" / "scenes").string(),
              (testing::testDataDir() / "scenes" / "tiny_dynamic.json").string()};
  std::map<std::string, std::string> groupOf;
  for (const auto& s : planBatch(r, "test").manifest.scenes)
    groupOf[s.name] = s.group;
  EXPECT_EQ(groupOf, (std::map<std::string, std::string>{
                         {"x", "x/scenes"}, {"y", "y/scenes"}, {"tiny_dynamic", "data/scenes"}}))
      << "three folders named scenes: each with its parent";
}

TEST(PlanBatch, BadRequestsAreInputErrors) {
  for (const char* shard : {"0/3", "4/3", "1/0", "a/b", "1/2/3", "2"})
    EXPECT_THROW(parseShard(shard), InputError) << shard;
  BatchRequest r = tinyRequest();
  r.methods = {"paper", "nope"};
  EXPECT_THROW(planBatch(r, "test"), InputError);
  r = tinyRequest(0);
  EXPECT_THROW(planBatch(r, "test"), InputError);
  r = tinyRequest();
  r.scenes = {"/no/such/folder"};
  EXPECT_THROW(planBatch(r, "test"), InputError);
}

TEST(RunBatch, ASecondRunResumesWithNothingLeftAndAFailedJobIsRecorded) {
  const testing::ScratchDir dir;
  const records::BatchFolder folder(dir / "out");
  BatchPlan plan = planBatch(tinyRequest(1), "test");
  prepareFolder(folder, plan.manifest, false);
  // One job points at a scene file that breaks, which it reads itself (handed no scene): it
  // fails alone.
  plan.jobs[1].spec.sceneFile = dir / "missing.json";
  plan.jobs[1].spec.scene = nullptr;
  Recorder first;
  const BatchRun run = runBatch(plan.jobs, folder, 2, first);
  EXPECT_EQ(first.alreadyDone, 0u);
  EXPECT_EQ(first.ran.size(), 4u);
  EXPECT_TRUE(run.outcomes[1].failed);
  EXPECT_TRUE(fs::exists(folder.errorFile(plan.jobs[1].stem)));
  EXPECT_EQ(run.timings.size(), 4u);
  for (std::size_t i : {0u, 2u, 3u}) {
    EXPECT_FALSE(run.outcomes[i].failed) << run.outcomes[i].error;
    EXPECT_TRUE(fs::exists(folder.runFile(plan.jobs[i].stem)));
  }
  Recorder second;
  const BatchRun again = runBatch(plan.jobs, folder, 2, second);
  EXPECT_EQ(second.alreadyDone, 3u) << "the finished ones are kept";
  EXPECT_EQ(second.ran, std::vector<std::string>{plan.jobs[1].stem}) << "the failed one runs again";
  EXPECT_EQ(again.outcomes[0].summary.averageCoverage, run.outcomes[0].summary.averageCoverage);
}

TEST(RunBatch, FewerJobsThanWorkersGiveEachRunTheThreadsLeftOverForTheSameFiles) {
  // The threads a run may use for its own work (util/run_threads.h), as a job finishes: one
  // job on four workers has all four, four jobs on two workers one each, and after the batch
  // the setting is as before. The run files are the same bytes.
  class Threads final : public BatchObserver {
   public:
    void resuming(const Resumption&) override {}
    void finished(const BatchJob&, const records::JobOutcome&) override {
      seen.push_back(runThreads());
    }
    std::vector<unsigned> seen;
  };
  BatchRequest request = tinyRequest(1);
  request.methods = {"camcov-dec"};
  request.parameters.knowledge.limited = true;
  request.parameters.comms.range = 10.0;
  BatchPlan plan = planBatch(request, "test");
  ASSERT_GE(plan.jobs.size(), 2u);
  const std::vector<BatchJob> one{plan.jobs.front()};
  const testing::ScratchDir dir;
  const records::BatchFolder wide(dir / "wide"), narrow(dir / "narrow");
  prepareFolder(wide, plan.manifest, false);
  prepareFolder(narrow, plan.manifest, false);
  Threads alone, shared;
  runBatch(one, wide, 4, alone);
  EXPECT_EQ(alone.seen, std::vector<unsigned>{4});
  runBatch(plan.jobs, narrow, 2, shared);
  EXPECT_EQ(shared.seen, std::vector<unsigned>(plan.jobs.size(), 1));
  EXPECT_EQ(runThreads(), 1u);
  const auto bytes = [](const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string stem = one.front().stem;
  EXPECT_EQ(bytes(wide.runFile(stem)), bytes(narrow.runFile(stem)));
}

// A batch leaves its run files for the system to write back, so a power cut may leave some
// empty or cut short after their rename; a resume must run those again, and keep the rest.
TEST(RunBatch, RunFilesAPowerCutLeftEmptyOrShortRunAgainOnAResume) {
  const testing::ScratchDir dir;
  const records::BatchFolder folder(dir / "out");
  BatchPlan plan = planBatch(tinyRequest(2), "test");
  prepareFolder(folder, plan.manifest, false);
  Recorder first;
  runBatch(plan.jobs, folder, 2, first);
  ASSERT_EQ(first.ran.size(), 8u);
  const auto csvOf = [&](std::size_t i) {
    return fs::path(folder.runFile(plan.jobs[i].stem)).replace_extension(".csv");
  };
  const auto keepFirstBytes = [](const fs::path& file, std::uintmax_t bytes) {
    fs::resize_file(file, bytes);
  };
  keepFirstBytes(folder.runFile(plan.jobs[0].stem), 0);  // the JSON empty
  keepFirstBytes(folder.runFile(plan.jobs[1].stem),
                 fs::file_size(folder.runFile(plan.jobs[1].stem)) / 2);
  keepFirstBytes(csvOf(2), 0);  // the JSON whole, its CSV empty
  // The CSV cut after a whole line: it still ends with one, but a step is missing.
  std::string csv = testing::readFile(csvOf(3));
  csv.pop_back();
  keepFirstBytes(csvOf(3), csv.rfind('\n') + 1);
  fs::remove(csvOf(4));  // the JSON renamed, the CSV's rename lost
  Recorder second;
  const BatchRun again = runBatch(plan.jobs, folder, 2, second);
  EXPECT_EQ(second.alreadyDone, 3u);
  std::set<std::string> ran(second.ran.begin(), second.ran.end());
  EXPECT_EQ(ran, (std::set<std::string>{plan.jobs[0].stem, plan.jobs[1].stem, plan.jobs[2].stem,
                                        plan.jobs[3].stem, plan.jobs[4].stem}));
  Recorder third;
  runBatch(plan.jobs, folder, 2, third);
  EXPECT_EQ(third.alreadyDone, 8u) << "the files run again are whole";
  for (const auto& outcome : again.outcomes)
    EXPECT_FALSE(outcome.failed) << outcome.error;
}

TEST(PlanBatch, EveryJobOfASceneIsHandedTheOneReadingOfItsFile) {
  const BatchPlan plan = planBatch(tinyRequest(2), "test");
  ASSERT_EQ(plan.jobs.size(), 8u);
  for (const BatchJob& job : plan.jobs) {
    const BatchJob& first = plan.jobs[job.scene == plan.jobs.front().scene ? 0 : 4];
    EXPECT_EQ(job.spec.scene, first.spec.scene) << job.stem << ": one copy per scene";
    EXPECT_EQ(job.spec.scene->scene.name, job.scene) << job.stem;
    EXPECT_EQ(job.spec.scene->hash, job.sceneHash) << job.stem;
  }
  EXPECT_NE(plan.jobs.front().spec.scene, plan.jobs.back().spec.scene);
}

TEST(RunJob, RunsTheSceneItIsHandedWhileItsFileHoldsThoseBytesElseTheFileAsItIsNow) {
  const testing::ScratchDir dir;
  const fs::path file = dir / "tiny.json";
  fs::copy_file(testing::testDataDir() / "scenes" / "tiny_static.json", file);
  BatchPlan plan = planBatch(tinyRequest(1), "test");
  JobSpec job = plan.jobs.front().spec;
  job.sceneFile = file;
  auto handed = std::make_shared<scene::SceneFile>(*readSceneFile(file));
  handed->scene.name = "as handed";  // tells which reading ran
  job.scene = handed;
  EXPECT_EQ(runJob(job).metadata.scene, "as handed") << "the file was not read again";

  // Edited since the reading: the job reads the file as it is now, as one on its own would.
  fs::copy_file(testing::testDataDir() / "scenes" / "tiny_dynamic.json", file,
                fs::copy_options::overwrite_existing);
  const records::RunRecord run = runJob(job);
  EXPECT_EQ(run.metadata.scene, "tiny");
  EXPECT_EQ(run.metadata.sceneHash, scene::sceneFileHash(file));
  EXPECT_NE(run.metadata.sceneHash, handed->hash);
}

TEST(PrepareFolder, RefusesResultsOfOtherParametersUnlessForced) {
  const testing::ScratchDir dir;
  const records::BatchFolder folder(dir / "out");
  BatchPlan plan = planBatch(tinyRequest(1), "test");
  prepareFolder(folder, plan.manifest, false);
  plan.manifest.parameters.global.K = 21;
  EXPECT_THROW(prepareFolder(folder, plan.manifest, false), InputError);
  EXPECT_NO_THROW(prepareFolder(folder, plan.manifest, true));
}

// A method brought for one batch (as Python brings its controllers), of a given code identity.
control::Method brought(const std::string& identity) {
  const control::Method& local = control::requireMethod("local");
  return {"brought", "a brought method", "#000000", control::Role::method, local.make, identity};
}

TEST(PrepareFolder, ResultsOfAMethodWhoseCodeChangedAreRefusedOrWithForceRunAgain) {
  const testing::ScratchDir dir;
  const records::BatchFolder folder(dir / "out");
  const std::vector<control::Method> before{brought("python 1111")};
  BatchRequest r = tinyRequest(1);
  r.methods = {"local", "brought"};
  r.extraMethods = before;
  BatchPlan plan = planBatch(r, "test");
  EXPECT_EQ(plan.manifest.methodIdentities.at("brought"), "python 1111");
  EXPECT_EQ(plan.manifest.methodIdentities.at("local").rfind("c++ ", 0), 0u);
  prepareFolder(folder, plan.manifest, false);
  Recorder first;
  runBatch(plan.jobs, folder, 2, first);
  ASSERT_EQ(first.ran.size(), 4u);

  const std::vector<control::Method> after{brought("python 2222")};
  r.extraMethods = after;
  BatchPlan changed = planBatch(r, "test");
  try {
    prepareFolder(folder, changed.manifest, false);
    FAIL() << "resumed results of other code";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("brought (python 1111 then, python 2222 now)"),
              std::string::npos)
        << e.what();
  }
  prepareFolder(folder, changed.manifest, true);
  Recorder second;
  runBatch(changed.jobs, folder, 2, second);
  EXPECT_EQ(second.alreadyDone, 2u) << "local's results stay";
  for (const std::string& stem : second.ran)
    EXPECT_NE(stem.find("-brought-"), std::string::npos) << stem << " ran again";
  EXPECT_EQ(second.ran.size(), 2u);
  EXPECT_EQ(folder.readManifest()->methodIdentities.at("brought"), "python 2222");

  // A batch of local alone keeps saying which code made brought's results.
  r.methods = {"local"};
  BatchPlan alone = planBatch(r, "test");
  prepareFolder(folder, alone.manifest, false);
  EXPECT_EQ(folder.readManifest()->methodIdentities.at("brought"), "python 2222");
}

TEST(PlanBatch, MethodsNamedTwiceOrNotAtAllAndTooManyJobsAreRefused) {
  BatchRequest r = tinyRequest(1);
  r.methods = {"paper", "paper"};
  EXPECT_THROW(planBatch(r, "test"), InputError);
  r.methods = {};
  EXPECT_THROW(planBatch(r, "test"), InputError);
  r.methods = {"paper"};
  r.seeds = kMaxSeeds + 1;
  EXPECT_THROW(planBatch(r, "test"), InputError);
  r.seeds = kMaxSeeds;
  r.methods = {"paper", "local", "camcov"};
  r.scenes.push_back(r.scenes.front());  // 2 x 2 scenes x 3 methods x 100,000 seeds
  EXPECT_THROW(planBatch(r, "test"), InputError) << "more than a million jobs";
}

// The tiny batch with `seeds` seeds run as two shards in dir/shard-1 and dir/shard-2.
std::vector<std::string> runTwoShards(const fs::path& dir, std::uint64_t seeds) {
  std::vector<std::string> shards;
  for (std::size_t k = 1; k <= 2; ++k) {
    BatchRequest r = tinyRequest(seeds);
    r.shard = {k - 1, 2};
    BatchPlan plan = planBatch(r, "test");
    const records::BatchFolder folder(dir / ("shard-" + std::to_string(k)));
    prepareFolder(folder, plan.manifest, false);
    Recorder quiet;
    runBatch(plan.jobs, folder, 1, quiet);
    shards.push_back(folder.root().string());
  }
  return shards;
}

TEST(MergeFolders, ShardsCombineIntoEveryRunAndOtherParametersAreRefused) {
  const testing::ScratchDir dir;
  const std::vector<std::string> shards = runTwoShards(dir.path(), 1);
  const records::BatchFolder merged(dir / "merged");
  const auto manifest = mergeFolders(shards, merged, {"camcov", "merge"});
  EXPECT_EQ(manifest.scenes.size(), 2u);
  EXPECT_EQ(merged.allJobs().size(), 4u);
  EXPECT_EQ(merged.readTimings().size(), 4u);
  EXPECT_EQ(merged.readManifest()->command, (std::vector<std::string>{"camcov", "merge"}));

  BatchRequest other = tinyRequest(1);
  other.parameters.global.K = 21;
  const records::BatchFolder odd(dir / "odd");
  BatchPlan oddPlan = planBatch(other, "test");
  prepareFolder(odd, oddPlan.manifest, false);
  EXPECT_THROW(mergeFolders({shards[0], odd.root().string()}, merged, {}), InputError);
  EXPECT_THROW(mergeFolders({(dir / "nothing").string()}, merged, {}), InputError);

  // Shards built from other code of a method.
  records::BatchManifest rebuilt = *records::BatchFolder(shards[1]).readManifest();
  rebuilt.methodIdentities["paper"] = "c++ 0123456789abcdef";
  records::BatchFolder(shards[1]).writeManifest(rebuilt);
  try {
    mergeFolders(shards, records::BatchFolder(dir / "mixed"), {});
    FAIL() << "merged results of other code";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("other code"), std::string::npos) << e.what();
  }
}

TEST(MergeFolders, AMissingShardOrRunAndARunUnderAnotherJobsNameAreRefused) {
  const testing::ScratchDir dir;
  const auto refused = [&](const std::vector<std::string>& inputs, const std::string& fragment) {
    const records::BatchFolder target(dir / "target");
    try {
      mergeFolders(inputs, target, {});
      ADD_FAILURE() << "merged: " << fragment;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(target.runsDir())) << "nothing copied";
  };
  const std::vector<std::string> shards = runTwoShards(dir.path(), 2);
  // One shard of two.
  refused({shards[0]}, "jobs have no run in any folder given");
  // Both, but a run deleted.
  const records::BatchFolder second(shards[1]);
  const std::vector<records::JobOutcome> jobs = second.allJobs();
  ASSERT_GE(jobs.size(), 2u);
  const fs::path first =
      second.runFile(records::runStem(jobs[0].scene, jobs[0].method, jobs[0].seed));
  const fs::path other =
      second.runFile(records::runStem(jobs[1].scene, jobs[1].method, jobs[1].seed));
  const fs::path kept = dir / "kept.json";
  fs::rename(first, kept);
  refused(shards, "jobs have no run in any folder given");
  // Another job's run under its name.
  fs::copy_file(other, first);
  refused(shards, "not a run of this batch: its name is not its job's");
  fs::remove(first);
  fs::rename(kept, first);
  const records::BatchFolder whole(dir / "whole");
  EXPECT_EQ(mergeFolders(shards, whole, {}).scenes.size(), 2u);
}

TEST(MergeFolders, ADamagedRunIsNamedInItsSourceAndNothingIsCopied) {
  const testing::ScratchDir dir;
  BatchPlan plan = planBatch(tinyRequest(1), "test");
  const records::BatchFolder source(dir / "source");
  prepareFolder(source, plan.manifest, false);
  Recorder quiet;
  runBatch(plan.jobs, source, 1, quiet);
  const fs::path json = source.runFile(plan.jobs.back().stem);
  const fs::path csv = fs::path(json).replace_extension(".csv");
  const std::string wholeJson = testing::readFile(json), wholeCsv = testing::readFile(csv);
  const records::BatchFolder target(dir / "target");
  // A truncated JSON; a whole JSON whose CSV is cut short, or empty.
  for (const auto& [damaged, bytes] : {std::pair{json, wholeJson.size() / 2},
                                       std::pair{csv, wholeCsv.size() / 2}, std::pair{csv, 0ul}}) {
    SCOPED_TRACE(damaged.string() + " cut to " + std::to_string(bytes) + " bytes");
    std::ofstream(json, std::ios::binary) << wholeJson;
    std::ofstream(csv, std::ios::binary) << wholeCsv;
    fs::resize_file(damaged, bytes);
    try {
      mergeFolders({source.root().string()}, target, {});
      ADD_FAILURE() << "merged a damaged run";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(json.string()), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(target.runsDir())) << "nothing copied";
  }
}

}  // namespace
}  // namespace camcov::batch
