// The WebAssembly build under Node's WASI (node:wasi), against the native
// build: the determinism hashes (committed in tests/test_determinism.cpp) and
// each committed game replay's final state (build/game --replay LOG
// --headless --dump: the same dump, byte for byte). Run by `make web-test`:
//   node web/test/node_check.mjs build/web/physics.wasm build/game
import { WASI } from 'node:wasi';
import { readFileSync, writeFileSync, mkdtempSync, readdirSync, openSync, closeSync, mkdirSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const [wasmPath, gamePath] = process.argv.slice(2);
const module = await WebAssembly.compile(readFileSync(wasmPath));
let failures = 0;
const check = (ok, what) => {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) failures++;
};

// One export called in a fresh instance: its return value, stdout, stderr,
// and the time it took. The repository is preopened as "/" (scenes/, replays/).
async function run(exportName, arg, number) {
  const dir = mkdtempSync(join(tmpdir(), 'web-check-'));
  const out = openSync(join(dir, 'out'), 'w'), err = openSync(join(dir, 'err'), 'w');
  const wasi = new WASI({ version: 'preview1', preopens: { '/': process.cwd() }, stdout: out, stderr: err,
                          returnOnExit: true });
  const instance = await WebAssembly.instantiate(module, { wasi_snapshot_preview1: wasi.wasiImport });
  wasi.initialize(instance);
  const { memory, web_alloc } = instance.exports;
  const args = [];
  if (arg !== undefined) {
    const bytes = new TextEncoder().encode(arg + '\0');
    const p = web_alloc(bytes.length);
    new Uint8Array(memory.buffer, p, bytes.length).set(bytes);
    args.push(p);
  }
  if (number !== undefined) args.push(number);
  const t0 = performance.now();
  const rc = instance.exports[exportName](...args);
  const ms = performance.now() - t0;
  closeSync(out), closeSync(err);
  return { rc, text: readFileSync(join(dir, 'out'), 'utf8'), err: readFileSync(join(dir, 'err'), 'utf8'), ms };
}

// 1. Determinism: each mode's pair of hashes and the 1 000-frame one, as committed.
const test = readFileSync('tests/test_determinism.cpp', 'utf8');
const list = (name) => test.match(new RegExp(`${name}\\[\\] = \\{([^}]*)\\}`))[1].match(/0x[0-9a-f]+/g);
const gas = list('gas_expected'), pyramid = list('pyramid_expected');
const long = test.match(/expected_hash = (0x[0-9a-f]+)/)[1];
const det = await run('web_determinism');
const lines = det.text.trim().split('\n');
const norm = (h) => '0x' + BigInt(h).toString(16).padStart(16, '0');
lines.slice(0, -1).forEach((line, m) => {
  const [name, , g, , p] = line.split(' ');
  check(g === norm(gas[m]) && p === norm(pyramid[m]), `determinism ${name}: gas ${g} pyramid ${p} (committed ${norm(gas[m])} ${norm(pyramid[m])})`);
});
const last = lines.at(-1).split(' ')[1];
check(last === norm(long), `determinism 1000 frames: ${last} (committed ${norm(long)}), ${(det.ms / 1000).toFixed(1)} s`);

// 2. Each committed replay: the wasm's final dump is the native game's.
for (const log of readdirSync('replays').filter((f) => f.endsWith('.log')).sort()) {
  const path = `replays/${log}`;
  const web = await run('web_replay', path);
  const dump = web.text.slice(web.text.indexOf('id,'));
  const head = web.text.slice(0, web.text.indexOf('id,')).trim().split('\n');
  const native = join(mkdtempSync(join(tmpdir(), 'web-native-')), 'dump.csv');
  execFileSync(gamePath, ['--replay', path, '--headless', '--dump', native], { stdio: 'ignore' });
  const same = readFileSync(native, 'utf8') === dump;
  check(same, `replay ${path}: ${head.join(', ')}; final dump ${same ? 'identical to' : 'DIFFERS from'} the native one`);
}
// 3. Every scene file, 300 frames headless: the wasm's final dump is the
// native game's; and the ms/step of both on gas10k (the bench's gas 10 000).
for (const file of readdirSync('scenes').filter((f) => f.endsWith('.json')).sort()) {
  const path = `scenes/${file}`;
  const web = await run('web_headless', path, 300);
  const native = join(mkdtempSync(join(tmpdir(), 'web-native-')), 'dump.csv');
  const summary = execFileSync(gamePath, ['--scene', path, '--headless', '--frames', '300', '--dump', native], { encoding: 'utf8' });
  const same = readFileSync(native, 'utf8') === web.text.slice(web.text.indexOf('id,'));
  const ms = (text) => text.match(/physics ms\/step: ([0-9.e-]+)/)[1];
  check(same, `scene ${path}, 300 frames: final dump ${same ? 'identical to' : 'DIFFERS from'} the native one` +
    (file === 'gas10k.json' ? ` (physics ms/step: wasm ${ms(web.text)}, native ${ms(summary)})` : ''));
}
// 4. Bad input: the exception is caught (web/cxa_exceptions.cpp), and the
// message is the native game's, word for word.
const bad = 'build/web-check';
mkdirSync(bad, { recursive: true });
const cases = {
  'missing.json': null,
  'syntax.json': '{ "name": "s",\n  "world": { "gravity": [0, 1] ]\n}\n',
  'key.json': '{ "name": "k", "world": { "gravty": [0, 1] } }\n',
  'wall.json': '{ "name": "w", "blocks": [ { "pos": [770, 100], "size": [20, 20], "mass": 1 } ] }\n',
};
for (const [file, text] of Object.entries(cases)) {
  const path = `${bad}/${file}`;
  if (text !== null) writeFileSync(path, text);
  const web = await run('web_headless', path, 1);
  let native = '';
  try {
    execFileSync(gamePath, ['--scene', path, '--headless', '--frames', '1'], { stdio: 'pipe' });
  } catch (e) {
    native = e.stderr.toString();
  }
  check(web.rc === 2 && native !== '' && web.err === native, `bad scene ${file}: ${web.err.trim()}` +
    (web.err === native ? ' (as natively)' : ` (natively: ${native.trim()})`));
}
process.exit(failures ? 1 : 0);
