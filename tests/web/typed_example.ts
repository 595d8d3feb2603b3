// Checked by `tsc --noEmit --strict` against the installed package's declarations
// (tests/web/package_test.sh), never run: the last two calls must not type-check.
import loadFragsim, { Controller, FragsimError, Warning, type StepStats } from 'fragsim-control';

const fragsim = await loadFragsim();
const def = fragsim.defaultControllerDef();
const controller: Controller = fragsim.createController({
  strategy: 'edge-min',
  edgeMin: { aMaxMps2: 2 * def.edgeMin.aMaxMps2, cameraModel: 'reachable' },
});
controller.setCameras([{ fovyDeg: 60, aspect: 16 / 9, bodyHalfM: { x: 0.2, y: 0.2, z: 0.2 } }]);
controller.reserve(1024);

const forces = new Float64Array(3);
const stats: StepStats = controller.step(
  { dtS: 1 / 60, groundHeightM: 0, cameras: [{ eyeM: [0, 1.6, 0], velocityMps: { x: 0, y: 0, z: -2 } }] },
  {
    position: new Float64Array([0, 1.6, -3]),
    velocity: new Float64Array([0, 0, 9]),
    radius: new Float64Array([0.05]),
    mass: new Float64Array([1]),
    id: new BigUint64Array([1n]),
  },
  forces,
);
if ((stats.warnings & Warning.UNPROTECTED) !== 0) console.log(`${stats.unprotected} unprotected`);
try {
  controller.setCameras([]);
} catch (error) {
  if (error instanceof FragsimError) console.log(error.status, error.code);
}
controller.dispose();

// @ts-expect-error: a strategy the library does not have
fragsim.createController({ strategy: 'edgemin' });
controller.step(
  { cameras: [{}] },
  {
    position: new Float32Array(3),
    velocity: new Float32Array(3),
    radius: new Float32Array(1),
    mass: new Float32Array(1),
    id: new Uint32Array(1),
  },
  // @ts-expect-error: forces of another float type than the fragments'
  new Float64Array(3),
);
