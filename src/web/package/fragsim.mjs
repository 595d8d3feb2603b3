// fragsim-control for JavaScript: the controller library (libfragsim_control) compiled to
// WebAssembly, behind an API over plain objects and typed arrays. The C API's rules hold as they
// are (fragsim/control.h); this file only turns JavaScript values into its structs and back.
//
// Names: every C field in camelCase, units kept (max_speed_mps is maxSpeedMps); enums as the
// strings fragsim's scene keys use ('edge-min', 'bounded_accel'); a vec3 as {x, y, z} (a three.js
// Vector3 is one) or [x, y, z]. The structs' layout is read from the module itself
// (fragsim_web_layout), so nothing here repeats the C declarations.

import createModule from './fragsim_control_wasm.mjs';

const ENUMS = {
  strategy: ['edge-min', 'edge', 'deflect-all'],
  'edge_min.camera_model': ['constant', 'bounded_accel', 'reachable'],
  'edge.predictor': ['thesis', 'discrete'],
  'edge.reach': ['thesis', 'growing'],
  'edge.horizon': ['camera', 'ground'],
  'edge.replan': ['never', 'contact', 'always'],
};

// The C fields JavaScript does not set: the game's allocator and task system (a WebAssembly
// module has one thread and its own heap) and the def's defaulted mark.
const HIDDEN = new Set(['alloc_fn', 'camera_poses', 'camera_count']);

export const Warning = Object.freeze({
  CAMERA_OVER_SPEED: 1,
  FOVY_IN_RADIANS: 2,
  BELOW_GROUND: 4,
  UNPROTECTED: 8,
  SKIPPED: 16,
});

export const MAX_CAMERAS = 8;
export const MAX_FRAGMENTS = 536870911;

// A refused call: message is the library's own reason, status its short name
// ('invalid argument'), code the fragsim_status number.
export class FragsimError extends Error {
  constructor(message, status, code) {
    super(message);
    this.name = 'FragsimError';
    this.status = status;
    this.code = code;
  }
}

const camel = (name) => name.replace(/_([a-zA-Z0-9])/g, (_, c) => c.toUpperCase());

// One C struct as this build lays it out: reads it into a plain object and writes a plain
// object's fields over it, by offset.
class StructLayout {
  constructor(name, spec) {
    this.name = name;
    this.size = spec.size;
    this.fields = Object.entries(spec.fields)
      .filter(([path]) => !HIDDEN.has(path))
      .map(([path, [offset, kind]]) => ({
        path,
        keys: path.split('.').map(camel),
        offset,
        kind,
        names: ENUMS[path],
      }));
  }

  read(heap, at) {
    const out = {};
    for (const f of this.fields) {
      let node = out;
      for (const key of f.keys.slice(0, -1)) node = node[key] ??= {};
      node[f.keys.at(-1)] = readField(heap, at + f.offset, f);
    }
    return out;
  }

  // Writes the fields `value` names; refuses a key this struct does not have, so that a typo is
  // an error and not a silently ignored setting.
  write(heap, at, value, where) {
    checkKeys(value, this.fields, 0, where);
    for (const f of this.fields) {
      let node = value;
      for (const key of f.keys) {
        if (node === undefined || node === null) break;
        node = node[key];
      }
      if (node !== undefined) writeField(heap, at + f.offset, f, node, `${where}.${f.keys.join('.')}`);
    }
  }
}

function checkKeys(value, fields, depth, where) {
  if (value === null || typeof value !== 'object') {
    throw new TypeError(`fragsim: ${where} must be an object`);
  }
  for (const key of Object.keys(value)) {
    const below = fields.filter((f) => f.keys[depth] === key);
    if (below.length === 0) {
      throw new TypeError(`fragsim: ${where}.${key} is not a field of this struct`);
    }
    const leaf = below.find((f) => f.keys.length === depth + 1);
    if (!leaf && value[key] !== undefined) checkKeys(value[key], below, depth + 1, `${where}.${key}`);
  }
}

function readField(heap, at, f) {
  switch (f.kind) {
    case 'f64':
      return heap.f64[at >> 3];
    case 'i32':
      return f.names ? f.names[heap.i32[at >> 2]] : heap.i32[at >> 2];
    case 'u32':
      return heap.u32[at >> 2];
    case 'vec3':
      return { x: heap.f64[at >> 3], y: heap.f64[(at >> 3) + 1], z: heap.f64[(at >> 3) + 2] };
    case 'f64x4':
      return Array.from(heap.f64.subarray(at >> 3, (at >> 3) + 4));
    default:
      throw new Error(`fragsim: no reader for ${f.kind}`);
  }
}

function number(value, where) {
  if (typeof value !== 'number') throw new TypeError(`fragsim: ${where} must be a number`);
  return value;
}

function writeField(heap, at, f, value, where) {
  switch (f.kind) {
    case 'f64':
      heap.f64[at >> 3] = number(value, where);
      return;
    case 'i32': {
      if (f.names) {
        const index = f.names.indexOf(value);
        if (index < 0) {
          throw new TypeError(`fragsim: ${where} is ${JSON.stringify(value)}; one of ${f.names.join(', ')}`);
        }
        heap.i32[at >> 2] = index;
      } else {
        if (!Number.isInteger(value) || value < -2147483648 || value > 2147483647) {
          throw new TypeError(`fragsim: ${where} must be a 32-bit integer`);
        }
        heap.i32[at >> 2] = value;
      }
      return;
    }
    case 'vec3': {
      const v = Array.isArray(value) || ArrayBuffer.isView(value) ? value : [value?.x, value?.y, value?.z];
      if (v.length !== 3) throw new TypeError(`fragsim: ${where} must have 3 numbers`);
      for (let i = 0; i < 3; ++i) heap.f64[(at >> 3) + i] = number(v[i], `${where}[${i}]`);
      return;
    }
    case 'f64x4': {
      if (!value || value.length !== 4) throw new TypeError(`fragsim: ${where} must have 4 numbers`);
      for (let i = 0; i < 4; ++i) heap.f64[(at >> 3) + i] = number(value[i], `${where}[${i}]`);
      return;
    }
    default:
      throw new Error(`fragsim: no writer for ${f.kind}`);
  }
}

// The module's memory as typed views, made again after the memory grows (growing detaches the
// old ones).
class Heap {
  constructor(module) {
    this.module = module;
    this.buffer = null;
    this.refresh();
  }
  refresh() {
    const buffer = this.module.HEAPU8.buffer;
    if (buffer === this.buffer) return this;
    this.buffer = buffer;
    this.u8 = new Uint8Array(buffer);
    this.i32 = new Int32Array(buffer);
    this.u32 = new Uint32Array(buffer);
    this.f32 = new Float32Array(buffer);
    this.f64 = new Float64Array(buffer);
    this.u64 = new BigUint64Array(buffer);
    return this;
  }
}

const align = (n, to) => Math.ceil(n / to) * to;

export class Controller {
  // Made by Fragsim.createController only.
  constructor(fragsim, index1, generation) {
    this._fragsim = fragsim;
    this._index1 = index1;
    this._generation = generation;
    const L = fragsim._layout;
    // One block for what a call passes besides the fragments: the step input, the poses, the
    // arrays, the stats, the cameras' constants.
    this._inputAt = 0;
    this._posesAt = align(L.step_input.size, 8);
    this._arraysAt = this._posesAt + MAX_CAMERAS * L.camera_pose.size;
    this._statsAt = align(this._arraysAt + L.fragment_arrays.size, 8);
    this._camerasAt = align(this._statsAt + L.step_stats.size, 8);
    this._block = fragsim._malloc(this._camerasAt + MAX_CAMERAS * L.camera_def.size);
    this._fragmentsAt = 0;
    this._fragmentBytes = 0;
  }

  get disposed() {
    return this._block === 0;
  }

  // The constants of the controller's cameras (fragsim_controller_set_cameras): an array of 1 to
  // 8 objects, each started from the default camera def.
  setCameras(cameras) {
    const fs = this._live('setCameras');
    if (!Array.isArray(cameras) || cameras.length < 1 || cameras.length > MAX_CAMERAS) {
      throw new TypeError(`fragsim: setCameras takes an array of 1 to ${MAX_CAMERAS} cameras`);
    }
    const L = fs._layout;
    const heap = fs._heap.refresh();
    cameras.forEach((camera, i) => {
      const at = this._block + this._camerasAt + i * L.camera_def.size;
      fs._module._fragsim_web_default_camera_def(at);
      L.camera_def.write(heap, at, camera, `cameras[${i}]`);
    });
    this._check('setCameras', fs._module._fragsim_web_set_cameras(this._index1, this._generation,
      this._block + this._camerasAt, cameras.length));
  }

  // Room for count fragments now (fragsim_controller_reserve), so that the explosion's step does
  // not grow the controller.
  reserve(count) {
    const fs = this._live('reserve');
    if (!Number.isInteger(count)) throw new TypeError('fragsim: reserve takes an integer count');
    this._check('reserve', fs._module._fragsim_web_reserve(this._index1, this._generation, count));
  }

  // Forgets every fragment (fragsim_controller_reset).
  reset() {
    const fs = this._live('reset');
    this._check('reset', fs._module._fragsim_web_reset(this._index1, this._generation));
  }

  // One physics step (fragsim_controller_step_arrays). `input`: the step input's fields (timeS,
  // dtS, gravityMps2, ...) and `cameras`, one pose per camera set. `fragments`: per-field typed
  // arrays, all Float32Array or all Float64Array: position and velocity (x, y, z per fragment),
  // radius, mass; id as a BigUint64Array or a Uint32Array; touched, optional, a Uint8Array.
  // `forces` (the same float type, 3 per fragment) receives the force on each fragment, in
  // newtons. The arrays are copied into the module's memory and the forces out of it in one bulk
  // copy each: no JavaScript runs per fragment. Returns the step's stats.
  step(input, fragments, forces) {
    const fs = this._live('step');
    const L = fs._layout;
    const m = fs._module;
    if (fragments === null || typeof fragments !== 'object') {
      throw new TypeError('fragsim: step takes (input, fragments, forces)');
    }
    const { position, velocity, radius, mass, id, touched } = fragments;
    const count = fragments.count ?? radius?.length;
    if (!Number.isInteger(count) || count < 0 || count > MAX_FRAGMENTS) {
      throw new TypeError('fragsim: fragments.count (or radius.length) must be a count of fragments');
    }
    const Float = position instanceof Float64Array ? Float64Array
      : position instanceof Float32Array ? Float32Array : null;
    if (Float === null) throw new TypeError('fragsim: fragments.position must be a Float32Array or Float64Array');
    const scalar = Float.BYTES_PER_ELEMENT;
    for (const [name, array, per] of [['position', position, 3], ['velocity', velocity, 3],
      ['radius', radius, 1], ['mass', mass, 1], ['forces', forces, 3]]) {
      const where = name === 'forces' ? 'forces' : `fragments.${name}`;
      if (!(array instanceof Float)) throw new TypeError(`fragsim: ${where} must be a ${Float.name}, as fragments.position is`);
      if (array.length < per * count) throw new RangeError(`fragsim: ${where} has ${array.length} numbers; ${count} fragments need ${per * count}`);
    }
    if (!(id instanceof BigUint64Array || id instanceof Uint32Array)) {
      throw new TypeError('fragsim: fragments.id must be a BigUint64Array or a Uint32Array');
    }
    if (id.length < count) throw new RangeError(`fragsim: fragments.id has ${id.length} ids; ${count} fragments need ${count}`);
    if (touched !== undefined && !(touched instanceof Uint8Array && touched.length >= count)) {
      throw new TypeError(`fragsim: fragments.touched must be a Uint8Array of at least ${count}`);
    }
    if (input === null || typeof input !== 'object' || !Array.isArray(input.cameras)) {
      throw new TypeError('fragsim: input.cameras must be an array of camera poses');
    }
    if (input.cameras.length > MAX_CAMERAS) {
      throw new RangeError(`fragsim: input.cameras has ${input.cameras.length} poses; at most ${MAX_CAMERAS}`);
    }

    // The fragments' block: ids first (8-byte aligned), then the floats, then touched.
    const vec = 3 * count * scalar;
    const need = 8 * count + 3 * vec + 2 * count * scalar + count + 8;
    if (need > this._fragmentBytes) {
      // Grown by doubling, so that a count that creeps up does not reallocate every step.
      const bytes = Math.max(need, 2 * this._fragmentBytes);
      if (this._fragmentsAt !== 0) m._free(this._fragmentsAt);
      this._fragmentsAt = 0;
      this._fragmentBytes = 0;
      const at = m._malloc(bytes);
      if (at === 0) throw new FragsimError('fragsim: step: out of memory for the fragments', 'out of memory', 5);
      this._fragmentsAt = at;
      this._fragmentBytes = bytes;
    }
    const heap = fs._heap.refresh();
    const idAt = align(this._fragmentsAt, 8);
    const positionAt = idAt + 8 * count;
    const velocityAt = positionAt + vec;
    const forceAt = velocityAt + vec;
    const radiusAt = forceAt + vec;
    const massAt = radiusAt + count * scalar;
    const touchedAt = massAt + count * scalar;
    const floats = Float === Float64Array ? heap.f64 : heap.f32;
    const shift = Float === Float64Array ? 3 : 2;
    floats.set(position.subarray(0, 3 * count), positionAt >> shift);
    floats.set(velocity.subarray(0, 3 * count), velocityAt >> shift);
    floats.set(radius.subarray(0, count), radiusAt >> shift);
    floats.set(mass.subarray(0, count), massAt >> shift);
    if (id instanceof BigUint64Array) {
      heap.u64.set(id.subarray(0, count), idAt >> 3);
    } else {
      // The 32-bit ids go in at the forces' place and are widened in one call.
      heap.u32.set(id.subarray(0, count), forceAt >> 2);
      m._fragsim_web_widen_ids(forceAt, idAt, count);
    }
    if (touched) heap.u8.set(touched.subarray(0, count), touchedAt);
    else heap.u8.fill(0, touchedAt, touchedAt + count);

    const arraysAt = this._block + this._arraysAt;
    const A = L.fragment_arrays.offsets;
    m._fragsim_web_default_fragment_arrays(arraysAt);
    const u32 = heap.u32;
    const set = (field, value) => { u32[(arraysAt + A[field]) >> 2] = value; };
    set('position_m', positionAt); set('position_stride_bytes', 3 * scalar);
    set('velocity_mps', velocityAt); set('velocity_stride_bytes', 3 * scalar);
    set('radius_m', radiusAt); set('radius_stride_bytes', scalar);
    set('mass_kg', massAt); set('mass_stride_bytes', scalar);
    set('id', idAt); set('id_stride_bytes', 8);
    set('touched', touchedAt); set('touched_stride_bytes', 1);
    set('force_N', forceAt); set('force_stride_bytes', 3 * scalar);
    heap.i32[(arraysAt + A.scalar_type) >> 2] = Float === Float64Array ? 0 : 1;

    const inputAt = this._block + this._inputAt;
    const posesAt = this._block + this._posesAt;
    m._fragsim_web_default_step_input(inputAt);
    const { cameras, ...rest } = input;
    L.step_input.write(heap, inputAt, rest, 'input');
    cameras.forEach((pose, i) => {
      const at = posesAt + i * L.camera_pose.size;
      m._fragsim_web_default_camera_pose(at);
      L.camera_pose.write(heap, at, pose, `input.cameras[${i}]`);
    });
    const S = L.step_input.offsets;
    u32[(inputAt + S.camera_poses) >> 2] = posesAt;
    heap.i32[(inputAt + S.camera_count) >> 2] = cameras.length;

    const statsAt = this._block + this._statsAt;
    const status = m._fragsim_web_step_arrays(this._index1, this._generation, inputAt, arraysAt,
      count, statsAt);
    const after = fs._heap.refresh();
    // Written on a refusal too (zeros), as the C call does.
    forces.set((Float === Float64Array ? after.f64 : after.f32).subarray(forceAt >> shift, (forceAt >> shift) + 3 * count));
    this._check('step', status);
    return L.step_stats.read(after, statsAt);
  }

  // Destroys the controller and frees its memory in the module. Calls after it throw.
  dispose() {
    if (this._block === 0) return;
    const fs = this._fragsim;
    fs._module._fragsim_web_destroy(this._index1, this._generation);
    fs._free(this._block);
    if (this._fragmentsAt !== 0) fs._free(this._fragmentsAt);
    this._block = 0;
    this._fragmentsAt = 0;
  }

  _live(call) {
    if (this._block === 0) throw new FragsimError(`fragsim: ${call}: the controller was disposed`, 'stale id', 7);
    return this._fragsim;
  }

  _check(call, status) {
    if (status === 0) return;
    const m = this._fragsim._module;
    const reason = m.UTF8ToString(m._fragsim_web_last_error(this._index1, this._generation));
    const name = m.UTF8ToString(m._fragsim_status_string(status));
    throw new FragsimError(`fragsim: ${call}: ${reason || name}`, name, status);
  }
}

export class Fragsim {
  constructor(module) {
    this._module = module;
    this._heap = new Heap(module);
    const spec = JSON.parse(module.UTF8ToString(module._fragsim_web_layout()));
    this._layout = {};
    for (const [name, s] of Object.entries(spec)) {
      const layout = new StructLayout(name, s);
      layout.offsets = Object.fromEntries(Object.entries(s.fields).map(([k, [o]]) => [k, o]));
      this._layout[name] = layout;
    }
    this.version = module.UTF8ToString(module._fragsim_version_string());
  }

  defaultControllerDef() {
    return this._defaults('controller_def', '_fragsim_web_default_controller_def');
  }
  defaultCameraDef() {
    return this._defaults('camera_def', '_fragsim_web_default_camera_def');
  }
  defaultCameraPose() {
    return this._defaults('camera_pose', '_fragsim_web_default_camera_pose');
  }
  // The step input's fields but the cameras, which every step passes.
  defaultStepInput() {
    return this._defaults('step_input', '_fragsim_web_default_step_input');
  }

  // A controller from the defaults and the fields `def` sets (any subset, nested as the
  // default def is). Throws a FragsimError with the library's reason when the def is refused.
  createController(def = {}) {
    const L = this._layout;
    const m = this._module;
    const defAt = this._malloc(L.controller_def.size + L.controller_id.size + 512);
    try {
      const idAt = defAt + L.controller_def.size;
      const messageAt = idAt + L.controller_id.size;
      m._fragsim_web_default_controller_def(defAt);
      L.controller_def.write(this._heap.refresh(), defAt, def, 'def');
      const status = m._fragsim_controller_create(defAt, idAt, messageAt, 512);
      if (status !== 0) {
        const name = m.UTF8ToString(m._fragsim_status_string(status));
        throw new FragsimError(`fragsim: createController: ${m.UTF8ToString(messageAt) || name}`, name, status);
      }
      const heap = this._heap.refresh();
      return new Controller(this, heap.u32[idAt >> 2], heap.u32[(idAt >> 2) + 1]);
    } finally {
      this._free(defAt);
    }
  }

  _defaults(struct, fill) {
    const L = this._layout[struct];
    const at = this._malloc(L.size);
    try {
      this._module[fill](at);
      return L.read(this._heap.refresh(), at);
    } finally {
      this._free(at);
    }
  }

  _malloc(bytes) {
    const at = this._module._malloc(bytes);
    if (at === 0) throw new FragsimError('fragsim: out of memory in the module', 'out of memory', 5);
    return at;
  }

  _free(at) {
    this._module._free(at);
  }
}

// Loads the WebAssembly module (inside this package's JavaScript: nothing is fetched) and
// resolves to the library's entry points. `moduleOptions` goes to the module's factory as it is.
export default async function loadFragsim(moduleOptions = {}) {
  return new Fragsim(await createModule(moduleOptions));
}
