// The page in headless Chromium (Debian's, driven by playwright-core): it
// loads, runs a scene, answers keys and mouse drags, and shows what the
// native build draws. Run by `make web-test`:
//   node web/test/chromium_check.mjs build/web build/game OUTDIR
// OUTDIR gets the screenshots (look at them) and the measures.
import { createServer } from 'node:http';
import { readFileSync, writeFileSync, mkdirSync, mkdtempSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { createRequire } from 'node:module';
import { join, extname } from 'node:path';
import { tmpdir } from 'node:os';
import { readPng } from './png.mjs';

const [webDir, gamePath, outDir] = process.argv.slice(2);
const require = createRequire(join(process.cwd(), 'build/npm/'));
const { chromium } = require('playwright-core');
mkdirSync(outDir, { recursive: true });
let failures = 0;
const check = (ok, what) => {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) failures++;
};

// build/web on an ephemeral localhost port.
const types = { '.html': 'text/html', '.js': 'text/javascript', '.json': 'application/json', '.wasm': 'application/wasm' };
const server = createServer((req, res) => {
  const path = join(webDir, decodeURIComponent(new URL(req.url, 'http://x').pathname));
  try {
    const body = readFileSync(path);
    res.writeHead(200, { 'Content-Type': types[extname(path)] || 'text/plain' }).end(body);
  } catch {
    res.writeHead(404).end();
  }
});
await new Promise((ok) => server.listen(0, '127.0.0.1', ok));
const base = `http://127.0.0.1:${server.address().port}/index.html`;

const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  // (playwright gives each launch a fresh profile directory of its own)
  args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
         '--disable-sync', '--no-first-run'],
});
const page = await browser.newPage({ viewport: { width: 1000, height: 760 } });
const errors = [];
page.on('pageerror', (e) => errors.push(e.message));
page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
const state = () => page.evaluate(() => window.physics.state());
const wait = (ms) => page.waitForTimeout(ms);
const canvas = page.locator('#view');
// The canvas's pixels, from a screenshot, saved as OUTDIR/NAME.png.
async function shot(name) {
  const buf = await canvas.screenshot({ path: join(outDir, `${name}.png`) });
  return readPng(buf);
}
const count = (img, pred) => {
  let n = 0;
  for (let i = 0; i < img.width * img.height; i++) n += pred(img.rgb[3 * i], img.rgb[3 * i + 1], img.rgb[3 * i + 2]);
  return n;
};
const press = async (key) => { await page.keyboard.press(key); await wait(50); };
async function open(scene) {
  await page.goto(`${base}?scene=${encodeURIComponent(scene)}`);
  await page.evaluate(() => window.physics.ready);
  await canvas.focus();
}

// 1. The scene runs, then pauses, steps and resumes from the keys.
await open('many');
await wait(1000);
let s = await state();
check(s.scene === 'many' && s.frame > 20, `many runs: frame ${s.frame} after 1 s`);
await press('Space');
const paused = await state();
await wait(300);
s = await state();
check(paused.paused && s.frame === paused.frame, `Space pauses (frame ${paused.frame}, ${s.frame} 300 ms later)`);
await press('n');
s = await state();
check(s.paused && s.frame === paused.frame + 1, `N steps one frame (${s.frame})`);

// 2. The picture is the native one: blocks drawn as build/game --screenshot
// draws them at this frame, HUD off (I), pixel for pixel.
await press('i');
const frame = (await state()).frame;
const img = await shot('many-paused');
const nativePng = join(mkdtempSync(join(tmpdir(), 'web-shot-')), 'native.png');
execFileSync(gamePath, ['--scene', 'many', '--headless', '--frames', String(frame), '--screenshot', nativePng], { stdio: 'ignore' });
const native = readPng(readFileSync(nativePng));
let differ = 0;
for (let i = 0; i < native.rgb.length; i++) differ += native.rgb[i] !== img.rgb[i];
check(img.width === native.width && differ === 0,
  `frame ${frame}'s canvas (${img.width}x${img.height}) is the native screenshot's pixels (${differ} bytes differ)`);
await press('i');

// 3. Overlays and the key list from their keys.
await press('a');
await press('h');
const over = await shot('many-overlays');
const green = count(over, (r, g, b) => r === 0 && g === 170 && b === 0);
const panel = count(over, (r, g, b) => r === 255 && g === 255 && b >= 238 && b <= 242);
// The HUD's lines: dark text at (48, 44) and below, where the HUD-off picture has none.
const inHud = (im) => {
  let n = 0;
  for (let y = 44; y < 100; y++) for (let x = 48; x < 600; x++) n += im.at(x, y).every((v) => v < 80);
  return n;
};
check(green > 500 && panel > 20000 && inHud(over) > 500 && inHud(img) === 0, `A draws the boxes (${green} green ` +
  `pixels), H the key list (${panel} panel pixels), I the HUD (${inHud(over)} dark pixels, ${inHud(img)} without)`);
await press('a');
await press('h');

// 4. The mouse: a click spawns a block, a drag flings one, a right drag casts a ray.
const before = (await state()).bodies;
const box = await canvas.boundingBox();
const mouse = (x, y) => page.mouse.move(box.x + x, box.y + y);
await mouse(400, 300), await page.mouse.down(), await page.mouse.up();
await press('n');
const clicked = (await state()).bodies;
await mouse(600, 200), await page.mouse.down(), await mouse(650, 230), await mouse(700, 260);
const sling = await shot('many-slingshot');
await page.mouse.up();
await press('n');
const flung = (await state()).bodies;
check(clicked === before + 1 && flung === before + 2, `a click spawns (${before} -> ${clicked} bodies), a drag flings (${flung})`);
check(count(sling, (r, g, b) => r === 255 && g === 140 && b === 0) > 50, 'the slingshot shows while dragging');
await mouse(100, 500), await page.mouse.down({ button: 'right' }), await mouse(700, 100);
const ray = await shot('many-ray');
await page.mouse.up({ button: 'right' });
check(count(ray, (r, g, b) => r === 0 && g === 150 && b === 150) > 50, 'a right drag draws the ray');

// 5. R resets, digits and Tab switch scenes.
await press('r');
s = await state();
check(s.frame <= 1 && s.bodies === before, `R resets (frame ${s.frame}, ${s.bodies} bodies)`);
await press('7');
s = await state();
check(s.scene === 'gas', `7 opens scene 7 (${s.scene}, ${s.bodies} bodies)`);
await press('Tab');
check((await state()).scene === 'stack', 'Tab opens the next one (stack)');

// Every built-in scene and scene file opens and runs in the page.
const names = await page.evaluate(() => [...document.querySelectorAll('#scene option')].map((o) => o.value));
const stalled = [];
for (const name of names) {
  await open(name);
  await wait(400);
  const st = await state();
  if (!(st.frame > 0) || errors.length) stalled.push(`${name} (frame ${st.frame})`);
}
check(names.length >= 23 && stalled.length === 0,
  `all ${names.length} scenes of the menu run${stalled.length ? '; not: ' + stalled.join(', ') : ''}`);

// 6. Frame rates: the 300-body gas and the games, 3 s each.
const measures = {};
async function rate(scene) {
  await open(scene);
  await wait(500);
  const a = await page.evaluate(() => ({ ...window.physics.stats, t: performance.now() }));
  await wait(3000);
  const b = await page.evaluate(() => ({ ...window.physics.stats, t: performance.now() }));
  const fps = (b.frames - a.frames) / ((b.t - a.t) / 1000);
  const perFrame = (b.wasmMs + b.paintMs - a.wasmMs - a.paintMs) / (b.frames - a.frames);
  measures[scene] = { fps: +fps.toFixed(1), ms_per_frame: +perFrame.toFixed(2) };
  return fps;
}
for (const scene of ['gas', 'scenes/maps/platformer.tmj', 'scenes/targets-1.json']) {
  const fps = await rate(scene);
  check(fps >= 55, `${scene}: ${fps.toFixed(1)} frames/s (wasm and painting ${measures[scene].ms_per_frame} ms a frame)`);
  await shot(scene.replace(/.*\//, '').replace(/\.\w+$/, ''));
}

// 7. The games: keys held move the player; each committed replay ends in
// the page with the native final state.
await open('scenes/maps/platformer.tmj');
await page.keyboard.down('ArrowRight');
await wait(700);
await page.keyboard.up('ArrowRight');
await press('Space');
const moved = await state();
// The same level without input, to the same frame: another state.
const idle = await page.evaluate((f) => window.physics.run('web_headless', 'scenes/maps/platformer.tmj', f), moved.frame);
const idleHash = idle.match(/state (\S+)/)[1];
check(moved.game && moved.frame > 20 && moved.hash !== idleHash,
  `the platformer answers the keys: frame ${moved.frame}, state ${moved.hash}, without them ${idleHash}`);
for (const log of ['replays/platformer.log', 'replays/targets-1.log']) {
  const out = await page.evaluate((l) => window.physics.run('web_replay', l), log);
  const dump = join(mkdtempSync(join(tmpdir(), 'web-native-')), 'dump.csv');
  execFileSync(gamePath, ['--replay', log, '--headless', '--dump', dump], { stdio: 'ignore' });
  const same = out.slice(out.indexOf('id,')) === readFileSync(dump, 'utf8');
  check(same && /game: won/.test(out), `${log} in the page: ${out.match(/state \S+/)[0]}, won, final dump ` +
    `${same ? 'identical to' : 'DIFFERS from'} the native one`);
}

// 8. The physics' speed in Chromium: gas10k's ms/step, against the native build's.
const gas10k = await page.evaluate(() => window.physics.run('web_headless', 'scenes/gas10k.json', 300));
const nativeGas = execFileSync(gamePath, ['--scene', 'scenes/gas10k.json', '--headless', '--frames', '300'], { encoding: 'utf8' });
const msStep = (text) => Number(text.match(/physics ms\/step: ([0-9.e-]+)/)[1]);
measures.gas10k_ms_per_step = { chromium: msStep(gas10k), native: msStep(nativeGas) };
console.log(`     gas10k, 300 frames: ${msStep(gas10k)} ms/step in Chromium, ${msStep(nativeGas)} natively`);

// 9. A scene that does not read: its error under the picture (the exception
// caught in the module), and the default scene runs.
errors.length = 0;
await page.goto(`${base}?scene=scenes/nope.json`);
await page.evaluate(() => window.physics.ready);
await wait(300);
const shown = await page.locator('#error').textContent();
s = await state();
check(/scenes\/nope\.json: cannot read the scene file: no such file/.test(shown) && s.scene === 'many' && s.frame > 0,
  `a missing scene: "${shown.trim()}" shown, many runs instead (frame ${s.frame})`);
errors.splice(0, errors.length, ...errors.filter((e) => !/nope\.json/.test(e)));

check(errors.length === 0, `no error on the page${errors.length ? ': ' + errors.join('; ') : ''}`);
writeFileSync(join(outDir, 'measures.json'), JSON.stringify(measures, null, 1) + '\n');
await browser.close();
server.close();
process.exit(failures ? 1 : 0);
