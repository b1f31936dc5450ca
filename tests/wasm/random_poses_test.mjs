// One engine, two targets: on 1,000 random team poses over the 32 published scenes, the
// WebAssembly build's segments S (ends and visibleBy) and reward terms equal the native
// build's (`camcov inspect --json`) to 1e-12. Run by ctest:
//   node tests/wasm/random_poses_test.mjs ENGINE.js CAMCOV REPO
// The published scenes are read from $COVERAGE_SCENES_DIR, else ../shared/coverage_scenes.
import assert from "node:assert/strict";
import {execFileSync} from "node:child_process";
import {mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync} from "node:fs";
import {tmpdir} from "node:os";
import {createRequire} from "node:module";
import path from "node:path";

const [enginePath, camcov, repo] = process.argv.slice(2);
const published = process.env.COVERAGE_SCENES_DIR ||
                  path.join(repo, "..", "shared", "coverage_scenes");
const createCamcovEngine = createRequire(import.meta.url)(path.resolve(enginePath));
const engine = await createCamcovEngine();
const scratch = mkdtempSync(path.join(tmpdir(), "camcov_poses_"));
process.on("exit", () => rmSync(scratch, {recursive: true, force: true}));

const kPoses = 1000, kTolerance = 1e-12;
// A fixed sequence (a 32-bit linear congruential generator): the same poses every run.
let state = 12345;
const uniform = (lo, hi) => {
  state = (Math.imul(state, 1664525) + 1013904223) >>> 0;
  return lo + (hi - lo) * (state / 2 ** 32);
};
const ring = (wkt) => wkt.slice(wkt.indexOf("((") + 2, wkt.lastIndexOf("))")).split(",")
    .map((p) => p.trim().split(/\s+/).map(Number));
const inside = (p, r) => {
  let c = false;
  for (let i = 0, j = r.length - 1; i < r.length; j = i++) {
    if ((r[i][1] > p[1]) !== (r[j][1] > p[1]) &&
        p[0] < (r[j][0] - r[i][0]) * (p[1] - r[i][1]) / (r[j][1] - r[i][1]) + r[i][0]) c = !c;
  }
  return c;
};

const scenes = readdirSync(published).filter((f) => f.endsWith(".json")).sort();
assert.equal(scenes.length, 32, `${published} should hold the 32 published scenes`);
let worst = 0, compared = 0;
for (let k = 0; k < kPoses; ++k) {
  const file = path.join(published, scenes[k % scenes.length]);
  const text = readFileSync(file, "utf8");
  const scene = JSON.parse(text);
  const boundary = ring(scene.boundary);
  const xs = boundary.map((p) => p[0]), ys = boundary.map((p) => p[1]);
  const poses = scene.cameras.map(() => {
    for (;;) {
      const p = [uniform(Math.min(...xs), Math.max(...xs)), uniform(Math.min(...ys), Math.max(...ys))];
      if (inside(p, boundary)) return {x: p[0], y: p[1], yaw_deg: uniform(-180, 180)};
    }
  });
  const time = uniform(0, 30);
  const posesText = JSON.stringify(poses);
  const posesFile = path.join(scratch, "poses.json");
  writeFileSync(posesFile, posesText);
  const cli = JSON.parse(execFileSync(camcov, ["inspect", file, "--time", String(time),
                                               "--cameras", posesFile, "--json"], {encoding: "utf8"}));
  const ours = JSON.parse(engine.inspect(text, path.basename(file), time, posesText));
  const where = `${scenes[k % scenes.length]}, pose set ${k}, t = ${time}`;
  assert.equal(ours.error, undefined, `${where}: ${ours.error}`);
  const near = (a, b, what) => {
    worst = Math.max(worst, Math.abs(a - b));
    assert.ok(Math.abs(a - b) <= kTolerance, `${where}: ${what}: ${a} (WebAssembly) vs ${b}`);
  };
  for (const key of ["coverage", "utilization", "repulsion", "reward"]) near(ours[key], cli[key], key);
  assert.equal(ours.segments.length, cli.segments.length, `${where}: |S|`);
  ours.segments.forEach((s, i) => {
    const c = cli.segments[i];
    assert.deepEqual([s.target, s.edge, s.visibleBy], [c.target, c.edge, c.visibleBy],
                     `${where}: segment ${i}`);
    for (const end of ["a", "b"]) {
      near(s[end][0], c[end][0], `segment ${i}.${end}.x`);
      near(s[end][1], c[end][1], `segment ${i}.${end}.y`);
    }
  });
  ++compared;
}
console.log(`engine: ${compared} random pose sets over ${scenes.length} published scenes agree ` +
            `with camcov to ${kTolerance} (largest difference ${worst})`);
