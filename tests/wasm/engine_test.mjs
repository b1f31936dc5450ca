// The WebAssembly engine (src/wasm) against the program it is compiled from: for scenes and
// poses, the engine answers what `camcov inspect --json` prints (the same writer: every key, each
// number to 1e-9), and a bad scene gets the message `camcov validate` prints. Run by ctest:
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

// The same JSON, numbers to `close`.
function agree(ours, cli, where) {
  if (typeof cli === "number") return close(ours, cli, where);
  if (Array.isArray(cli)) {
    assert.ok(Array.isArray(ours) && ours.length === cli.length, `${where}: length`);
    return cli.forEach((v, i) => agree(ours[i], v, `${where}[${i}]`));
  }
  if (cli !== null && typeof cli === "object") {
    assert.deepEqual(Object.keys(ours).sort(), Object.keys(cli).sort(), `${where}: keys`);
    return Object.keys(cli).forEach((k) => agree(ours[k], cli[k], `${where}.${k}`));
  }
  assert.equal(ours, cli, where);
}

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
  agree(ours, cli, `${sceneFile} at ${time}`);
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
// Poses inspect refuses (outside the boundary), refused in the inspect's words.
const outside = JSON.parse(engine.inspect(
    readFileSync(path.join(repo, "tests", "data", "scenes", "tiny_dynamic.json"), "utf8"),
    "tiny_dynamic.json", 0, JSON.stringify([{x: 1e6, y: 0, yaw_deg: 0}])));
assert.match(outside.error ?? "", /outside the scene's boundary/);
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
