// Runs a WASI command module (a main) under Node's WASI, its stdout into a
// file: node wasi_run.mjs MODULE.wasm OUT
import { WASI } from 'node:wasi';
import { readFileSync, openSync } from 'node:fs';

const [module, out] = process.argv.slice(2);
const wasi = new WASI({ version: 'preview1', stdout: openSync(out, 'w'), returnOnExit: true });
const instance = await WebAssembly.instantiate(await WebAssembly.compile(readFileSync(module)), wasi.getImportObject());
process.exit(wasi.start(instance));
