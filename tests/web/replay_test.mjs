// The WebAssembly library against the native one on a dump of `fragsim run --dump-control`
// (format: src/experiments/control_dump.hpp):
//  1. tests/control/replay.c built both ways (the native control_replay, and replay.cjs from
//     scripts/web_build.sh) through structs, double arrays and float arrays: each must match the
//     tool's forces bit for bit (doubles) and print the same digest of every force and stat;
//  2. the JavaScript API (fragsim.mjs) replaying the same steps from Float64Arrays (the tool's
//     forces bit for bit, and the native digest) and Float32Arrays (the native float digest).
//
//   node tests/web/replay_test.mjs NATIVE_REPLAY WASM_REPLAY_CJS PACKAGE_DIR DUMP
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

import { readControlDump, replayControlDump } from './control_dump.mjs';

const [nativeReplay, wasmReplay, packageDir, dumpPath] = process.argv.slice(2);
if (!dumpPath) throw new Error('usage: replay_test.mjs NATIVE_REPLAY WASM_REPLAY_CJS PACKAGE_DIR DUMP');
const name = path.basename(dumpPath);

// 1. The C replay, native and WebAssembly.
const printed = {};
for (const mode of ['structs', 'arrays', 'floats']) {
  const flags = mode === 'structs' ? [] : [`--${mode}`];
  const native = execFileSync(nativeReplay, [dumpPath, ...flags], { encoding: 'utf8' }).trim();
  const wasm = execFileSync(process.execPath, [wasmReplay, dumpPath, ...flags], { encoding: 'utf8' }).trim();
  assert.match(native, / 0 mismatches /, `native ${mode}`);
  assert.equal(wasm, native, `${name} ${mode}: WebAssembly and native print the same`);
  printed[mode] = native.match(/digest ([0-9a-f]{8})/)[1];
  console.log(`${name} ${mode}: native and WebAssembly alike: ${wasm}`);
}

// 2. The JavaScript API.
const api = await import(pathToFileURL(path.resolve(packageDir, 'fragsim.mjs')).href);
const fragsim = await api.default();

// 32-bit FNV-1a, as replay.c's digest.
const fnv = (h, view) => {
  for (let i = 0; i < view.length; ++i) h = Math.imul(h ^ view[i], 16777619) >>> 0;
  return h;
};
const statsBytes = (stats) => new Uint8Array(Int32Array.from(Object.values(stats)).buffer);

const bytes = readFileSync(dumpPath);
const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
for (const Float of [Float64Array, Float32Array]) {
  const dump = readControlDump(buffer, fragsim, Float);
  let digest = 2166136261;
  let mismatches = 0;
  let pushes = 0;
  replayControlDump(fragsim, dump, (step, stats, forces) => {
    digest = fnv(digest, statsBytes(stats));
    digest = fnv(digest, new Uint8Array(forces.buffer));
    pushes += stats.pushed;
    if (Float === Float64Array) {
      const got = new BigUint64Array(forces.buffer);
      const want = new BigUint64Array(step.expected.buffer);
      for (let i = 0; i < got.length; ++i) if (got[i] !== want[i]) ++mismatches;
    }
  });
  const mode = Float === Float64Array ? 'structs' : 'floats';
  const hex = digest.toString(16).padStart(8, '0');
  assert.equal(mismatches, 0, `${name}: the JavaScript API's ${Float.name} forces are the tool's`);
  assert.equal(hex, printed[mode], `${name}: the JavaScript API's ${Float.name} digest is the native ${mode} one`);
  console.log(`${name} JavaScript API, ${Float.name}: ${dump.steps.length} steps, ${pushes} pushes, ` +
    `0 mismatches, digest ${hex} as native`);
}
