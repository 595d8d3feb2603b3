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

const bytes = readFileSync(dumpPath);
const data = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
let at = 0;
const u32 = () => { const v = data.getUint32(at, true); at += 4; return v; };
const i32 = () => { const v = data.getInt32(at, true); at += 4; return v; };
const f64 = () => { const v = data.getFloat64(at, true); at += 8; return v; };
const vec = () => [f64(), f64(), f64()];
assert.equal(bytes.subarray(0, 8).toString('latin1'), 'FSCDUMP2');
at = 8;
assert.equal(u32(), 0x01020304);
const defSize = u32();
const stepCount = u32();
u32();
const defAt = at;
at += defSize + ((8 - (defSize % 8)) % 8);

// The def's numbers, by this module's offsets: they precede every pointer of the struct and lie
// at the same offsets in the tool's 64-bit def (tests/control/replay.c, read_def, says why). The
// layout is the package's own (a private field: the public API takes plain objects).
const layout = fragsim._layout.controller_def;
const def = {};
for (const f of layout.fields) {
  let value;
  if (f.kind === 'f64') value = data.getFloat64(defAt + f.offset, true);
  else if (f.kind === 'i32') {
    value = data.getInt32(defAt + f.offset, true);
    if (f.names) value = f.names[value];
  }
  else if (f.kind === 'f64x4') value = [0, 1, 2, 3].map((k) => data.getFloat64(defAt + f.offset + 8 * k, true));
  else continue;
  let node = def;
  for (const key of f.keys.slice(0, -1)) node = node[key] ??= {};
  node[f.keys.at(-1)] = value;
}

// 32-bit FNV-1a, as replay.c's digest.
const fnv = (h, view) => {
  for (let i = 0; i < view.length; ++i) h = Math.imul(h ^ view[i], 16777619) >>> 0;
  return h;
};
const statsBytes = (stats) => new Uint8Array(Int32Array.from(Object.values(stats)).buffer);

for (const Float of [Float64Array, Float32Array]) {
  const ctl = fragsim.createController(def);
  at = defAt + defSize + ((8 - (defSize % 8)) % 8);
  let digest = 2166136261;
  let cameraKey = '';
  let mismatches = 0;
  let nonzero = 0;
  for (let s = 0; s < stepCount; ++s) {
    i32();
    const n = i32();
    const forceCount = i32();
    i32();
    const c = Array.from({ length: 32 }, f64);
    const camera = { fovyDeg: c[15], aspect: c[16], nearM: c[17], farM: c[18], maxSpeedMps: c[22],
      maxAccelMps2: c[23], maxTurnDegps: c[24], bodyHalfM: c.slice(25, 28) };
    if (JSON.stringify(camera) !== cameraKey) {
      ctl.setCameras([camera]);
      cameraKey = JSON.stringify(camera);
    }
    const input = { timeS: c[0], dtS: c[1], endTimeS: c[2], gravityMps2: c.slice(28, 31),
      groundHeightM: c[31], groundNormal: [0, 1, 0],
      cameras: [{ eyeM: c.slice(3, 6), right: c.slice(6, 9), up: c.slice(9, 12),
        forward: c.slice(12, 15), velocityMps: c.slice(19, 22) }] };
    const fragments = { position: new Float(3 * n), velocity: new Float(3 * n), radius: new Float(n),
      mass: new Float(n), id: new Uint32Array(n).map((_, i) => i), touched: new Uint8Array(n) };
    for (let i = 0; i < n; ++i) {
      fragments.position.set(vec(), 3 * i);
      fragments.velocity.set(vec(), 3 * i);
      fragments.radius[i] = f64();
      fragments.mass[i] = f64();
    }
    fragments.touched.set(bytes.subarray(at, at + n));
    at += n + ((8 - (n % 8)) % 8);
    const expected = new Float64Array(3 * n);
    for (let k = 0; k < forceCount; ++k) {
      const which = i32();
      i32();
      expected.set(vec(), 3 * which);
    }
    const forces = new Float(3 * n);
    const stats = ctl.step(input, fragments, forces);
    digest = fnv(digest, statsBytes(stats));
    digest = fnv(digest, new Uint8Array(forces.buffer));
    nonzero += stats.pushed;
    if (Float === Float64Array) {
      const got = new BigUint64Array(forces.buffer);
      const want = new BigUint64Array(expected.buffer);
      for (let i = 0; i < 3 * n; ++i) if (got[i] !== want[i]) ++mismatches;
    }
  }
  assert.equal(at, bytes.length, 'the whole dump was read');
  ctl.dispose();
  const mode = Float === Float64Array ? 'structs' : 'floats';
  const hex = digest.toString(16).padStart(8, '0');
  assert.equal(mismatches, 0, `${name}: the JavaScript API's ${Float.name} forces are the tool's`);
  assert.equal(hex, printed[mode], `${name}: the JavaScript API's ${Float.name} digest is the native ${mode} one`);
  console.log(`${name} JavaScript API, ${Float.name}: ${stepCount} steps, ${nonzero} pushes, ` +
    `0 mismatches, digest ${hex} as native`);
}
