// The WebAssembly engine (src/wasm) against the program it is compiled from: for scenes and
// poses, what the engine computes is what `camcov inspect --json` prints, and a bad scene gets
// the message `camcov validate` prints. Run by ctest:
//   node tests/wasm/engine_test.mjs ENGINE.js CAMCOV REPO
import assert from "node:assert/strict";
import {execFileSync, spawnSync} from "node:child_process";
import {mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync} from "node:fs";
import {tmpdir} from "node:os";
import {createRequire} from "node:module";
import path from "node:path";

const [enginePath, camcov, repo] = process.argv.slice(2);
const createCamcovEngine = createRequire(import.meta.url)(path.resolve(enginePath));
const engine = await createCamcovEngine();

// Numbers the two compute with different maths libraries (musl's sin and cos in WebAssembly,
// glibc's in the program) agree to far below anything a camera can tell apart.
const close = (a, b, what) =>
  assert.ok(Math.abs(a - b) <= 1e-9 * Math.max(1, Math.abs(b)), `${what}: ${a} vs ${b}`);

const scratch = mkdtempSync(path.join(tmpdir(), "camcov_engine_"));
process.on("exit", () => rmSync(scratch, {recursive: true, force: true}));

function compare(sceneFile, time, poses) {
  const args = ["inspect", sceneFile, "--time", String(time), "--json"];
  let posesText = "";
  if (poses) {
    posesText = JSON.stringify(poses);
    const file = path.join(scratch, "poses.json");
    writeFileSync(file, posesText);
    args.push("--cameras", file);
  }
  const cli = JSON.parse(execFileSync(camcov, args, {encoding: "utf8"}));
  const ours = JSON.parse(engine.inspect(readFileSync(sceneFile, "utf8"), path.basename(sceneFile),
                                         time, posesText));
  assert.equal(ours.error, undefined, `${sceneFile}: ${ours.error}`);
  for (const key of ["coverage", "utilization", "repulsion", "reward", "targetPerimeter"])
    close(ours[key], cli[key], `${sceneFile} at ${time}: ${key}`);
  assert.equal(ours.cameras.length, cli.cameras.length);
  ours.cameras.forEach((c, j) =>
    close(c.visibleLength, cli.cameras[j].visibleLength, `${sceneFile}: camera ${j}`));
  assert.deepEqual(ours.segments.map((s) => [s.target, s.edge, s.visibleBy]),
                   cli.segments.map((s) => [s.target, s.edge, s.visibleBy]), sceneFile);
}

// Every scene of our own and every test scene, at two instants, at the initial poses; and one
// scene with poses given.
const folders = [path.join(repo, "scenes"), path.join(repo, "tests", "data", "scenes")];
let compared = 0;
for (const folder of folders) {
  for (const name of readdirSync(folder).filter((f) => f.endsWith(".json")).sort()) {
    for (const time of [0, 7.3]) {
      compare(path.join(folder, name), time);
      ++compared;
    }
  }
}
compare(path.join(repo, "tests", "data", "scenes", "tiny_dynamic.json"), 2.5,
        [{x: 1.5, y: -4, yaw_deg: 80}]);
assert.ok(compared >= 20, `only ${compared} scenes compared`);

// Bad scenes: the validator's own words.
const bad = path.join(repo, "tests", "data", "bad");
for (const name of readdirSync(bad).filter((f) => f.endsWith(".json")).sort()) {
  const file = path.join(bad, name);
  const cli = spawnSync(camcov, ["validate", file], {encoding: "utf8"});
  assert.equal(cli.status, 2, name);
  const ours = JSON.parse(engine.validate(readFileSync(file, "utf8"), file));
  assert.ok(ours.error, `${name}: the engine accepts what camcov validate refuses`);
  assert.ok((cli.stdout + cli.stderr).includes(ours.error.split("\n")[0]),
            `${name}: ${ours.error} not in ${cli.stdout}${cli.stderr}`);
}
console.log(`engine: ${compared + 1} inspections and the bad scenes agree with camcov`);
