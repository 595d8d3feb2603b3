// A dump of `fragsim run --dump-control` (format: src/experiments/control_dump.hpp) read into
// what the JavaScript API takes: the controller def, and per step the camera's constants, the
// step input and the fragments as typed arrays, with the tool's forces. Runs in Node and in a
// browser (it reads an ArrayBuffer), for the replay test and the benchmarks.

// `fragsim` gives the def's layout: the def's numbers are read at this module's offsets, which
// are the tool's too, since they precede every pointer of the struct (tests/control/replay.c,
// read_def, says why). The layout is the package's own (a private field: the public API takes
// plain objects). Float is Float64Array or Float32Array: the fragments' arrays.
export function readControlDump(buffer, fragsim, Float = Float64Array) {
  const bytes = new Uint8Array(buffer);
  const data = new DataView(buffer);
  let at = 0;
  const u32 = () => { const v = data.getUint32(at, true); at += 4; return v; };
  const i32 = () => { const v = data.getInt32(at, true); at += 4; return v; };
  const f64 = () => { const v = data.getFloat64(at, true); at += 8; return v; };
  const vec = () => [f64(), f64(), f64()];
  const pad8 = (n) => (8 - (n % 8)) % 8;

  if (String.fromCharCode(...bytes.subarray(0, 8)) !== 'FSCDUMP2') throw new Error('not a control dump');
  at = 8;
  if (u32() !== 0x01020304) throw new Error('a control dump of another byte order');
  const defSize = u32();
  const stepCount = u32();
  u32();
  const defAt = at;
  at += defSize + pad8(defSize);

  const def = {};
  for (const f of fragsim._layout.controller_def.fields) {
    let value;
    if (f.kind === 'f64') value = data.getFloat64(defAt + f.offset, true);
    else if (f.kind === 'i32') {
      value = data.getInt32(defAt + f.offset, true);
      if (f.names) value = f.names[value];
    } else if (f.kind === 'f64x4') {
      value = [0, 1, 2, 3].map((k) => data.getFloat64(defAt + f.offset + 8 * k, true));
    } else continue;
    let node = def;
    for (const key of f.keys.slice(0, -1)) node = node[key] ??= {};
    node[f.keys.at(-1)] = value;
  }

  const steps = [];
  for (let s = 0; s < stepCount; ++s) {
    i32();
    const n = i32();
    const forceCount = i32();
    i32();
    const c = Array.from({ length: 32 }, f64);
    let camera = { fovyDeg: c[15], aspect: c[16], nearM: c[17], farM: c[18], maxSpeedMps: c[22],
      maxAccelMps2: c[23], maxTurnDegps: c[24], bodyHalfM: c.slice(25, 28) };
    // One object while the constants stay (they do, in the tool's runs): a replay sets them anew
    // only when the object changes.
    const previous = steps.at(-1)?.camera;
    if (previous && JSON.stringify(previous) === JSON.stringify(camera)) camera = previous;
    // The tool's world is y-up: the dump carries no normal.
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
    at += n + pad8(n);
    const expected = new Float64Array(3 * n);
    for (let k = 0; k < forceCount; ++k) {
      const which = i32();
      i32();
      expected.set(vec(), 3 * which);
    }
    steps.push({ camera, input, fragments, expected, count: n });
  }
  if (at !== bytes.length) throw new Error(`the dump has ${bytes.length - at} bytes past its last step`);
  return { def, steps };
}

// The steps replayed by a new controller: the camera's constants set when they change, forces
// into one array per step. `onStep(step, stats, forces)` sees each answer. Returns the time the
// loop of calls took, in milliseconds, timed as a whole: a browser's performance.now() is coarse
// (100 us in Chromium for a page that is not cross-origin isolated), longer than many steps.
export function replayControlDump(fragsim, dump, onStep = () => {}) {
  const ctl = fragsim.createController(dump.def);
  const forces = dump.steps.map((step) => new step.fragments.position.constructor(3 * step.count));
  try {
    let camera = null;
    const started = performance.now();
    dump.steps.forEach((step, s) => {
      if (step.camera !== camera) {
        ctl.setCameras([step.camera]);
        camera = step.camera;
      }
      onStep(step, ctl.step(step.input, step.fragments, forces[s]), forces[s]);
    });
    return performance.now() - started;
  } finally {
    ctl.dispose();
  }
}

// The median over `repeats` replays (each with a new controller) of the time per fragment and
// step, in nanoseconds: the JavaScript API's cost, the copies in and out included.
export function timeControlDump(fragsim, dump, repeats) {
  const fragmentSteps = dump.steps.reduce((sum, step) => sum + step.count, 0);
  const ms = Array.from({ length: repeats }, () => replayControlDump(fragsim, dump)).sort((a, b) => a - b);
  return (1e6 * ms[Math.floor(repeats / 2)]) / fragmentSteps;
}
