// fragsim's web demo: a crate explodes in front of a camera the user flies, in a Rapier world
// drawn with three.js, and fragsim's controller (the WebAssembly build of src/control) pushes the
// pieces that would clip through the camera's near plane. build_page.py embeds this module in
// page.html with three.js, Rapier and the fragsim package; the page opens from file://.
//
// The page counts near-plane cuts with its own check (a swept sphere per piece per step against
// the near rectangle), independent of the library. index.html?test=1 draws nothing on its own and
// exposes window.fragsimDemo.runScripted, a fixed-step scripted flight that gives the same counts
// for the same seed (tests/web/page_test.py runs it).
//
// The simulation part needs no page: createCrate, explode, stepSimulation and runScripted take
// Rapier and the loaded fragsim module as arguments, so Node can run them too.

export const STEP_S = 1 / 60;
const MAX_STEPS_PER_FRAME = 3; // beyond that the page runs slow rather than spiral
const STEP_BUDGET_MS = 25; // of a frame's time for physics steps
const GRAVITY_MPS2 = [0, -9.81, 0];
const GROUND_HEIGHT_M = 0;

// The camera the controller is told about; every camera move of the page keeps these bounds.
// The turn rate is not declared: the mouse turns the view as fast as the user moves it.
export const CAMERA_DEF = {
  fovyDeg: 60,
  aspect: 16 / 9,
  nearM: 0.1,
  farM: 500,
  bodyHalfM: [0.15, 0.1, 0.15], // the camera's small physical extent (the library's default)
  maxSpeedMps: 3.5,
  maxAccelMps2: 6,
};
const WALK_SPEED_MPS = 3; // under maxSpeedMps
const MIN_EYE_HEIGHT_M = 0.3;

// The crate: a 1 m cube on the ground, cut into n x n x n cubes of wood.
const CRATE_CENTRE_M = [0, 0.5, 0];
const CRATE_SIZE_M = 1;
const PIECE_DENSITY_KGPM3 = 600;

// The blast: most pieces scatter outward; a few are thrown at the camera's eye, aimed where the
// eye will be when they arrive (the camera's velocity held, gravity allowed for), within a few
// centimetres, so that without the controller the blast reaches the lens in most seeds.
const BLAST = {
  aimedShare: 0.06,
  aimedMin: 2,
  aimedSpeedMps: [8, 11],
  aimScatterM: 0.06,
  scatterSpeedMps: [2, 7],
  scatterLiftMps: 2,
  spinRadps: 8,
};

// The scripted flight (test mode, and the page's "scripted walk-in"): the camera walks at 3 m/s
// straight at the crate, looking 10 degrees down, from 8.5 m away; constant velocity, so within
// maxSpeedMps and maxAccelMps2 at every step.
export const SCRIPTED_FLIGHT = {
  startEyeM: [0, 1.6, 8.5],
  velocityMps: [0, 0, -3],
  yawDeg: 0,
  pitchDeg: -10,
};

// Rapier collision groups (16 bits of memberships, 16 of filter): the pieces meet the ground
// only, as in fragsim's default scenes, which keeps 15,625 pieces affordable in a browser.
const PIECE_GROUPS = 0x0001_0002;
const GROUND_GROUPS = 0x0002_0001;

// ---------------------------------------------------------------------------------------------
// Small vector helpers on [x, y, z] arrays.

const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
const length = (a) => Math.hypot(a[0], a[1], a[2]);
const normalize = (a) => scale(a, 1 / (length(a) || 1));

// A seeded PRNG (mulberry32): 32 bits of state, uniform floats in [0, 1).
export function mulberry32(seed) {
  let state = seed >>> 0;
  return function next() {
    state = (state + 0x6d2b79f5) >>> 0;
    let t = state;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
const uniform = (random, [low, high]) => low + (high - low) * random();

// ---------------------------------------------------------------------------------------------
// The camera: a pose is {eyeM, right, up, forward}; yaw turns left about +y, pitch up. The axes
// are those of a three.js camera with rotation order 'YXZ' (x = pitch, y = yaw), which looks
// down its local -z.

export function cameraAxes(yawRad, pitchRad) {
  const cy = Math.cos(yawRad), sy = Math.sin(yawRad);
  const cp = Math.cos(pitchRad), sp = Math.sin(pitchRad);
  return {
    right: [cy, 0, -sy],
    up: [sp * sy, cp, sp * cy],
    forward: [-cp * sy, sp, -cp * cy],
  };
}

export function scriptedPose(timeS) {
  const f = SCRIPTED_FLIGHT;
  const rad = Math.PI / 180;
  return {
    eyeM: add(f.startEyeM, scale(f.velocityMps, timeS)),
    ...cameraAxes(f.yawDeg * rad, f.pitchDeg * rad),
  };
}

// ---------------------------------------------------------------------------------------------
// The page's own near-plane check: the near rectangle in the camera's frame (x right, y up, z
// along the view), and a sphere swept along a segment against it, exactly (a port of
// examples/bullet/near_plane_check.cpp).

export function nearRectangle(def) {
  const halfHeightM = def.nearM * Math.tan((0.5 * def.fovyDeg * Math.PI) / 180);
  return { distanceM: def.nearM, halfHeightM, halfWidthM: halfHeightM * def.aspect };
}

function squaredDistanceToRectangle(rect, x, y, z) {
  const dx = Math.max(Math.abs(x) - rect.halfWidthM, 0);
  const dy = Math.max(Math.abs(y) - rect.halfHeightM, 0);
  const dz = z - rect.distanceM;
  return dx * dx + dy * dy + dz * dz;
}

// Squared distance between segments p1-q1 and p2-q2 (q2 != p2): the closest points by clamping
// each segment's parameter in turn, the classic closed form.
function squaredDistanceBetweenSegments(p1, q1, p2, q2) {
  const d1 = sub(q1, p1), d2 = sub(q2, p2), r = sub(p1, p2);
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  const clamp01 = (v) => Math.min(Math.max(v, 0), 1);
  let s = 0, t = 0;
  if (a <= 1e-30) {
    t = clamp01(f / e); // the first segment is a point (a piece at rest)
  } else {
    const c = dot(d1, r), b = dot(d1, d2);
    const denominator = a * e - b * b; // 0 for parallel segments: any s will do
    s = denominator > 0 ? clamp01((b * f - c * e) / denominator) : 0;
    t = (b * s + f) / e;
    if (t < 0) {
      t = 0;
      s = clamp01(-c / a);
    } else if (t > 1) {
      t = 1;
      s = clamp01((b - c) / a);
    }
  }
  const gap = sub(add(p1, scale(d1, s)), add(p2, scale(d2, t)));
  return dot(gap, gap);
}

// Whether a sphere of radiusM whose centre moves from `from` to `to` (camera frame) meets the
// near rectangle.
export function sweptSphereMeets(rect, from, to, radiusM) {
  const r2 = radiusM * radiusM;
  const before = from[2] - rect.distanceM, after = to[2] - rect.distanceM;
  if ((before <= 0 && after >= 0) || (before >= 0 && after <= 0)) {
    // The centre crosses the rectangle's plane: inside the rectangle there?
    const s = before === after ? 0 : before / (before - after);
    const x = from[0] + (to[0] - from[0]) * s, y = from[1] + (to[1] - from[1]) * s;
    if (Math.abs(x) <= rect.halfWidthM && Math.abs(y) <= rect.halfHeightM) return true;
  }
  // Otherwise the closest points of two convex sets that do not meet lie on the boundary of one
  // of them: an end of the segment against the rectangle, or the segment against an edge.
  if (squaredDistanceToRectangle(rect, ...from) <= r2) return true;
  if (squaredDistanceToRectangle(rect, ...to) <= r2) return true;
  const w = rect.halfWidthM, h = rect.halfHeightM, z = rect.distanceM;
  const corners = [[-w, -h, z], [w, -h, z], [w, h, z], [-w, h, z]];
  for (let i = 0; i < 4; ++i) {
    if (squaredDistanceBetweenSegments(from, to, corners[i], corners[(i + 1) % 4]) <= r2) return true;
  }
  return false;
}

// Hand-worked cases (those of the bullet example), checked before the counts are trusted.
export function nearCheckAgreesWithKnownCases() {
  const rect = nearRectangle({ nearM: 0.1, fovyDeg: 60, aspect: 16 / 9 });
  const w = rect.halfWidthM, h = rect.halfHeightM;
  const cases = [
    [[0, 0, 1], [0, 0, -1], 0.001, true], // straight through the middle
    [[0, 0, 1], [0, 0, 0.3], 0.19, false], // stops 0.2 m short
    [[0, 0, 1], [0, 0, 0.3], 0.21, true],
    [[0.5, 0, 1], [0.5, 0, -1], 0.39, false], // beside it, 0.397 m from its edge
    [[0.5, 0, 1], [0.5, 0, -1], 0.4, true],
    [[-1, h + 0.03, 0.14], [1, h + 0.03, 0.14], 0.049, false], // across, above the top edge
    [[-1, h + 0.03, 0.14], [1, h + 0.03, 0.14], 0.051, true],
    [[w + 0.3, h + 0.4, 0.1], [w + 0.3, h + 0.4, 0.1], 0.49, false], // at rest, 0.5 m off
    [[w + 0.3, h + 0.4, 0.1], [w + 0.3, h + 0.4, 0.1], 0.51, true],
    [[2, 0, 0.5], [-2, 0, -0.3], 0.001, true], // a fast diagonal pass through it
  ];
  return cases.every(([from, to, radiusM, meets]) => sweptSphereMeets(rect, from, to, radiusM) === meets);
}

// ---------------------------------------------------------------------------------------------
// The world: the ground and the crate's pieces, at rest until explode() throws them.

// The float32 at or above x: a bounding radius handed over in floats must not shrink.
function float32AtLeast(x) {
  const f = Math.fround(x);
  return f >= x ? f : Math.fround(f * (1 + 2 ** -23));
}

export function createCrate(RAPIER, { seed, pieces }) {
  const perSide = Math.max(1, Math.round(Math.cbrt(pieces)));
  const count = perSide ** 3;
  const world = new RAPIER.World({ x: GRAVITY_MPS2[0], y: GRAVITY_MPS2[1], z: GRAVITY_MPS2[2] });
  world.timestep = STEP_S;
  const ground = world.createRigidBody(RAPIER.RigidBodyDesc.fixed().setTranslation(0, GROUND_HEIGHT_M - 1, 0));
  world.createCollider(RAPIER.ColliderDesc.cuboid(200, 1, 200).setCollisionGroups(GROUND_GROUPS), ground);

  const edgeM = CRATE_SIZE_M / perSide;
  const halfM = edgeM / 2;
  const sim = {
    world, count, perSide, edgeM, seed,
    bodies: new Array(count),
    offsetM: new Float32Array(3 * count), // from the crate's centre: the blast's direction
    fragments: {
      position: new Float32Array(3 * count),
      velocity: new Float32Array(3 * count),
      radius: new Float32Array(count).fill(float32AtLeast(halfM * Math.sqrt(3))),
      mass: new Float32Array(count),
      id: new Uint32Array(count),
    },
    forces: new Float32Array(3 * count),
    positionAfter: new Float32Array(3 * count),
    forced: new Uint8Array(count), // a force is on the body (Rapier keeps it until reset)
    cutBefore: new Uint8Array(count), // met the near rectangle in the previous step
    everCut: new Uint8Array(count),
    lastPushedStep: new Int32Array(count).fill(-1000),
    controller: null,
    strategy: 'none',
    exploded: false,
    step: 0,
    timeS: 0,
    totals: { cuts: 0, cutPieces: 0, pushes: 0, pushedPieces: 0, controllerMs: 0, controllerCalls: 0, warnings: 0, firstCutStep: -1 },
    lastPushes: 0,
  };
  for (let i = 0; i < count; ++i) {
    const ix = i % perSide, iy = Math.floor(i / perSide) % perSide, iz = Math.floor(i / perSide ** 2);
    const offset = [(ix + 0.5) * edgeM - 0.5 * CRATE_SIZE_M, (iy + 0.5) * edgeM - 0.5 * CRATE_SIZE_M,
      (iz + 0.5) * edgeM - 0.5 * CRATE_SIZE_M];
    const at = add(CRATE_CENTRE_M, offset);
    const body = world.createRigidBody(RAPIER.RigidBodyDesc.dynamic().setTranslation(...at).setCanSleep(true));
    world.createCollider(RAPIER.ColliderDesc.cuboid(halfM, halfM, halfM)
      .setDensity(PIECE_DENSITY_KGPM3).setCollisionGroups(PIECE_GROUPS), body);
    sim.bodies[i] = body;
    sim.offsetM.set(offset, 3 * i);
    sim.fragments.position.set(at, 3 * i);
    sim.fragments.mass[i] = body.mass();
    sim.fragments.id[i] = i; // the piece's index: stable, as the bodies never change order
  }
  return sim;
}

// The blast, at the camera's pose and velocity of that moment. The draws come in a fixed order
// whatever the camera, so a seed is one blast.
export function explode(sim, eyeM, eyeVelocityMps) {
  const random = mulberry32(sim.seed);
  const aimed = new Uint8Array(sim.count);
  let aimedCount = 0;
  for (let i = 0; i < sim.count; ++i) {
    aimed[i] = random() < BLAST.aimedShare ? 1 : 0;
    aimedCount += aimed[i];
  }
  // A few at least, so that a small crate threatens the lens too.
  for (let i = 0; aimedCount < Math.min(BLAST.aimedMin, sim.count); ++i) {
    const pick = Math.floor(random() * sim.count);
    if (!aimed[pick]) (aimed[pick] = 1), ++aimedCount;
    if (i > 1000) break;
  }
  for (let i = 0; i < sim.count; ++i) {
    const at = Array.from(sim.fragments.position.subarray(3 * i, 3 * i + 3));
    const velocity = aimed[i] ? aimedVelocity(random, at, eyeM, eyeVelocityMps) : scatterVelocity(random, sim, i);
    const spin = [0, 0, 0].map(() => (2 * random() - 1) * BLAST.spinRadps);
    const body = sim.bodies[i];
    body.setLinvel({ x: velocity[0], y: velocity[1], z: velocity[2] }, true);
    body.setAngvel({ x: spin[0], y: spin[1], z: spin[2] }, true);
  }
  sim.exploded = true;
}

// Thrown to reach the eye as it will be on arrival: the flight time from the distance and speed
// (refined twice as the eye moves), the throw's rise cancelling gravity's fall.
function aimedVelocity(random, fromM, eyeM, eyeVelocityMps) {
  const speedMps = uniform(random, BLAST.aimedSpeedMps);
  const scatterAngle = 2 * Math.PI * random();
  const scatterM = BLAST.aimScatterM * Math.sqrt(random());
  let flightS = length(sub(eyeM, fromM)) / speedMps;
  let targetM = eyeM;
  for (let k = 0; k < 3; ++k) {
    targetM = add(eyeM, scale(eyeVelocityMps, flightS));
    flightS = length(sub(targetM, fromM)) / speedMps;
  }
  targetM = add(targetM, [scatterM * Math.cos(scatterAngle), scatterM * Math.sin(scatterAngle), 0]);
  return sub(scale(sub(targetM, fromM), 1 / flightS), scale(GRAVITY_MPS2, 0.5 * flightS));
}

function scatterVelocity(random, sim, i) {
  const outward = Array.from(sim.offsetM.subarray(3 * i, 3 * i + 3));
  const jitter = [0, 0, 0].map(() => 0.3 * (2 * random() - 1));
  const direction = normalize(add(normalize(outward), jitter));
  // The ground throws the blast back up: no piece is driven into it.
  direction[1] = Math.abs(direction[1]);
  return add(scale(direction, uniform(random, BLAST.scatterSpeedMps)), [0, BLAST.scatterLiftMps, 0]);
}

// A controller for the strategy ('none': none), told the camera and given room for the pieces.
export function attachController(sim, fragsim, strategy) {
  if (sim.controller) sim.controller.dispose();
  sim.controller = null;
  sim.strategy = strategy;
  if (strategy === 'none') return;
  const controller = fragsim.createController({ strategy });
  controller.setCameras([CAMERA_DEF]);
  controller.reserve(sim.count);
  sim.controller = controller;
}

export function disposeSimulation(sim) {
  if (sim.controller) sim.controller.dispose();
  sim.controller = null;
  sim.world.free();
}

// ---------------------------------------------------------------------------------------------
// One physics step: the controller's forces for this step, Rapier's step, the page's check.

function readState(sim, into, velocity) {
  for (let i = 0; i < sim.count; ++i) {
    const p = sim.bodies[i].translation();
    into[3 * i] = p.x, into[3 * i + 1] = p.y, into[3 * i + 2] = p.z;
    if (velocity) {
      const v = sim.bodies[i].linvel();
      velocity[3 * i] = v.x, velocity[3 * i + 1] = v.y, velocity[3 * i + 2] = v.z;
    }
  }
}

// Rapier keeps a force added with addForce on the body, step after step, until resetForces (see
// README.md): so each step every pushed body gets its force anew, and a body pushed last step but
// not now is cleared.
function applyForces(sim) {
  const f = sim.forces;
  let pushed = 0;
  for (let i = 0; i < sim.count; ++i) {
    const x = f[3 * i], y = f[3 * i + 1], z = f[3 * i + 2];
    const push = x !== 0 || y !== 0 || z !== 0;
    if (push || sim.forced[i]) sim.bodies[i].resetForces(false);
    if (push) {
      sim.bodies[i].addForce({ x, y, z }, true);
      if (sim.lastPushedStep[i] < 0) ++sim.totals.pushedPieces;
      sim.lastPushedStep[i] = sim.step;
      ++pushed;
    }
    sim.forced[i] = push ? 1 : 0;
  }
  return pushed;
}

function callController(sim, poseStart, poseEnd) {
  const velocityMps = scale(sub(poseEnd.eyeM, poseStart.eyeM), 1 / STEP_S);
  const input = {
    timeS: sim.timeS,
    dtS: STEP_S,
    gravityMps2: GRAVITY_MPS2,
    groundHeightM: GROUND_HEIGHT_M,
    cameras: [{ eyeM: poseStart.eyeM, right: poseStart.right, up: poseStart.up, forward: poseStart.forward, velocityMps }],
  };
  const startedMs = performance.now();
  const stats = sim.controller.step(input, sim.fragments, sim.forces);
  sim.totals.controllerMs += performance.now() - startedMs;
  ++sim.totals.controllerCalls;
  sim.totals.warnings |= stats.warnings;
  return stats;
}

// Each piece's sphere swept from its centre before the step (in the camera's frame at the
// step's start) to after it (in the frame at its end) against the near rectangle. A cut event is
// a step in which a piece meets it after a step in which it did not.
function countCuts(sim, poseStart, poseEnd, rect) {
  const before = sim.fragments.position, after = sim.positionAfter;
  const radiusM = sim.fragments.radius[0];
  const frame = (pose, p, i) => {
    const dx = p[3 * i] - pose.eyeM[0], dy = p[3 * i + 1] - pose.eyeM[1], dz = p[3 * i + 2] - pose.eyeM[2];
    const dot = (a) => dx * a[0] + dy * a[1] + dz * a[2];
    return [dot(pose.right), dot(pose.up), dot(pose.forward)];
  };
  for (let i = 0; i < sim.count; ++i) {
    const from = frame(poseStart, before, i), to = frame(poseEnd, after, i);
    // Both ends farther than the radius from the rectangle's plane, on one side: no meeting.
    const nearM = rect.distanceM;
    const apart = (from[2] - nearM > radiusM && to[2] - nearM > radiusM) ||
      (nearM - from[2] > radiusM && nearM - to[2] > radiusM);
    const meets = !apart && sweptSphereMeets(rect, from, to, radiusM);
    if (meets && !sim.cutBefore[i]) {
      ++sim.totals.cuts;
      if (sim.totals.firstCutStep < 0) sim.totals.firstCutStep = sim.step;
    }
    if (meets && !sim.everCut[i]) (sim.everCut[i] = 1), ++sim.totals.cutPieces;
    sim.cutBefore[i] = meets ? 1 : 0;
  }
}

const NEAR_RECTANGLE = nearRectangle(CAMERA_DEF);

export function stepSimulation(sim, poseStart, poseEnd) {
  readState(sim, sim.fragments.position, sim.fragments.velocity);
  sim.lastPushes = 0;
  if (sim.controller) {
    callController(sim, poseStart, poseEnd);
    sim.lastPushes = applyForces(sim);
    sim.totals.pushes += sim.lastPushes;
  }
  sim.world.step();
  readState(sim, sim.positionAfter, null);
  countCuts(sim, poseStart, poseEnd, NEAR_RECTANGLE);
  ++sim.step;
  sim.timeS += STEP_S;
}

// FNV-1a over the pieces' final positions' bytes: two runs that agree here agree everywhere.
function stateHash(sim) {
  readState(sim, sim.positionAfter, null);
  const bytes = new Uint8Array(sim.positionAfter.buffer);
  let hash = 0x811c9dc5;
  for (let i = 0; i < bytes.length; ++i) hash = Math.imul(hash ^ bytes[i], 0x01000193) >>> 0;
  return hash.toString(16).padStart(8, '0');
}

// The scripted flight at fixed steps, never timed by the wall clock: the counts depend on the
// seed, the strategy and the piece count only.
export function runScriptedSimulation(RAPIER, fragsim, { seed = 1, strategy = 'edge-min', pieces = 1728, steps = 150 } = {}) {
  const sim = createCrate(RAPIER, { seed, pieces });
  attachController(sim, fragsim, strategy);
  explode(sim, scriptedPose(0).eyeM, SCRIPTED_FLIGHT.velocityMps);
  const startedMs = performance.now();
  for (let k = 0; k < steps; ++k) stepSimulation(sim, scriptedPose(k * STEP_S), scriptedPose((k + 1) * STEP_S));
  const t = sim.totals;
  const result = {
    seed, strategy, pieces: sim.count, steps,
    cuts: t.cuts, cutPieces: t.cutPieces, firstCutStep: t.firstCutStep,
    pushes: t.pushes, pushedPieces: t.pushedPieces,
    controllerMsMean: t.controllerCalls ? t.controllerMs / t.controllerCalls : 0,
    runMs: performance.now() - startedMs,
    warnings: t.warnings,
    stateHash: stateHash(sim),
  };
  return { sim, result };
}

// ---------------------------------------------------------------------------------------------
// The page: loading the embedded modules, the view, the controls, the loop.

// A module embedded in the page as text (or base64), imported from a data: URL: Chromium refuses
// module scripts from file:// URLs but imports data: URLs, which cannot import relatively.
function embeddedSource(id) {
  const element = document.getElementById(id);
  if (!element) throw new Error(`the page has no embedded module #${id}`);
  const text = element.textContent;
  if (element.dataset.encoding !== 'base64') return text;
  const bytes = Uint8Array.from(atob(text.trim()), (c) => c.charCodeAt(0));
  return new TextDecoder().decode(bytes);
}

const moduleUrl = (source) => 'data:text/javascript;charset=utf-8,' + encodeURIComponent(source);

async function loadModules() {
  const THREE = await import(moduleUrl(embeddedSource('module-three')));
  const RAPIER = (await import(moduleUrl(embeddedSource('module-rapier')))).default;
  await RAPIER.init();
  // fragsim.mjs imports its emscripten glue relatively: that specifier becomes the glue's URL.
  const apiElement = document.getElementById('module-fragsim');
  const specifier = apiElement.dataset.glueSpecifier;
  const api = embeddedSource('module-fragsim');
  const glueUrl = moduleUrl(embeddedSource('module-fragsim-glue'));
  const fragsimModule = await import(moduleUrl(api.replace(specifier, JSON.stringify(glueUrl))));
  const fragsim = await fragsimModule.default();
  return { THREE, RAPIER, fragsim, Warning: fragsimModule.Warning };
}

const PIECE_COLOUR = 0xb08850, PUSHED_COLOUR = 0xff8c1a, CUT_COLOUR = 0xe0201c;
const PUSH_GLOW_STEPS = 20; // a pushed piece stays orange this long, so that the eye sees it

class View {
  constructor(THREE, canvas, { testMode }) {
    this.THREE = THREE;
    this.canvas = canvas;
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: !testMode, preserveDrawingBuffer: testMode });
    this.renderer.setPixelRatio(testMode ? 1 : Math.min(window.devicePixelRatio, 2));
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0xa9c8e8);
    this.camera = new THREE.PerspectiveCamera(CAMERA_DEF.fovyDeg, CAMERA_DEF.aspect, CAMERA_DEF.nearM, CAMERA_DEF.farM);
    this.camera.rotation.order = 'YXZ';
    this.scene.add(new THREE.HemisphereLight(0xdfefff, 0x4a5a3a, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.8);
    sun.position.set(4, 10, 6);
    this.scene.add(sun);
    const ground = new THREE.Mesh(new THREE.PlaneGeometry(400, 400), new THREE.MeshLambertMaterial({ color: 0x6f8a5a }));
    ground.rotation.x = -Math.PI / 2;
    ground.position.y = GROUND_HEIGHT_M;
    this.scene.add(ground);
    const grid = new THREE.GridHelper(40, 40, 0x3d4d30, 0x55693f);
    grid.position.y = GROUND_HEIGHT_M + 0.002;
    this.scene.add(grid);
    this.pieces = null;
    this.matrix = new THREE.Matrix4();
    this.colour = new THREE.Color();
    this.resize();
  }

  resize() {
    const width = Math.max(1, this.canvas.clientWidth), height = Math.max(1, this.canvas.clientHeight);
    this.renderer.setSize(width, height, false);
  }

  // One instanced mesh for all the pieces: one draw call for 15,625 cubes.
  usePieces(sim) {
    const THREE = this.THREE;
    if (this.pieces) {
      this.scene.remove(this.pieces);
      this.pieces.geometry.dispose();
      this.pieces.material.dispose();
    }
    const geometry = new THREE.BoxGeometry(sim.edgeM, sim.edgeM, sim.edgeM);
    this.pieces = new THREE.InstancedMesh(geometry, new THREE.MeshLambertMaterial(), sim.count);
    this.pieces.frustumCulled = false;
    this.scene.add(this.pieces);
  }

  draw(sim, pose) {
    const THREE = this.THREE;
    const position = new THREE.Vector3(), rotation = new THREE.Quaternion(), unit = new THREE.Vector3(1, 1, 1);
    for (let i = 0; i < sim.count; ++i) {
      const body = sim.bodies[i];
      const p = body.translation(), q = body.rotation();
      this.matrix.compose(position.set(p.x, p.y, p.z), rotation.set(q.x, q.y, q.z, q.w), unit);
      this.pieces.setMatrixAt(i, this.matrix);
      const colour = sim.everCut[i] ? CUT_COLOUR
        : sim.step - sim.lastPushedStep[i] <= PUSH_GLOW_STEPS ? PUSHED_COLOUR : PIECE_COLOUR;
      this.pieces.setColorAt(i, this.colour.setHex(colour));
    }
    this.pieces.instanceMatrix.needsUpdate = true;
    this.pieces.instanceColor.needsUpdate = true;
    // The three.js camera from the pose's axes (its local -z is the view direction).
    const basis = new THREE.Matrix4().makeBasis(new THREE.Vector3(...pose.right), new THREE.Vector3(...pose.up),
      new THREE.Vector3(...scale(pose.forward, -1)));
    this.camera.quaternion.setFromRotationMatrix(basis);
    this.camera.position.set(...pose.eyeM);
    this.renderer.render(this.scene, this.camera);
  }
}

// The camera the user flies: WASD along the view (horizontally), E/Q up and down, drag to look.
// Its velocity follows the keys at no more than the declared acceleration, so the controller's
// assumptions hold.
class FlyingCamera {
  constructor() {
    this.keys = new Set();
    this.moveInput = [0, 0, 0]; // from touch: right, up, forward in [-1, 1]
    this.reset();
  }

  reset() {
    const f = SCRIPTED_FLIGHT;
    this.eyeM = [...f.startEyeM];
    this.velocityMps = [0, 0, 0];
    this.yawRad = (f.yawDeg * Math.PI) / 180;
    this.pitchRad = (f.pitchDeg * Math.PI) / 180;
  }

  pose() {
    return { eyeM: [...this.eyeM], ...cameraAxes(this.yawRad, this.pitchRad) };
  }

  look(dxPx, dyPx) {
    this.yawRad -= dxPx * 0.004;
    this.pitchRad = Math.min(Math.max(this.pitchRad - dyPx * 0.004, -1.45), 1.45);
  }

  wantedVelocityMps() {
    const k = (code) => (this.keys.has(code) ? 1 : 0);
    const right = k('KeyD') - k('KeyA') + this.moveInput[0];
    const up = k('KeyE') - k('KeyQ') + this.moveInput[1];
    const forward = k('KeyW') - k('KeyS') + this.moveInput[2];
    const axes = cameraAxes(this.yawRad, 0); // walking stays level
    const wanted = add(add(scale(axes.right, right), scale(axes.forward, forward)), [0, up, 0]);
    const speed = length(wanted);
    return speed > 1 ? scale(wanted, WALK_SPEED_MPS / speed) : scale(wanted, WALK_SPEED_MPS);
  }

  advance(dtS) {
    const change = sub(this.wantedVelocityMps(), this.velocityMps);
    const maxChange = 0.95 * CAMERA_DEF.maxAccelMps2 * dtS;
    const size = length(change);
    this.velocityMps = add(this.velocityMps, size > maxChange ? scale(change, maxChange / size) : change);
    this.eyeM = add(this.eyeM, scale(this.velocityMps, dtS));
    if (this.eyeM[1] < MIN_EYE_HEIGHT_M) {
      this.eyeM[1] = MIN_EYE_HEIGHT_M;
      this.velocityMps[1] = Math.max(this.velocityMps[1], 0);
    }
  }
}

function bindInput(canvas, flyer) {
  const typing = (event) => event.target instanceof HTMLInputElement || event.target instanceof HTMLSelectElement;
  window.addEventListener('keydown', (event) => { if (!typing(event)) flyer.keys.add(event.code); });
  window.addEventListener('keyup', (event) => flyer.keys.delete(event.code));
  window.addEventListener('blur', () => flyer.keys.clear());
  // Mouse: drag to look; double-click locks the pointer (Esc frees it).
  let dragging = false;
  canvas.addEventListener('mousedown', () => { dragging = true; });
  window.addEventListener('mouseup', () => { dragging = false; });
  window.addEventListener('mousemove', (event) => {
    if (dragging || document.pointerLockElement === canvas) flyer.look(event.movementX, event.movementY);
  });
  canvas.addEventListener('dblclick', () => canvas.requestPointerLock?.());
  // Touch: one finger looks; two fingers move (how far they are dragged from where they landed).
  const touchStart = new Map();
  let lastTouch = null;
  canvas.addEventListener('touchstart', (event) => {
    for (const t of event.changedTouches) touchStart.set(t.identifier, [t.clientX, t.clientY]);
    lastTouch = event.touches.length === 1 ? [event.touches[0].clientX, event.touches[0].clientY] : null;
    event.preventDefault();
  }, { passive: false });
  canvas.addEventListener('touchmove', (event) => {
    if (event.touches.length === 1 && lastTouch) {
      const t = event.touches[0];
      flyer.look(t.clientX - lastTouch[0], t.clientY - lastTouch[1]);
      lastTouch = [t.clientX, t.clientY];
    } else if (event.touches.length >= 2) {
      const t = event.touches[0], start = touchStart.get(t.identifier) ?? [t.clientX, t.clientY];
      const reach = 80; // px of drag for full speed
      flyer.moveInput = [Math.max(-1, Math.min(1, (t.clientX - start[0]) / reach)), 0,
        Math.max(-1, Math.min(1, -(t.clientY - start[1]) / reach))];
    }
    event.preventDefault();
  }, { passive: false });
  const touchEnd = (event) => {
    for (const t of event.changedTouches) touchStart.delete(t.identifier);
    if (event.touches.length < 2) flyer.moveInput = [0, 0, 0];
    lastTouch = event.touches.length === 1 ? [event.touches[0].clientX, event.touches[0].clientY] : null;
  };
  canvas.addEventListener('touchend', touchEnd);
  canvas.addEventListener('touchcancel', touchEnd);
}

const ARM_S = 0.8; // the crate stands this long after a replay before it blows

class Demo {
  constructor(modules, { testMode }) {
    Object.assign(this, modules);
    this.testMode = testMode;
    this.canvas = document.getElementById('view');
    this.view = new View(this.THREE, this.canvas, { testMode });
    this.flyer = new FlyingCamera();
    this.sim = null;
    this.fps = 0;
  }

  settings() {
    const value = (id) => document.getElementById(id).value;
    return { strategy: value('strategy'), pieces: Number(value('pieces')),
      seed: Math.max(0, Math.floor(Number(value('seed')))) || 0, cameraMode: value('camera-mode') };
  }

  // A new crate with the panel's settings, the camera back at its start; it blows after ARM_S.
  replay() {
    if (this.sim) disposeSimulation(this.sim);
    const { strategy, pieces, seed, cameraMode } = this.settings();
    this.cameraMode = cameraMode;
    this.flyer.reset();
    this.sim = createCrate(this.RAPIER, { seed, pieces });
    attachController(this.sim, this.fragsim, strategy);
    this.armedS = 0;
    this.scriptS = 0;
    this.view.usePieces(this.sim);
  }

  // One fixed step of the camera and, once the crate has blown, of the world.
  fixedStep() {
    const poseStart = this.flyer.pose();
    const scripted = this.cameraMode === 'scripted' && this.sim.exploded && this.scriptS < 3;
    if (scripted) {
      // The scripted walk-in, then the user's camera carries on at that velocity.
      this.scriptS += STEP_S;
      const pose = scriptedPose(this.scriptS);
      this.flyer.eyeM = pose.eyeM;
      this.flyer.velocityMps = [...SCRIPTED_FLIGHT.velocityMps];
    } else {
      this.flyer.advance(STEP_S);
    }
    const poseEnd = this.flyer.pose();
    if (!this.sim.exploded) {
      this.armedS += STEP_S;
      if (this.armedS >= ARM_S) {
        const velocity = this.cameraMode === 'scripted' ? SCRIPTED_FLIGHT.velocityMps : this.flyer.velocityMps;
        explode(this.sim, poseEnd.eyeM, velocity);
      }
      return;
    }
    stepSimulation(this.sim, poseStart, poseEnd);
  }

  start() {
    bindInput(this.canvas, this.flyer);
    for (const id of ['strategy', 'pieces', 'seed', 'camera-mode']) {
      document.getElementById(id).addEventListener('change', () => this.replay());
    }
    document.getElementById('explode').addEventListener('click', () => this.replay());
    window.addEventListener('keydown', (event) => { if (event.code === 'KeyR' && !event.repeat) this.replay(); });
    window.addEventListener('resize', () => this.view.resize());
    this.replay();
    let lastMs = performance.now(), owedS = 0, hudMs = 0, frames = 0;
    const frame = (nowMs) => {
      const elapsedS = Math.min((nowMs - lastMs) / 1000, 0.25);
      lastMs = nowMs;
      owedS += elapsedS;
      // At most a few steps, and no more than a frame's worth of time in them: a heavy world
      // (15,625 pieces) then runs in slow motion instead of freezing the page.
      let taken = 0;
      const budgetEndMs = performance.now() + STEP_BUDGET_MS;
      while (owedS >= STEP_S && taken < MAX_STEPS_PER_FRAME && (taken === 0 || performance.now() < budgetEndMs)) {
        owedS -= STEP_S, ++taken, this.fixedStep();
      }
      if (owedS >= STEP_S) owedS = Math.min(owedS, STEP_S); // the time not stepped is dropped
      this.view.draw(this.sim, this.flyer.pose());
      ++frames;
      if (nowMs - hudMs > 500) {
        this.fps = (1000 * frames) / (nowMs - hudMs || 1);
        hudMs = nowMs, frames = 0;
        this.showStats();
      }
      requestAnimationFrame(frame);
    };
    requestAnimationFrame(frame);
  }

  showStats() {
    const sim = this.sim, t = sim.totals;
    const set = (id, text) => { document.getElementById(id).textContent = text; };
    set('stat-cuts', `${t.cutPieces} piece${t.cutPieces === 1 ? '' : 's'}, ${t.cuts} event${t.cuts === 1 ? '' : 's'}`);
    set('stat-ms', sim.controller ? `${(t.controllerCalls ? t.controllerMs / t.controllerCalls : 0).toFixed(3)} ms` : 'not called');
    set('stat-pushes', sim.controller ? `${sim.lastPushes} now, ${(sim.step ? t.pushes / sim.step : 0).toFixed(2)} mean` : '-');
    set('stat-fps', this.testMode ? '- (test mode)' : `${this.fps.toFixed(0)}`);
    set('stat-time', sim.exploded ? `${sim.timeS.toFixed(2)} s after the blast, ${sim.count} pieces` : 'about to blow');
    set('stat-warnings', t.warnings ? `controller warnings: ${warningNames(this.Warning, t.warnings)}` : '');
  }
}

function warningNames(Warning, bits) {
  return Object.entries(Warning).filter(([, bit]) => bits & bit).map(([name]) => name).join(', ') || String(bits);
}

async function main() {
  const testMode = new URLSearchParams(location.search).has('test');
  const status = document.getElementById('status');
  try {
    if (!nearCheckAgreesWithKnownCases()) throw new Error("the page's near-plane check fails its known cases");
    const modules = await loadModules();
    const demo = new Demo(modules, { testMode });
    document.getElementById('versions').textContent =
      `three.js ${modules.THREE.REVISION}, Rapier ${modules.RAPIER.version()}, fragsim-control ${modules.fragsim.version}`;
    if (testMode) {
      exposeTestApi(demo);
      status.textContent = 'Test mode: window.fragsimDemo.runScripted runs the scripted flight.';
    } else {
      demo.start();
      status.textContent = '';
    }
    document.body.dataset.state = 'ready';
  } catch (error) {
    document.body.dataset.state = 'failed';
    status.className = 'error';
    status.textContent = `The demo could not start: ${error.message}`;
    console.error(error);
  }
}

// Test mode: no animation loop; each call runs the scripted flight at fixed steps and draws its
// last frame.
function exposeTestApi(demo) {
  window.fragsimDemo = {
    ready: true,
    async runScripted(options = {}) {
      if (demo.sim) disposeSimulation(demo.sim);
      const { sim, result } = runScriptedSimulation(demo.RAPIER, demo.fragsim, options);
      demo.sim = sim;
      // The panel shows what ran, so that a screenshot reads right.
      const show = { strategy: result.strategy, pieces: String(result.pieces), seed: String(result.seed), 'camera-mode': 'scripted' };
      for (const [id, value] of Object.entries(show)) document.getElementById(id).value = value;
      demo.view.usePieces(sim);
      demo.view.resize();
      demo.view.draw(sim, scriptedPose(sim.step * STEP_S));
      demo.showStats();
      return result;
    },
  };
}

if (typeof document !== 'undefined') main();
