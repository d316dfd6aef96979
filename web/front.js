// The page: physics.wasm's testbed on a <canvas>, as the course archive's
// browser back end does it: key and mouse events into the testbed's input
// (InputEvent), a loop on requestAnimationFrame running the fixed steps of
// dt that the real time covers (Testbed::advance), and the window's picture
// drawn from the module's draw commands (web/draw_commands.hpp).
import { Wasi } from './wasi.js';

const canvas = document.getElementById('view');
const ctx = canvas.getContext('2d');
const select = document.getElementById('scene');
const status = document.getElementById('status');
const errorBox = document.getElementById('error');
const Kind = { quit: 0, key: 1, mouse_down: 2, mouse_up: 3, mouse_move: 4, key_up: 5, wheel: 6 };  // InputEvent::Kind

// KeyboardEvent.key to SDL's key codes (input/keys.hpp): letters and digits
// are their lower-case ASCII.
const SPECIAL = { Escape: 27, Tab: 9, ' ': 32, Enter: 13, ArrowRight: 0x4000004f, ArrowLeft: 0x40000050,
                  ArrowDown: 0x40000051, ArrowUp: 0x40000052 };
function sdlKey(e) {
  if (e.key === 'Shift') return e.code === 'ShiftRight' ? 0x400000e5 : 0x400000e1;  // Shift+drag pans
  if (e.key in SPECIAL) return SPECIAL[e.key];
  return e.key.length === 1 ? e.key.toLowerCase().charCodeAt(0) : 0;
}

let wasm, captured = null, running = false, last = 0, fps = 0, drawMs = 0;
const stats = { frames: 0, steps: 0, wasmMs: 0, paintMs: 0 };

function cString(text) {
  const bytes = new TextEncoder().encode(text + '\0');
  const p = wasm.web_alloc(bytes.length);
  new Uint8Array(wasm.memory.buffer, p, bytes.length).set(bytes);
  return p;
}
function readString(p) {
  const mem = new Uint8Array(wasm.memory.buffer);
  let end = p;
  while (mem[end]) end++;
  return new TextDecoder().decode(mem.subarray(p, end));
}
const state = () => JSON.parse(readString(wasm.web_state()));

function open(name) {
  const p = cString(name);
  const failed = wasm.web_open(p);  // its error went to stderr, shown under the picture
  wasm.web_free(p);
  if (failed) return false;
  const s = state();
  canvas.width = s.width, canvas.height = s.height;
  running = true;
  canvas.focus();
  return true;
}

// The commands' colours are 0-255, alpha too.
const rgba = (o, i) => `rgba(${o[i]},${o[i + 1]},${o[i + 2]},${o[i + 3] / 255})`;
// A box's pixels are those whose centre it holds (app/offscreen.cpp's rule).
const edge = (v) => Math.ceil(v - 0.5);

function paint(count) {
  const ops = new Float32Array(wasm.memory.buffer, wasm.web_ops(), count);
  const texts = readString(wasm.web_texts()).split('\n');
  ctx.fillStyle = '#fff';
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  ctx.font = "14px 'DejaVu Sans Mono', monospace";
  ctx.textBaseline = 'top';
  let t = 0;
  for (let i = 0; i < count;) {
    const op = ops[i];
    if (op === 1 || op === 2) {
      const x0 = edge(ops[i + 1]), y0 = edge(ops[i + 2]);
      const x1 = edge(ops[i + 1] + ops[i + 3]), y1 = edge(ops[i + 2] + ops[i + 4]);
      ctx.fillStyle = rgba(ops, i + 5);
      if (op === 1) ctx.fillRect(x0, y0, x1 - x0, y1 - y0);
      else {
        ctx.fillRect(x0, y0, x1 - x0, 1), ctx.fillRect(x0, y1 - 1, x1 - x0, 1);
        ctx.fillRect(x0, y0, 1, y1 - y0), ctx.fillRect(x1 - 1, y0, 1, y1 - y0);
      }
      i += 9;
    } else if (op === 3) {
      ctx.strokeStyle = rgba(ops, i + 5);
      ctx.lineWidth = 1;
      ctx.beginPath();
      ctx.moveTo(ops[i + 1] + 0.5, ops[i + 2] + 0.5);
      ctx.lineTo(ops[i + 3] + 0.5, ops[i + 4] + 0.5);
      ctx.stroke();
      i += 9;
    } else if (op === 4) {
      const s = texts[t++], x = ops[i + 1], y = ops[i + 2];
      ctx.fillStyle = 'rgba(255,255,255,0.667)';  // the window's pale backdrop
      ctx.fillRect(x, y, Math.ceil(ctx.measureText(s).width), 17);
      ctx.fillStyle = rgba(ops, i + 3);
      ctx.fillText(s, x, y + 1);
      i += 7;
    } else throw new Error(`bad draw command ${op} at ${i}`);
  }
}

function frame(now) {
  requestAnimationFrame(frame);
  if (!running) return;
  const elapsed = last ? now - last : 0;
  last = now;
  if (elapsed > 0) fps = 0.9 * fps + 0.1 * (1000 / elapsed);
  const t0 = performance.now();
  stats.steps += wasm.web_advance(elapsed);
  const count = wasm.web_draw(fps, drawMs);
  const t1 = performance.now();
  paint(count);
  const t2 = performance.now();
  drawMs = drawMs === 0 ? t2 - t1 : 0.9 * drawMs + 0.1 * (t2 - t1);
  stats.frames++, stats.wasmMs += t1 - t0, stats.paintMs += t2 - t1;
}

function send(kind, key = 0, x = 0, y = 0, button = 0) {
  if (!running) return;
  if (wasm.web_event(kind, key, x, y, button)) {
    running = false;
    status.textContent = 'quit (Esc or Q): pick a scene to start again';
  }
}
const at = (e) => [Math.round(e.offsetX * canvas.width / canvas.clientWidth),
                   Math.round(e.offsetY * canvas.height / canvas.clientHeight)];
canvas.addEventListener('keydown', (e) => {
  const k = sdlKey(e);
  if (!k) return;
  e.preventDefault();
  send(Kind.key, k);
});
canvas.addEventListener('keyup', (e) => { const k = sdlKey(e); if (k) e.preventDefault(), send(Kind.key_up, k); });
canvas.addEventListener('mousedown', (e) => { canvas.focus(); send(Kind.mouse_down, 0, ...at(e), e.button + 1); e.preventDefault(); });
canvas.addEventListener('mouseup', (e) => send(Kind.mouse_up, 0, ...at(e), e.button + 1));
canvas.addEventListener('mousemove', (e) => send(Kind.mouse_move, 0, ...at(e)));
// The wheel zooms the testbed's camera about the pointer, a notch a step.
canvas.addEventListener('wheel', (e) => { e.preventDefault(); if (e.deltaY) send(Kind.wheel, e.deltaY < 0 ? 1 : -1, ...at(e)); },
                        { passive: false });
canvas.addEventListener('contextmenu', (e) => e.preventDefault());
select.addEventListener('change', () => open(select.value));

async function start() {
  const list = await (await fetch('files.json')).json();  // scenes/*.json, scenes/maps/*, replays/*.log
  const files = {};
  await Promise.all(list.map(async (f) => { files[f] = new Uint8Array(await (await fetch(f)).arrayBuffer()); }));
  // A Tiled tileset (.tsj) is read by the maps that use it: not a scene of its own.
  const sceneFiles = list.filter((f) => f.startsWith('scenes/') && !f.endsWith('.tsj')).map((f) => f.slice(7));
  const wasi = new Wasi(files, (fd, line) => {
    if (captured && fd === 1) return void captured.push(line);
    (fd === 2 ? console.error : console.log)(line);
    if (fd === 2) errorBox.textContent += line + '\n';
  });
  const bytes = await (await fetch('physics.wasm')).arrayBuffer();
  const { instance } = await WebAssembly.instantiate(bytes, wasi.imports);
  wasm = instance.exports;
  wasi.memory = wasm.memory;
  wasm._initialize();
  const builtins = readString(wasm.web_builtins()).trim().split('\n');
  for (const name of [...builtins, ...sceneFiles.map((f) => `scenes/${f}`)])
    select.add(new Option(name.startsWith('scenes/') ? `${name.slice(7)} (file)` : name, name));
  const wanted = new URLSearchParams(location.search).get('scene') || 'many';
  select.value = wanted;
  if (!open(wanted)) open(select.value = 'many');  // the error stays shown
  status.textContent = '';
  requestAnimationFrame(frame);
}

// One of the module's headless runs (web_replay LOG, web_headless SCENE
// FRAMES), apart from the page's testbed: what it printed.
function run(name, arg, number) {
  const p = cString(arg);
  captured = [];
  try {
    wasm[name](p, ...(number === undefined ? [] : [number]));
    return captured.join('\n') + '\n';
  } finally {
    captured = null;
    wasm.web_free(p);
  }
}

// For the browser test (web/test/chromium_check.mjs): the state, the
// counters, the headless runs.
window.physics = { state: () => state(), stats, run, ready: start().catch((e) => {
  errorBox.textContent += `${e.message}\n`;
  throw e;
}) };
