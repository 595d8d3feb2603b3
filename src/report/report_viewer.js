// The report's 3D player (src/report/report_viewer.hpp writes its data). Runs as an inline module
// script: three.js comes from the page itself as a data: URL, so the page opens offline from disk.
// #viewer's data-state ends as "ready" once a frame is drawn, or "failed" with the reason shown
// and logged as a console error (the browser test fails on either).

const root = document.getElementById('viewer');
const statusLine = document.getElementById('viewer-status');

function fail(message) {
  root.dataset.state = 'failed';
  statusLine.textContent = 'The 3D view failed: ' + message;
  console.error('3D view: ' + message);
}

async function start() {
  const data = JSON.parse(document.getElementById('viewer-data').textContent);
  const source = document.getElementById('three-module').textContent.trim();
  const THREE = await import('data:text/javascript;base64,' + source);

  const canvas = document.getElementById('viewer-canvas');
  let renderer;
  try {
    renderer = new THREE.WebGLRenderer({canvas, antialias: true, preserveDrawingBuffer: true});
  } catch (e) {
    fail('WebGL is not available in this browser (' + e.message + ')');
    return;
  }
  renderer.setPixelRatio(1);
  renderer.setScissorTest(true);
  const background = new THREE.Color(0xf4f6f8);

  const geometries = data.meshes.map(m => {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(m.v, 3));
    g.setIndex(m.t);
    // Flat shading: face normals from non-indexed triangles read best on small convex pieces.
    const flat = g.toNonIndexed();
    flat.computeVertexNormals();
    return flat;
  });
  // Both sides drawn: a piece the near plane cuts shows its inside, as the game would.
  const materials = [0x8d99a6, 0xf08c00, 0xd62828].map(  // a piece, pushed, cut by the near plane
      color => new THREE.MeshLambertMaterial({color, side: THREE.DoubleSide}));
  const pieceCount = data.piece_mesh.length;

  function decode(run) {
    const bytes = Uint8Array.from(atob(run.poses), c => c.charCodeAt(0));
    const samples = run.t_s.length;
    const nPos = samples * pieceCount * 3, nRot = samples * pieceCount * 4;
    return {
      position: new Int16Array(bytes.buffer, 0, nPos),
      rotation: new Int16Array(bytes.buffer, 2 * nPos, nRot),
      flags: new Uint8Array(bytes.buffer, 2 * (nPos + nRot), samples * pieceCount),
    };
  }

  const views = new Map();  // strategy -> its scene, pieces, frustum and decoded poses
  function view(strategy) {
    if (views.has(strategy)) return views.get(strategy);
    const run = data.runs.find(r => r.strategy === strategy);
    const scene = new THREE.Scene();
    scene.background = background;
    scene.add(new THREE.HemisphereLight(0xffffff, 0x70665a, 2.2));
    const sun = new THREE.DirectionalLight(0xffffff, 1.6);
    sun.position.set(0.4, 1, 0.3);
    scene.add(sun);
    if (data.ground) {
      const ground = new THREE.Mesh(new THREE.PlaneGeometry(400, 400),
                                    new THREE.MeshLambertMaterial({color: 0xd8d2c4}));
      ground.rotation.x = -Math.PI / 2;
      ground.position.set(target.x, data.ground_height_m, target.z);
      scene.add(ground);
    }
    const pieces = data.piece_mesh.map(m => {
      const mesh = new THREE.Mesh(geometries[m], materials[0]);
      scene.add(mesh);
      return mesh;
    });
    // The run's camera: its frustum to a depth past the object, the near rectangle in red.
    const frustum = new THREE.LineSegments(
        new THREE.BufferGeometry().setAttribute(
            'position', new THREE.Float32BufferAttribute(new Float32Array(16 * 3), 3)),
        new THREE.LineBasicMaterial({color: 0x1d3557}));
    const nearRect = new THREE.LineLoop(
        new THREE.BufferGeometry().setAttribute(
            'position', new THREE.Float32BufferAttribute(new Float32Array(4 * 3), 3)),
        new THREE.LineBasicMaterial({color: 0xd62828}));
    // Their vertices move every frame, so three's bounding spheres (computed once) would cull them.
    frustum.frustumCulled = nearRect.frustumCulled = false;
    scene.add(frustum, nearRect);
    const v = {run, scene, pieces, frustum, nearRect, poses: decode(run)};
    views.set(strategy, v);
    return v;
  }

  const runCamera = new THREE.PerspectiveCamera(data.fovy_deg, data.aspect, 0.1, data.far_m);
  const orbitCamera = new THREE.PerspectiveCamera(50, 1, 0.05, 2000);
  // The orbit turns about the middle of the action: the box around the pieces' centre and the
  // run's camera over the whole first run (the scene may have moved the object from its nominal
  // centre, and the debris may fly past the camera). Far-flung single pieces do not count.
  const action = new THREE.Box3();
  {
    const run = data.runs[0], P = decode(run).position;
    for (let s = 0; s < run.t_s.length; ++s) {
      const centre = new THREE.Vector3();
      for (let i = 0; i < pieceCount; ++i) {
        for (let k = 0; k < 3; ++k) {
          const a = 3 * (s * pieceCount + i) + k;
          centre.setComponent(k, centre.getComponent(k) + run.lo_m[k] +
                                     (P[a] / 32767 + 1) / 2 * (run.hi_m[k] - run.lo_m[k]));
        }
      }
      action.expandByPoint(centre.divideScalar(Math.max(pieceCount, 1)));
      action.expandByPoint(new THREE.Vector3(...run.camera[s].slice(0, 3)));
    }
  }
  const target = action.getCenter(new THREE.Vector3());
  const reach = action.getSize(new THREE.Vector3()).length() / 2 + 2;
  const eye0 = new THREE.Vector3(...data.runs[0].camera[0].slice(0, 3));
  const orbit = {radius: reach / Math.sin(THREE.MathUtils.degToRad(25)), yaw: 0, pitch: 0.45};
  // Beside the run's camera, so its frustum and the debris in front of it are both in view.
  orbit.yaw = Math.atan2(eye0.x - target.x, eye0.z - target.z) + 1.1;

  const q = new THREE.Quaternion(), p = new THREE.Vector3();
  function pose(v, sample) {
    const run = v.run, P = v.poses.position, R = v.poses.rotation, F = v.poses.flags;
    const s = Math.min(sample, run.t_s.length - 1);
    const lo = run.lo_m, hi = run.hi_m;
    for (let i = 0; i < pieceCount; ++i) {
      const a = 3 * (s * pieceCount + i), b = 4 * (s * pieceCount + i);
      const piece = v.pieces[i];
      for (let k = 0; k < 3; ++k) {
        p.setComponent(k, lo[k] + (P[a + k] / 32767 + 1) / 2 * (hi[k] - lo[k]));
      }
      piece.position.copy(p);
      q.set(R[b] / 32767, R[b + 1] / 32767, R[b + 2] / 32767, R[b + 3] / 32767).normalize();
      piece.quaternion.copy(q);
      const f = F[s * pieceCount + i];
      piece.material = materials[f & 2 ? 2 : f & 1 ? 1 : 0];
    }
    const c = run.camera[s];
    runCamera.position.set(c[0], c[1], c[2]);
    runCamera.quaternion.set(c[3], c[4], c[5], c[6]);
    runCamera.near = c[7];
    runCamera.fov = data.fovy_deg;
    runCamera.aspect = data.aspect;
    runCamera.updateProjectionMatrix();
    runCamera.updateMatrixWorld();
    // Frustum corners in camera space, to the near plane and to a depth past the object.
    const depth = Math.min(data.far_m, reach);
    const corner = (d, sx, sy) => {
      const h = d * Math.tan(THREE.MathUtils.degToRad(data.fovy_deg) / 2);
      return new THREE.Vector3(sx * h * data.aspect, sy * h, -d).applyMatrix4(runCamera.matrixWorld);
    };
    const signs = [[-1, -1], [1, -1], [1, 1], [-1, 1]];
    const near = signs.map(([x, y]) => corner(c[7], x, y));
    const far = signs.map(([x, y]) => corner(depth, x, y));
    const e = runCamera.position;
    const lines = [];
    for (let k = 0; k < 4; ++k) {
      lines.push(e, far[k], far[k], far[(k + 1) % 4]);
    }
    const fa = v.frustum.geometry.attributes.position;
    lines.forEach((x, k) => fa.setXYZ(k, x.x, x.y, x.z));
    fa.needsUpdate = true;
    const na = v.nearRect.geometry.attributes.position;
    near.forEach((x, k) => na.setXYZ(k, x.x, x.y, x.z));
    na.needsUpdate = true;
  }

  const slider = document.getElementById('viewer-time');
  const clock = document.getElementById('viewer-clock');
  const leftSelect = document.getElementById('viewer-left');
  const rightSelect = document.getElementById('viewer-right');
  const modeSelect = document.getElementById('viewer-mode');
  const playButton = document.getElementById('viewer-play');

  function resize(views, cameraView) {
    const width = Math.max(320, Math.floor(root.clientWidth));
    // Through the run's camera each view keeps the run's aspect; orbiting, a fixed shape.
    const wanted = cameraView ? width / views / data.aspect : width * 0.45;
    const height = Math.round(Math.min(Math.max(wanted, 240), 720));
    if (canvas.width !== width || canvas.height !== height) renderer.setSize(width, height, true);
  }

  function draw() {
    const sample = Number(slider.value);
    const shown = [leftSelect.value, rightSelect.value].filter(s => s !== '');
    const cameraView = modeSelect.value === 'camera';
    resize(Math.max(shown.length, 1), cameraView);
    const width = canvas.width, height = canvas.height;
    renderer.setScissor(0, 0, width, height);
    renderer.setViewport(0, 0, width, height);
    renderer.setClearColor(0xffffff);
    renderer.clear();
    shown.forEach((strategy, i) => {
      const v = view(strategy);
      pose(v, sample);
      v.frustum.visible = v.nearRect.visible = !cameraView;
      let x = i * width / shown.length, w = width / shown.length, y = 0, h = height;
      let camera;
      if (cameraView) {
        // Letterboxed to the run's aspect, so the picture is the one the run's camera saw.
        if (w / h > data.aspect) {
          const fit = h * data.aspect;
          x += (w - fit) / 2;
          w = fit;
        } else {
          const fit = w / data.aspect;
          y += (h - fit) / 2;
          h = fit;
        }
        camera = runCamera;
      } else {
        orbitCamera.aspect = w / h;
        orbitCamera.updateProjectionMatrix();
        orbitCamera.position.set(
            target.x + orbit.radius * Math.cos(orbit.pitch) * Math.sin(orbit.yaw),
            target.y + orbit.radius * Math.sin(orbit.pitch),
            target.z + orbit.radius * Math.cos(orbit.pitch) * Math.cos(orbit.yaw));
        orbitCamera.lookAt(target);
        camera = orbitCamera;
      }
      renderer.setViewport(x, y, w, h);
      renderer.setScissor(x, y, w, h);
      renderer.render(v.scene, camera);
    });
    const t = data.runs[0].t_s[Math.min(sample, data.runs[0].t_s.length - 1)];
    clock.textContent = 't = ' + t.toFixed(2) + ' s';
  }

  // Play in real time: each frame shows the last sample due by the clock, skipping samples when
  // drawing is slower than the run (software WebGL).
  let playing = false, startMs = 0, startT = 0;
  function tick(now) {
    if (!playing) return;
    const t_s = data.runs[0].t_s;
    const due = startT + (now - startMs) / 1000;
    let s = Number(slider.value);
    while (s + 1 < t_s.length && t_s[s + 1] <= due) ++s;
    if (s !== Number(slider.value)) {
      slider.value = String(s);
      draw();
    }
    if (s + 1 >= t_s.length) {
      playing = false;
      playButton.textContent = 'Play';
      return;
    }
    requestAnimationFrame(tick);
  }
  playButton.addEventListener('click', () => {
    playing = !playing;
    playButton.textContent = playing ? 'Pause' : 'Play';
    if (playing) {
      if (Number(slider.value) >= Number(slider.max)) slider.value = '0';
      startMs = performance.now();
      startT = data.runs[0].t_s[Number(slider.value)];
      requestAnimationFrame(tick);
    }
  });
  for (const control of [slider, leftSelect, rightSelect, modeSelect]) {
    control.addEventListener('input', draw);
    control.addEventListener('change', draw);
  }
  window.addEventListener('resize', draw);

  // Orbit by hand (drag to turn, wheel to zoom): three's OrbitControls lives in examples/jsm and
  // would be a second module to carry; this is all the report needs.
  let drag = null;
  canvas.addEventListener('pointerdown', e => {
    drag = {x: e.clientX, y: e.clientY};
    canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener('pointerup', () => { drag = null; });
  canvas.addEventListener('pointermove', e => {
    if (!drag || modeSelect.value !== 'orbit') return;
    orbit.yaw -= (e.clientX - drag.x) * 0.01;
    orbit.pitch = Math.max(-1.5, Math.min(1.5, orbit.pitch + (e.clientY - drag.y) * 0.01));
    drag = {x: e.clientX, y: e.clientY};
    draw();
  });
  canvas.addEventListener('wheel', e => {
    if (modeSelect.value !== 'orbit') return;
    e.preventDefault();
    orbit.radius = Math.max(0.5, orbit.radius * Math.exp(e.deltaY * 0.001));
    draw();
  }, {passive: false});

  draw();
  const gl = renderer.getContext();
  if (!gl || gl.isContextLost()) {
    fail('the WebGL context was lost');
    return;
  }
  root.dataset.state = 'ready';
  statusLine.textContent = '';
  statusLine.hidden = true;
}

start().catch(e => fail(e && e.message ? e.message : String(e)));
