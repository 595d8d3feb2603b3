// fragsim-control: the types of fragsim.mjs. Every field is the C API's (fragsim/types.h) in
// camelCase, with its unit in its name: _m metres, _mps metres per second, _mps2 metres per
// second squared, _s seconds, _kg kilograms, _N newtons, _deg degrees, _degps degrees per second.

/** A vector as three numbers: a three.js Vector3, {x, y, z}, or an array of 3 (checked when called). */
export type Vec3Like = { x: number; y: number; z: number } | readonly number[] | Float32Array | Float64Array;
/** A vector as the defaults return it. */
export interface Vec3 {
  x: number;
  y: number;
  z: number;
}

export type Strategy = 'edge-min' | 'edge' | 'deflect-all';
export type CameraModel = 'constant' | 'bounded_accel' | 'reachable';
export type EdgePredictor = 'thesis' | 'discrete';
export type EdgeReach = 'thesis' | 'growing';
export type EdgeHorizon = 'camera' | 'ground';
export type EdgeReplan = 'never' | 'contact' | 'always';

export interface EdgeMinDef {
  marginM: number;
  aMaxMps2: number;
  cameraModel: CameraModel;
  cameraAccelMps2: number;
  /** Infinity: no bound on the camera's turn rate. */
  cameraTurnDegps: number;
  /** 0: no cap on the exact solves per step. */
  maxSolves: number;
  /** Top, bottom, left, right. */
  edgeWeights: [number, number, number, number];
  /** 1: the occlusion bound is off. */
  coverMax: number;
  coverRegion: number;
}

export interface EdgeDef {
  kNms2: number;
  aMaxMps2: number;
  predictor: EdgePredictor;
  reach: EdgeReach;
  horizon: EdgeHorizon;
  replan: EdgeReplan;
}

export interface DeflectAllDef {
  accelMps2: number;
  rangeM: number;
}

/** A controller's settings; createController takes any part of it over the defaults. */
export interface ControllerDef {
  strategy: Strategy;
  edgeMin: EdgeMinDef;
  edge: EdgeDef;
  deflectAll: DeflectAllDef;
  horizonCapS: number;
}

export type ControllerDefInput = Partial<
  Omit<ControllerDef, 'edgeMin' | 'edge' | 'deflectAll'> & {
    edgeMin: Partial<EdgeMinDef>;
    edge: Partial<EdgeDef>;
    deflectAll: Partial<DeflectAllDef>;
  }
>;

/** A camera's constants (fragsim_camera_def). */
export interface CameraDef {
  fovyDeg: number;
  aspect: number;
  nearM: number;
  farM: number;
  bodyHalfM: Vec3;
  maxSpeedMps: number;
  /** -1 (undeclared): the def's assumption applies. */
  maxAccelMps2: number;
  /** -1 (undeclared): the def's assumption applies. */
  maxTurnDegps: number;
}
export type CameraDefInput = Partial<Omit<CameraDef, 'bodyHalfM'> & { bodyHalfM: Vec3Like }>;

/** Where a camera is this step (fragsim_camera_pose). */
export interface CameraPose {
  eyeM: Vec3;
  right: Vec3;
  up: Vec3;
  forward: Vec3;
  velocityMps: Vec3;
}
export type CameraPoseInput = Partial<Record<keyof CameraPose, Vec3Like>>;

/** A step's world (fragsim_step_input) but its cameras. */
export interface StepInput {
  timeS: number;
  /** Infinity: no end. */
  endTimeS: number;
  dtS: number;
  gravityMps2: Vec3;
  /** -Infinity: no ground. */
  groundHeightM: number;
  groundNormal: Vec3;
}
export type StepInputWithCameras = Partial<
  Omit<StepInput, 'gravityMps2' | 'groundNormal'> & { gravityMps2: Vec3Like; groundNormal: Vec3Like }
> & {
  /** One pose per camera set by setCameras, in the same order. */
  cameras: CameraPoseInput[];
};

/** The fragments of one step, one entry (or three: x, y, z) per fragment in every array. */
export interface FragmentArrays<F extends Float32Array | Float64Array> {
  position: F;
  velocity: F;
  radius: F;
  /** 0, or in [1e-12, 1e24]. */
  mass: F;
  /** Unique within a step; the controller keeps its state by id between steps. */
  id: BigUint64Array | Uint32Array;
  /** Nonzero: the fragment had a contact in the last step (read by edge with replan 'contact'). */
  touched?: Uint8Array;
  /** Default: radius.length. */
  count?: number;
}

/** What a step did (fragsim_step_stats). */
export interface StepStats {
  candidates: number;
  pushed: number;
  capped: number;
  guarded: number;
  newIds: number;
  droppedIds: number;
  deferred: number;
  rejectedCheaply: number;
  skipped: number;
  firstSkipped: number;
  unprotected: number;
  belowGround: number;
  firstBelowGround: number;
  conflicts: number;
  firstConflict: number;
  /** Warning bits: see Warning. */
  warnings: number;
}

export declare const Warning: Readonly<{
  CAMERA_OVER_SPEED: 1;
  FOVY_IN_RADIANS: 2;
  BELOW_GROUND: 4;
  UNPROTECTED: 8;
  SKIPPED: 16;
}>;
export declare const MAX_CAMERAS: 8;
export declare const MAX_FRAGMENTS: 536870911;

/** A call the library refused: message is its reason. */
export declare class FragsimError extends Error {
  /** The status's short name, such as 'invalid argument'. */
  readonly status: string;
  /** The fragsim_status number. */
  readonly code: number;
}

export declare class Controller {
  private constructor();
  readonly disposed: boolean;
  /** 1 to 8 cameras' constants, each over the default camera def. */
  setCameras(cameras: CameraDefInput[]): void;
  /** Room for count fragments now, so that the explosion's step does not grow the controller. */
  reserve(count: number): void;
  /** Forgets every fragment. */
  reset(): void;
  /**
   * One physics step: writes the force on each fragment, in newtons, into forces (3 per
   * fragment, the same float type as the fragments' arrays). Apply them for this step only.
   */
  step<F extends Float32Array | Float64Array>(
    input: StepInputWithCameras,
    fragments: FragmentArrays<F>,
    forces: F,
  ): StepStats;
  /** Destroys the controller; calls after it throw. */
  dispose(): void;
}

export declare class Fragsim {
  private constructor();
  /** The library's version, "1.0.0". */
  readonly version: string;
  defaultControllerDef(): ControllerDef;
  defaultCameraDef(): CameraDef;
  defaultCameraPose(): CameraPose;
  defaultStepInput(): StepInput;
  createController(def?: ControllerDefInput): Controller;
}

/** Loads the WebAssembly module (inside the package: nothing is fetched). */
export default function loadFragsim(moduleOptions?: object): Promise<Fragsim>;
