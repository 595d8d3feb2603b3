// The JavaScript API of the WebAssembly library (src/web/package/fragsim.mjs), in Node:
// defaults as the C API's, refusals as FragsimErrors carrying the library's reason, a force
// computed by hand, the two id and two float types, growth of the module's memory, and an
// allocation failure caught inside the library (WebAssembly exception handling).
//
//   node tests/web/api_test.mjs PACKAGE_DIR
import test from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const packageDir = process.argv[2];
if (!packageDir) throw new Error('usage: api_test.mjs PACKAGE_DIR');
const api = await import(pathToFileURL(path.resolve(packageDir, 'fragsim.mjs')).href);
const fragsim = await api.default();

// One fragment 2 m ahead of the default camera (at the origin, looking down -z) and 0.5 m to its
// right, closing at 5 m/s: deflect-all pushes it straight away from the view axis, +x, with
// mass * accel_mps2 = 2 kg * 60 m/s^2 = 120 N, exactly (the offset across the axis is (0.5, 0, 0),
// whose direction is (1, 0, 0) with no rounding).
function oneFragment(Float, Id = Uint32Array) {
  return {
    position: new Float([0.5, 0, -2]),
    velocity: new Float([0, 0, 5]),
    radius: new Float([0.1]),
    mass: new Float([2]),
    id: Id === BigUint64Array ? new BigUint64Array([7n]) : new Id([7]),
  };
}
const noGravity = { gravityMps2: [0, 0, 0], cameras: [{}] };

test('the defaults are the C API defaults', () => {
  const def = fragsim.defaultControllerDef();
  assert.equal(fragsim.version, '1.0.0');
  assert.equal(def.strategy, 'edge-min');
  assert.equal(def.edgeMin.aMaxMps2, 50);
  assert.equal(def.edgeMin.marginM, 0.05);
  assert.equal(def.edgeMin.cameraModel, 'bounded_accel');
  assert.equal(def.edgeMin.cameraTurnDegps, Infinity);
  assert.deepEqual(def.edgeMin.edgeWeights, [1, 1, 1, 1]);
  assert.equal(def.edge.kNms2, 1);
  assert.equal(def.edge.replan, 'never');
  assert.equal(def.deflectAll.accelMps2, 60);
  assert.equal(def.horizonCapS, 3);
  assert.equal('allocFn' in def, false, 'the allocator hook is not for JavaScript');
  const camera = fragsim.defaultCameraDef();
  assert.equal(camera.maxSpeedMps, 3);
  assert.equal(camera.maxAccelMps2, -1);
  assert.deepEqual(camera.bodyHalfM, { x: 0.15, y: 0.1, z: 0.15 });
  assert.deepEqual(fragsim.defaultCameraPose().forward, { x: 0, y: 0, z: -1 });
  const input = fragsim.defaultStepInput();
  assert.equal(input.dtS, 1 / 60);
  assert.equal(input.groundHeightM, -Infinity);
  assert.deepEqual(input.gravityMps2, { x: 0, y: -9.81, z: 0 });
});

test('deflect-all pushes a fragment by mass times acceleration, away from the view axis', () => {
  for (const Float of [Float64Array, Float32Array]) {
    for (const Id of [Uint32Array, BigUint64Array]) {
      const ctl = fragsim.createController({ strategy: 'deflect-all' });
      ctl.setCameras([{}]);
      const forces = new Float(3).fill(NaN);
      const stats = ctl.step(noGravity, oneFragment(Float, Id), forces);
      assert.deepEqual(Array.from(forces), [120, 0, 0], `${Float.name}, ${Id.name}`);
      assert.equal(stats.pushed, 1);
      assert.equal(stats.newIds, 1);
      assert.equal(stats.warnings, 0);
      ctl.dispose();
    }
  }
});

test('a fragment beyond range_m, or moving away, gets no force', () => {
  const ctl = fragsim.createController({ strategy: 'deflect-all', deflectAll: { rangeM: 1.5 } });
  ctl.setCameras([{}]);
  const forces = new Float64Array(3).fill(NaN);
  assert.equal(ctl.step(noGravity, oneFragment(Float64Array), forces).pushed, 0);
  assert.deepEqual(Array.from(forces), [0, 0, 0]);
  ctl.dispose();
});

test('ids carry the controller state between steps: a returning id is not new', () => {
  const ctl = fragsim.createController({ strategy: 'deflect-all' });
  ctl.setCameras([{}]);
  const forces = new Float64Array(3);
  assert.equal(ctl.step(noGravity, oneFragment(Float64Array), forces).newIds, 1);
  assert.equal(ctl.step(noGravity, oneFragment(Float64Array), forces).newIds, 0);
  ctl.reset();
  assert.equal(ctl.step(noGravity, oneFragment(Float64Array), forces).newIds, 1);
  ctl.dispose();
});

test('refusals throw FragsimErrors with the library reason, and the controller stays usable', () => {
  assert.throws(() => fragsim.createController({ edgeMin: { aMaxMps2: -1 } }), (e) =>
    e instanceof api.FragsimError && e.status === 'invalid argument' && e.code === 3 &&
    /a_max_mps2/.test(e.message) && /-1/.test(e.message));
  const ctl = fragsim.createController();
  const forces = new Float64Array(3);
  assert.throws(() => ctl.step(noGravity, oneFragment(Float64Array), forces), (e) =>
    e instanceof api.FragsimError && /camera/.test(e.message));
  assert.throws(() => ctl.setCameras([{ aspect: 0 }]), (e) =>
    e instanceof api.FragsimError && /cameras\[0\]/.test(e.message) && /aspect/.test(e.message));
  ctl.setCameras([{}]);
  // Two poses for one camera: refused, and the forces are zeroed as the C call zeroes them.
  forces.fill(NaN);
  assert.throws(() => ctl.step({ cameras: [{}, {}] }, oneFragment(Float64Array), forces),
    api.FragsimError);
  assert.deepEqual(Array.from(forces), [0, 0, 0]);
  const twice = {
    position: new Float64Array([0.5, 0, -2, 0.5, 0, -2]),
    velocity: new Float64Array([0, 0, 5, 0, 0, 5]),
    radius: new Float64Array([0.1, 0.1]),
    mass: new Float64Array([2, 2]),
    id: new Uint32Array([7, 7]),
  };
  assert.throws(() => ctl.step(noGravity, twice, new Float64Array(6)), (e) =>
    e instanceof api.FragsimError && e.code === 4 &&
    e.message === 'fragsim: step: fragments[1].id = 7: the id of fragments[0] too');
  ctl.step(noGravity, oneFragment(Float64Array), forces);
  ctl.dispose();
  assert.equal(ctl.disposed, true);
  assert.throws(() => ctl.step(noGravity, oneFragment(Float64Array), forces), (e) =>
    e instanceof api.FragsimError && /disposed/.test(e.message));
  ctl.dispose(); // twice: nothing to do
});

test('wrong JavaScript values are TypeErrors naming the field', () => {
  assert.throws(() => fragsim.createController({ strategy: 'edgemin' }),
    /def.strategy is "edgemin"; one of edge-min, edge, deflect-all/);
  assert.throws(() => fragsim.createController({ edgeMin: { marginm: 1 } }),
    /def.edgeMin.marginm is not a field/);
  assert.throws(() => fragsim.createController({ horizonCapS: '3' }), /def.horizonCapS must be a number/);
  const ctl = fragsim.createController();
  ctl.setCameras([{}]);
  const f = oneFragment(Float64Array);
  assert.throws(() => ctl.step(noGravity, { ...f, radius: new Float32Array([0.1]) }, new Float64Array(3)),
    /fragments.radius must be a Float64Array/);
  assert.throws(() => ctl.step(noGravity, f, new Float32Array(3)), /forces must be a Float64Array/);
  assert.throws(() => ctl.step(noGravity, f, new Float64Array(2)), /forces has 2 numbers; 1 fragments need 3/);
  assert.throws(() => ctl.step(noGravity, { ...f, id: [7] }, new Float64Array(3)),
    /fragments.id must be a BigUint64Array or a Uint32Array/);
  assert.throws(() => ctl.step({ cameras: [{ eyeM: [0, 0] }] }, f, new Float64Array(3)),
    /input.cameras\[0\].eyeM must have 3 numbers/);
  assert.throws(() => ctl.setCameras([]), /1 to 8 cameras/);
  ctl.dispose();
});

test('an allocation the module cannot make is FRAGSIM_ERROR_OUT_OF_MEMORY, not an abort', () => {
  const ctl = fragsim.createController();
  ctl.setCameras([{}]);
  // 536,870,911 fragments' work space is far beyond WebAssembly's 2 GiB: std::bad_alloc, thrown
  // and caught inside the library.
  assert.throws(() => ctl.reserve(api.MAX_FRAGMENTS), (e) =>
    e instanceof api.FragsimError && e.status === 'out of memory' && e.code === 5);
  const forces = new Float64Array(3);
  ctl.step(noGravity, oneFragment(Float64Array), forces);
  ctl.dispose();
});

test('many fragments grow the module memory; the views follow it', () => {
  const n = 20000;
  const ctl = fragsim.createController({ strategy: 'deflect-all' });
  ctl.setCameras([{}]);
  const f = {
    position: new Float64Array(3 * n), velocity: new Float64Array(3 * n),
    radius: new Float64Array(n).fill(0.1), mass: new Float64Array(n).fill(2),
    id: new Uint32Array(n).map((_, i) => i),
  };
  for (let i = 0; i < n; ++i) {
    f.position.set([0.5, 0, -2 - i * 1e-4], 3 * i);
    f.velocity.set([0, 0, 5], 3 * i);
  }
  const forces = new Float64Array(3 * n);
  const stats = ctl.step(noGravity, f, forces);
  assert.equal(stats.pushed, n);
  assert.deepEqual(Array.from(forces.subarray(3 * (n - 1))), [120, 0, 0]);
  ctl.dispose();
});
