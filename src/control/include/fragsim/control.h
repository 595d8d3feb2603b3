/* fragsim control: keeps explosion debris off a game camera's near plane.
 *
 * Once per physics step, before the engine integrates, the game hands the controller its camera
 * and its fragments (position, velocity, size, mass, an id); the controller writes one force per
 * fragment, in newtons, for the engine to apply during that step. Most forces are zero: only the
 * fragments whose paths would meet the camera are pushed, toward the nearest screen edge, so they
 * leave the picture through its border instead of being cut open by the near plane.
 *
 *   fragsim_controller_def def = fragsim_default_controller_def();
 *   fragsim_controller_id ctl;
 *   if (fragsim_controller_create(&def, &ctl, NULL, 0) != FRAGSIM_OK) { ... }
 *   fragsim_step_input in = fragsim_default_step_input();   (never "= {0}": see below)
 *   each physics step: set in's camera pose and velocity, time and fragments, call
 *   fragsim_controller_step, apply the forces (the rules for engines: "Applying the forces")
 *   fragsim_controller_destroy(ctl);
 * or, the camera's constants set once (and several cameras, since 0.7):
 *   fragsim_camera_def cam = fragsim_default_camera_def();  (set fovy_deg, body, bounds)
 *   fragsim_controller_set_cameras(ctl, &cam, 1);
 *   fragsim_camera_pose pose;  in.camera_poses = &pose;  in.camera_count = 1;
 *   each physics step: set pose (eye, axes, velocity), time and fragments, step as above
 *
 * DOUBLES, or floats where said. Every number this header passes is a double (fragsim_vec3 is
 * three doubles), except the strided arrays of fragsim_controller_step_arrays, which since 0.6 may
 * be floats (fragsim_fragment_arrays.scalar_type). A float array handed where doubles are expected
 * is read as garbage (tiny numbers such as 1.6e-314) and nothing can check it: say FLOAT.
 *
 * ANY UP AXIS (since 0.6). The ground is the plane dot(ground_normal, p) = ground_height_m and
 * gravity any vector: a Z-up engine passes ground_normal (0, 0, 1) and its own coordinates.
 *
 * CAMERAS SET ONCE, AND SEVERAL OF THEM (since 0.7). fragsim_controller_set_cameras keeps what
 * does not move (frustum, body, declared bounds) on the controller, for 1 to FRAGSIM_MAX_CAMERAS
 * cameras; each step then passes only their poses (step input camera_poses, camera_count). A
 * step with camera_count 0 (the default) still takes its one camera whole from input.camera.
 *
 * Threads: the library creates none. Its one global is the table of controller slots behind the
 * ids (created and destroyed under a lock). One controller must be used by one thread at a time
 * (its calls are not synchronised); different controllers are independent and may be used from
 * different threads at once. fragsim_default_*, fragsim_version* and fragsim_status_string are
 * safe from any thread.
 *
 * Errors: every function that can fail returns a fragsim_status; no function throws, aborts or
 * writes a non-finite number to the caller. Units are SI, in every field's name: _m metres, _mps
 * metres per second, _mps2 metres per second squared, _s seconds, _kg kilograms, _N newtons,
 * _deg degrees, _degps and _radps degrees and radians per second.
 *
 * Special values, each with one meaning wherever it appears:
 *   FRAGSIM_UNDECLARED (-1)  a camera bound the game does not declare: the def's assumption applies
 *   INFINITY                 no bound at all (camera bounds), no end (end_time_s)
 *   -INFINITY                no ground (ground_height_m, whatever ground_normal)
 *   0                        zero, as a number: a camera whose max_speed_mps is 0 cannot move, one
 *                            whose max_turn_radps is 0 cannot turn; a fragment of mass 0 cannot be
 *                            pushed (it is examined, gets no force, and stats.unprotected counts it
 *                            when it threatens the camera)
 *
 * Applying the forces, in an engine with a fixed physics substep (Bullet, PhysX, Jolt, ODE):
 *   1. Call fragsim_controller_step once per physics substep, before the substep, with that
 *      substep's dt_s and the state the last substep left (not once per rendered frame).
 *   2. Apply each force for that one substep only, never as a force that persists: in Bullet an
 *      impulse F dt_s (applyCentralImpulse) from the pre-tick callback. (Bullet clears forces
 *      only after all of a frame's substeps, and clearing them after each one also drops the
 *      gravity it adds once per frame.)
 *   3. Wake a sleeping body you push (Bullet: activate(true)); the controller pushes only what
 *      moves, but a pushed body must integrate.
 *   4. Pass the camera as the physics sees it at the start of the substep: its pose interpolated
 *      to the substep's time and its velocity over the substep (the pose the renderer shows at the
 *      frame's end is up to one substep late). Declare the camera's bounds (max_speed_mps, and
 *      max_accel_mps2 / max_turn_radps or FRAGSIM_UNDECLARED) as the game enforces them.
 *   5. fragsim_fragment.touched (and the arrays' touched) is read only by the `edge` strategy with
 *      replan = CONTACT; the default edge-min never reads it: leave it 0, or the array NULL, and
 *      do not walk the engine's contact lists for it.
 *
 * C99; also compiles as C++. */
#ifndef FRAGSIM_CONTROL_H
#define FRAGSIM_CONTROL_H

#include <stddef.h>
#include <stdint.h>

/* Before 1.0 a minor version may change the structs, so the shared library is named for it
 * (libfragsim_control.so.0.7): a program built against another minor is not loaded with it. */
#define FRAGSIM_CONTROL_VERSION_MAJOR 0
#define FRAGSIM_CONTROL_VERSION_MINOR 7
#define FRAGSIM_CONTROL_VERSION_PATCH 0
/* major * 10000 + minor * 100 + patch, for #if comparisons. */
#define FRAGSIM_CONTROL_VERSION                                                  \
  (FRAGSIM_CONTROL_VERSION_MAJOR * 10000 + FRAGSIM_CONTROL_VERSION_MINOR * 100 + \
   FRAGSIM_CONTROL_VERSION_PATCH)

/* FRAGSIM_API marks every function of the library. FRAGSIM_CONTROL_STATIC is defined by the
 * static library's CMake target (fragsim::control_static); define it yourself when linking the
 * static archive some other way (it matters on Windows only). FRAGSIM_CONTROL_BUILDING is defined
 * while building the library. */
#if defined(FRAGSIM_CONTROL_STATIC)
#define FRAGSIM_API
#elif defined(_WIN32)
#if defined(FRAGSIM_CONTROL_BUILDING)
#define FRAGSIM_API __declspec(dllexport)
#else
#define FRAGSIM_API __declspec(dllimport)
#endif
#elif defined(__GNUC__)
#define FRAGSIM_API __attribute__((visibility("default")))
#else
#define FRAGSIM_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fragsim_vec3 {
  double x, y, z;
} fragsim_vec3;

/* The most fragments one call takes (INT32_MAX / 4: the controller's indices stay in 32 bits). */
#define FRAGSIM_MAX_FRAGMENTS 536870911
/* The most controllers alive at once in one process. */
#define FRAGSIM_MAX_CONTROLLERS 65536
/* The most cameras one controller protects at once (split-screen, two eyes of a headset). */
#define FRAGSIM_MAX_CAMERAS 8
/* A camera bound the game does not declare (fragsim_camera.max_accel_mps2, max_turn_radps). */
#define FRAGSIM_UNDECLARED (-1.0)

/* A controller, by id: a slot and the generation of its use, so an id kept after
 * fragsim_controller_destroy (or never created: all zero) is refused with
 * FRAGSIM_ERROR_STALE_ID, never followed to freed memory. Plain data: copy it freely. */
typedef struct fragsim_controller_id {
  uint32_t index1; /* slot + 1; 0: no controller */
  uint32_t generation;
} fragsim_controller_id;

typedef enum fragsim_status {
  FRAGSIM_OK = 0,
  FRAGSIM_ERROR_NULL_ARGUMENT = 1, /* a required pointer is NULL */
  FRAGSIM_ERROR_DEF_NOT_DEFAULTED =
      2,                              /* the def did not come from fragsim_default_controller_def */
  FRAGSIM_ERROR_INVALID_ARGUMENT = 3, /* a number out of range or not finite, a bad enum value */
  FRAGSIM_ERROR_DUPLICATE_ID = 4,     /* two fragments of one call share an id */
  FRAGSIM_ERROR_OUT_OF_MEMORY = 5,    /* the controller is as before the call */
  FRAGSIM_ERROR_INTERNAL = 6, /* a computed force was not finite (a bug: please report it) */
  FRAGSIM_ERROR_STALE_ID = 7  /* the controller id was destroyed, or never created (since 0.5) */
} fragsim_status;

/* Which force strategy the controller runs (fragsim's README compares them). */
typedef enum fragsim_strategy {
  /* The least constant push that takes a fragment just past the nearest screen edge before it
   * arrives, re-solved every step: no gain to tune; the recommended choice. */
  FRAGSIM_STRATEGY_EDGE_MIN = 0,
  /* The 2012 thesis's method: candidates by the camera's reachable ball, force k |V| / (d^2 t). */
  FRAGSIM_STRATEGY_EDGE = 1,
  /* Every approaching fragment within range pushed away from the view axis (a baseline). */
  FRAGSIM_STRATEGY_DEFLECT_ALL = 2
} fragsim_strategy;

/* What edge-min assumes the camera does before a fragment arrives. */
typedef enum fragsim_camera_model {
  FRAGSIM_CAMERA_CONSTANT = 0,      /* keeps its present velocity and orientation */
  FRAGSIM_CAMERA_BOUNDED_ACCEL = 1, /* may accelerate and turn within bounds */
  FRAGSIM_CAMERA_REACHABLE = 2      /* may be anywhere within V_c t of where it is */
} fragsim_camera_model;

typedef enum fragsim_edge_predictor {
  FRAGSIM_EDGE_PREDICTOR_THESIS = 0,  /* the parabola from the velocity as read */
  FRAGSIM_EDGE_PREDICTOR_DISCRETE = 1 /* semi-implicit Euler's parabola, velocity + g dt / 2 */
} fragsim_edge_predictor;

typedef enum fragsim_edge_reach {
  FRAGSIM_EDGE_REACH_THESIS = 0, /* the fixed ball V_c (t_G - t) around the camera */
  FRAGSIM_EDGE_REACH_GROWING = 1 /* the ball V_c (t - now) that grows with time: fewer candidates */
} fragsim_edge_reach;

typedef enum fragsim_edge_horizon {
  FRAGSIM_EDGE_HORIZON_CAMERA =
      0,                          /* a fragment "lands" when it falls through the camera's height */
  FRAGSIM_EDGE_HORIZON_GROUND = 1 /* ... through the ground height */
} fragsim_edge_horizon;

typedef enum fragsim_edge_replan {
  FRAGSIM_EDGE_REPLAN_NEVER = 0,   /* the thesis: a fragment is examined only while a candidate */
  FRAGSIM_EDGE_REPLAN_CONTACT = 1, /* ... and again after it touched something or was pushed */
  FRAGSIM_EDGE_REPLAN_ALWAYS = 2   /* every fragment every step: safest, slowest */
} fragsim_edge_replan;

typedef struct fragsim_edge_min_def {
  /* Clearance kept beyond the screen edge. Larger: safer against camera moves, more fragments
   * pushed and further. Default 0.05. */
  double margin_m;
  /* Cap on the imposed acceleration. Higher saves close explosions but makes the swerve visible;
   * lower looks natural but lets close fragments through (stats.capped counts them). Default 50. */
  double a_max_mps2;
  /* What the camera is assumed to do before a fragment arrives (fragsim's docs/camera_models.md).
   * CONSTANT pushes least but a player who swerves can close on a pushed fragment; the default
   * FRAGSIM_CAMERA_BOUNDED_ACCEL promises a miss while the camera honours its bounds. */
  fragsim_camera_model camera_model;
  /* Camera acceleration assumed when the camera declares no bound (max_accel_mps2 = 0), for the
   * bounded-acceleration model. Larger: more fragments pushed. Default 20. */
  double camera_accel_mps2;
  /* Turn rate assumed when the camera declares none (max_turn_radps = FRAGSIM_UNDECLARED), for
   * the robust models; INFINITY or a number in [0, 1e6]. INFINITY: no bound, safe against any
   * turn (mouse flicks): each side of the protected region reaches at once as far as any
   * orientation of it can, the distance of its farthest corner from the eye. A finite bound
   * gives a region never larger than that. Larger: more fragments pushed. Default INFINITY
   * (since 0.7; 90 before, which a game keeps by setting 90). */
  double camera_turn_degps;
  /* Per-step budget: at most this many fragments that survive the cheap rejection are solved
   * exactly per call, the soonest to arrive first (distance to the eye over closing speed); the
   * others are deferred and get the force of the last call that solved them (kept per id; none
   * for a fragment never solved), and stats.deferred counts them. Smaller: a bounded cost per
   * call, and late or stale pushes when many fragments threaten at once. 0 (default): no cap. */
  int32_t max_solves;
  /* Since 0.4. The ways out, weighed: each push goes toward the screen edge of least push divided
   * by its weight, in the order top, bottom, left, right; 0 forbids an edge (not all four), each
   * in [0, 1e6]. Default 1 1 1 1. Only pushed fragments change their way out, and a push is the
   * least that clears the camera, so a fragment may still leave by a forbidden edge (fragsim's
   * docs/visibility.md). */
  double edge_weights[4];
  /* Since 0.4. An occlusion bound: the share of the central region (cover_region of the screen's
   * width and height) that fragments are predicted to cover over the coming second may not
   * exceed cover_max; the fragments that cover most per unit of push are pushed out of it. Each
   * fragment is seen as a disc of its radius_m (its bounding sphere's shadow, so the cover is
   * overestimated). 1 (default): off. Smaller: a clearer view, at much more deviation (fragsim's
   * docs/visibility.md). In [0, 1]. */
  double cover_max;
  double cover_region; /* in (0, 1]; default 0.5 */
} fragsim_edge_min_def;

typedef struct fragsim_edge_def {
  /* Gain of the thesis's force (3.4). Larger saves close explosions and over-steers distant ones
   * (the thesis's fig. 4.6). Default 1. */
  double k_Nms2;
  /* Cap on the imposed acceleration. Default 50. */
  double a_max_mps2;
  fragsim_edge_predictor predictor; /* default FRAGSIM_EDGE_PREDICTOR_THESIS */
  fragsim_edge_reach reach;         /* default FRAGSIM_EDGE_REACH_THESIS */
  fragsim_edge_horizon horizon;     /* default FRAGSIM_EDGE_HORIZON_CAMERA */
  fragsim_edge_replan replan;       /* default FRAGSIM_EDGE_REPLAN_NEVER */
} fragsim_edge_def;

typedef struct fragsim_deflect_all_def {
  /* Push away from the view axis. Larger clears faster and looks more forced. Default 60. */
  double accel_mps2;
  /* Only fragments closer than this to the eye are pushed. Larger: more fragments moved. 6. */
  double range_m;
} fragsim_deflect_all_def;

/* Since 0.6. The controller's allocator (fragsim_controller_def.alloc_fn, free_fn): every
 * allocation a controller makes (the controller itself, its per-id tables, its work arrays, its
 * strategy's state) is alloc_fn(size, alignment, alloc_user), freed by free_fn(pointer, size,
 * alignment, alloc_user) with the same size and alignment. alignment is a power of two, at most
 * alignof(max_align_t) in practice. alloc_fn returns NULL when it cannot: the call then returns
 * FRAGSIM_ERROR_OUT_OF_MEMORY with the controller as before it. Called only from within the
 * controller's own calls (create, reserve, step, reset, destroy), on the calling thread. */
typedef void* (*fragsim_alloc_fn)(size_t size, size_t alignment, void* user);
typedef void (*fragsim_free_fn)(void* pointer, size_t size, size_t alignment, void* user);

/* Settings of one controller. Must be initialised with fragsim_default_controller_def(), then
 * changed field by field; fragsim_controller_create refuses a def that was not. Each number must
 * keep the range of fragsim's scene key of the same meaning (docs/guide.md, scene keys: edge-min.*,
 * edge.*, deflect-all.*; e.g. a_max_mps2 in [0, 1e9], horizon_cap_s in (0, 3600]); otherwise
 * fragsim_controller_create names the field and the rule. */
typedef struct fragsim_controller_def {
  fragsim_strategy strategy; /* default FRAGSIM_STRATEGY_EDGE_MIN */
  fragsim_edge_min_def edge_min;
  fragsim_edge_def edge;
  fragsim_deflect_all_def deflect_all;
  /* The look-ahead's cap. The horizon comes from the physics: edge-min examines a fragment's
   * path until it reaches the ground (its centre at ground_height_m plus its radius, going down:
   * the path means nothing after it bounces), edge until it falls through its horizon height
   * (t_G); a path that never comes down (no ground, gravity off) is examined this far ahead, and
   * none further (nor past step input end_time_s when sooner). Longer: threats seen earlier and
   * pushed more gently, more paths examined, and more pushes that a later camera move makes
   * needless. Default 3: a thrown fragment at 10 m/s covers 30 m. */
  double horizon_cap_s;
  /* Since 0.6. The game's allocator (fragsim_alloc_fn above): both NULL (the default) for the C++
   * runtime's operator new and delete; one without the other is refused
   * (FRAGSIM_ERROR_INVALID_ARGUMENT). alloc_user (default NULL) is passed to both as it is. The
   * one allocation it cannot take: the process-wide table of controller ids grows by a chunk of
   * 256 slots through operator new when the 1st, 257th, ... controller alive at once is created
   * (never freed); and the first fragsim_controller_create of a process builds the tables of the
   * parameters' rules (once, through operator new). */
  fragsim_alloc_fn alloc_fn;
  fragsim_free_fn free_fn;
  void* alloc_user;
  /* Private: set by fragsim_default_controller_def; do not touch. */
  int32_t internal_value;
} fragsim_controller_def;

/* The camera at the start of the step: the C form of fragsim's pose, body and declared limits. */
typedef struct fragsim_camera {
  fragsim_vec3 eye_m;
  /* Orthonormal (each unit length and at right angles within 1e-6): screen right, screen up and
   * the view direction, in world coordinates. */
  fragsim_vec3 right;
  fragsim_vec3 up;
  fragsim_vec3 forward;
  fragsim_vec3 velocity_mps; /* the eye's velocity over the step being taken */
  /* Vertical field of view in DEGREES, in (0, 180); below 5 it is likely radians and sets
   * FRAGSIM_WARNING_FOVY_IN_RADIANS. */
  double fovy_deg;
  double aspect; /* width over height, > 0 */
  double near_m; /* near clip distance, > 0 */
  double far_m;  /* far clip distance, > near_m */
  /* Half size of the camera's body, a box centred on the eye, along right, up and forward (the
   * camera's own axes, so it does not depend on the world's up axis); >= 0. */
  fragsim_vec3 body_half_m;
  /* V_c: the fastest the player can move the camera; >= 0 (0: a camera that cannot move). A
   * camera moving faster than it declares breaks the promise the robust models keep:
   * stats.warnings gets FRAGSIM_WARNING_CAMERA_OVER_SPEED. */
  double max_speed_mps;
  /* The camera's declared bounds (since 0.5; before, 0 meant undeclared): FRAGSIM_UNDECLARED
   * where the game declares none (edge-min's robust models then assume the def's
   * camera_accel_mps2 and camera_turn_degps); INFINITY where there is none (a player who changes
   * velocity at once: the bounded model then keeps only the ball V_c t, the reachable model's
   * region; a view that turns at once: every orientation, as camera_turn_degps = INFINITY);
   * else the bound, >= 0 (0: cannot accelerate, cannot turn). Radians per second for
   * the turn: a value above 60 (3,400 degrees a second) is likely degrees and sets
   * FRAGSIM_WARNING_TURN_IN_DEGREES. NaN and other negatives are refused. */
  double max_accel_mps2;
  double max_turn_radps;
} fragsim_camera;

/* Since 0.7. What a camera keeps from step to step: fragsim_camera's constant fields, the same
 * meanings and rules (set with fragsim_controller_set_cameras). */
typedef struct fragsim_camera_def {
  double fovy_deg;
  double aspect;
  double near_m;
  double far_m;
  fragsim_vec3 body_half_m;
  double max_speed_mps;
  double max_accel_mps2;
  double max_turn_radps;
} fragsim_camera_def;

/* Since 0.7. What moves: fragsim_camera's pose and velocity, the same meanings and rules. */
typedef struct fragsim_camera_pose {
  fragsim_vec3 eye_m;
  fragsim_vec3 right; /* orthonormal (within 1e-6), as in fragsim_camera */
  fragsim_vec3 up;
  fragsim_vec3 forward;
  fragsim_vec3 velocity_mps;
} fragsim_camera_pose;

/* One fragment as the engine sees it after its last step. A fragment whose numbers break a rule
 * below (a NaN position, a negative or infinite mass: a static body) is skipped, not refused: it
 * gets a zero force, the others are protected as usual, and stats.skipped and
 * stats.first_skipped say which. */
typedef struct fragsim_fragment {
  fragsim_vec3 position_m;   /* centre of mass; finite */
  fragsim_vec3 velocity_mps; /* linear velocity; finite */
  double radius_m;           /* bounding sphere radius; finite, >= 0 */
  /* Finite, >= 0; the force is mass times the chosen acceleration. 0: cannot be pushed (see the
   * special values above). */
  double mass_kg;
  /* The engine's handle for this fragment, unique within a call (a repeated id refuses the call:
   * FRAGSIM_ERROR_DUPLICATE_ID). The controller keeps state per id between calls; an id it has
   * not seen before is a new fragment. */
  uint64_t id;
  uint8_t
      touched; /* nonzero: had a contact in the last step (read by edge's replan = CONTACT only) */
} fragsim_fragment;

/* Everything one step needs. Start from fragsim_default_step_input(), never from "= {0}" (a zero
 * end_time_s would say the shot has ended, a zero camera could not move); keep it and update what
 * moves each step. */
typedef struct fragsim_step_input {
  /* The caller's clock at the start of this step. Only differences of times are used. */
  double time_s;
  /* When the shot ends, if known (a cut-scene): an optional extra cap, no path is examined past
   * it; INFINITY (the default) in a game, and in fragsim itself. Must be after time_s: a step at
   * or past the end is refused (FRAGSIM_ERROR_INVALID_ARGUMENT), since it could protect
   * nothing. */
  double end_time_s;
  double dt_s;               /* the coming physics step, > 0; default 1/60 */
  fragsim_vec3 gravity_mps2; /* default (0, -9.81, 0); any direction (since 0.6) */
  /* The ground plane: the points p with dot(ground_normal, p) = ground_height_m, its offset along
   * ground_normal (before 0.6: the height y of a y-up ground, which the default normal keeps).
   * -INFINITY (the default): no ground, so every path is examined to the def's horizon_cap_s
   * (safe, more work). Fragments fly on the side the normal points to. */
  double ground_height_m;
  /* Since 0.6. The ground's unit normal, pointing up, in world coordinates: (0, 1, 0) by default
   * (y up), (0, 0, 1) for a z-up engine (Unreal, Blender), any unit vector for a sloped ground.
   * Finite, of length 1 within 1e-6 (it is normalised); a zero normal (a zero-initialised input)
   * is refused, FRAGSIM_ERROR_INVALID_ARGUMENT. The controller works in a frame where the normal
   * is +y: for a normal along a coordinate axis (+-x, +-y, +-z) the change of frame is a signed
   * permutation of the coordinates and rounds nothing (the forces are those of the same scene
   * given y-up, rotated, to the bit); any other normal costs a rotation's rounding (about 1e-15
   * relative). The controller keeps state per fragment between steps in that frame: a step whose
   * normal differs (bit for bit) from the last successful step's forgets every fragment, as
   * fragsim_controller_reset does (stats.new_ids counts them all). */
  fragsim_vec3 ground_normal;
  /* The camera when camera_count is 0 (the default): its pose and its constants, whole. Ignored
   * when camera_count > 0. */
  fragsim_camera camera;
  const fragsim_fragment* fragments; /* may be NULL when fragment_count is 0 */
  int32_t fragment_count;            /* >= 0 */
  /* Since 0.7. 0 (the default): one camera, input.camera. Otherwise the number of cameras the
   * controller was given by fragsim_controller_set_cameras (another number is refused,
   * FRAGSIM_ERROR_INVALID_ARGUMENT), and camera_poses their poses in the same order.
   *
   * With several cameras every fragment is kept off every camera's near rectangle and body: each
   * camera's strategy runs as for one camera, and a fragment pushed for one camera is then checked
   * against the others with that push applied. edge-min settles them in rounds: where another
   * camera still sees a threat on the pushed path, its least extra push is added, until every
   * camera is clear (two eyes of a headset, cameras apart) or FRAGSIM_CAMERA_ROUNDS rounds are
   * spent: the fragment is then a conflict (stats.conflicts; its force is the last round's,
   * capped at a_max_mps2, finite). Two cameras conflict where one's way out of the picture leads
   * into the other's box: side-by-side cameras whose boxes lie closer than a fragment's diameter,
   * or facing cameras a fragment passes between (fragsim's docs/camera_models.md, "Several
   * cameras"). edge and deflect-all add each camera's force (no rounds, no conflicts counted).
   * A step whose camera count differs from the last successful step's forgets every fragment, as
   * fragsim_controller_reset does. */
  const fragsim_camera_pose* camera_poses;
  int32_t camera_count;
} fragsim_step_input;

/* Since 0.7. The most rounds edge-min spends settling one fragment's pushes for several cameras:
 * in each, every camera that still sees a threat on the pushed path adds its least extra push. */
#define FRAGSIM_CAMERA_ROUNDS 4

/* Since 0.6. The type of the numbers in fragsim_fragment_arrays. */
typedef enum fragsim_scalar_type {
  FRAGSIM_SCALAR_DOUBLE = 0, /* double (the default, and what a zeroed struct says) */
  FRAGSIM_SCALAR_FLOAT = 1   /* float: read, converted to double exactly, forces rounded back */
} fragsim_scalar_type;

/* The same fragments as strided arrays the engine already has: element i of an array is at byte
 * offset i * stride from its start (no alignment needed). With scalar_type DOUBLE: position_m,
 * velocity_mps 3 doubles each, radius_m, mass_kg one double, force_N (the output) 3 doubles per
 * fragment; with FLOAT, floats in each of these places. id: one uint64_t; touched: one uint8_t,
 * or NULL for "no contacts" (what the default edge-min needs). Each stride is at least its
 * element's size (24 bytes for 3 doubles, 12 for 3 floats, 8 for a double or an id, 4 for a
 * float, 1 for touched); with count > 1 a smaller one (0 included) is refused,
 * FRAGSIM_ERROR_INVALID_ARGUMENT, and a refused call writes zeros to force_N only when its
 * scalar_type and (count > 1) force stride are valid: otherwise its layout is unknown.
 *
 * The number arrays are void pointers (since 0.6; const double* and double* before): one field
 * takes a double* or a float* without a cast in C and C++, where a union or a second set of
 * fields would make every caller name the type twice, and scalar_type says which it is. A float
 * input is converted to double exactly, the controller computes in double as for doubles, and
 * each force is the double force rounded to the nearest float: no second code path. */
typedef struct fragsim_fragment_arrays {
  const void* position_m;
  size_t position_stride_bytes;
  const void* velocity_mps;
  size_t velocity_stride_bytes;
  const void* radius_m;
  size_t radius_stride_bytes;
  const void* mass_kg;
  size_t mass_stride_bytes;
  const uint64_t* id;
  size_t id_stride_bytes;
  const uint8_t* touched;
  size_t touched_stride_bytes;
  void* force_N;
  size_t force_stride_bytes;
  /* Since 0.6: a fragsim_scalar_type, FRAGSIM_SCALAR_DOUBLE (0) by default. Any other value is
   * refused, FRAGSIM_ERROR_INVALID_ARGUMENT naming arrays.scalar_type. */
  fragsim_scalar_type scalar_type;
} fragsim_fragment_arrays;

/* Bits of fragsim_step_stats.warnings: input that is legal but looks like a mistake. In builds
 * without NDEBUG the library also prints each kind once per controller to stderr. */
#define FRAGSIM_WARNING_CAMERA_OVER_SPEED 1u /* |camera.velocity_mps| > camera.max_speed_mps */
#define FRAGSIM_WARNING_FOVY_IN_RADIANS 2u   /* camera.fovy_deg < 5 */
#define FRAGSIM_WARNING_TURN_IN_DEGREES 4u   /* camera.max_turn_radps finite and > 60 */

/* What one step did. */
typedef struct fragsim_step_stats {
  int32_t candidates; /* fragments whose path was found to threaten the camera */
  int32_t pushed;     /* fragments given a nonzero force (since 0.5: a zero force is not counted) */
  int32_t capped;     /* forces a_max cut down: these fragments may still hit */
  int32_t guarded;    /* singular spots guarded (a fragment at the eye, a contact now) */
  int32_t new_ids;    /* fragments whose id the controller had not seen at its last step */
  int32_t dropped_ids; /* ids of the last step absent from this one (their state is forgotten) */
  int32_t deferred; /* fragments edge_min.max_solves left unsolved (they kept their last force) */
  /* Since 0.3: fragments (a count, 0 to fragment_count) that edge-min's cheap box rejection
   * settled as certainly clear before any exact solve; rejected_cheaply / fragment_count is the
   * share of the step's work that took the fast path. 0 for edge and deflect-all. */
  int32_t rejected_cheaply;
  /* Since 0.5. Fragments skipped for numbers that break fragsim_fragment's rules (they got a zero
   * force), and the index of the first of them in the call's order (-1: none). */
  int32_t skipped;
  int32_t first_skipped;
  /* Since 0.5. Fragments that threaten the camera and got no force: mass 0 (cannot be pushed). */
  int32_t unprotected;
  uint32_t warnings; /* since 0.5: FRAGSIM_WARNING_* bits (of any camera) */
  /* Since 0.7, several cameras only: fragments whose pushes did not settle (see camera_count:
   * one camera's way out leads into another's box), and the index of the first (-1: none). */
  int32_t conflicts;
  int32_t first_conflict;
} fragsim_step_stats;

/* The library's version, FRAGSIM_CONTROL_VERSION of the build (compare with the header's). */
FRAGSIM_API int32_t fragsim_version(void);
FRAGSIM_API const char* fragsim_version_string(void);

/* A short English name of a status ("invalid argument"); never NULL. */
FRAGSIM_API const char* fragsim_status_string(fragsim_status status);

FRAGSIM_API fragsim_controller_def fragsim_default_controller_def(void);

/* A still camera at the origin looking down -z, fragsim's default frustum (fovy 60, 16:9, near
 * 0.1 m, far 500 m), body 0.3 x 0.2 x 0.3 m, V_c 3 m/s, acceleration and turn FRAGSIM_UNDECLARED.
 */
FRAGSIM_API fragsim_camera fragsim_default_camera(void);

/* Since 0.7. fragsim_default_camera()'s constants, and its pose (at the origin, looking down -z,
 * still). */
FRAGSIM_API fragsim_camera_def fragsim_default_camera_def(void);
FRAGSIM_API fragsim_camera_pose fragsim_default_camera_pose(void);

/* Since 0.5. A step input to start from: time 0, no end (INFINITY), dt 1/60 s, gravity
 * (0, -9.81, 0), no ground (-INFINITY), ground normal (0, 1, 0) (since 0.6),
 * fragsim_default_camera(), no fragments, camera_count 0 and camera_poses NULL (since 0.7). */
FRAGSIM_API fragsim_step_input fragsim_default_step_input(void);

/* True for the all-zero id (no controller); says nothing of whether a nonzero id is alive. */
static inline int fragsim_controller_id_is_null(fragsim_controller_id id) {
  return id.index1 == 0;
}

/* Creates a controller. On failure *out_controller is the null id and, when message is not NULL,
 * a NUL-terminated reason naming the field and its value is written there (cut to
 * message_size). */
FRAGSIM_API fragsim_status fragsim_controller_create(const fragsim_controller_def* def,
                                                     fragsim_controller_id* out_controller,
                                                     char* message, size_t message_size);

/* Destroys a controller. FRAGSIM_ERROR_STALE_ID for an id already destroyed (destroying twice is
 * refused, not a crash), FRAGSIM_OK for the null id (nothing to do). */
FRAGSIM_API fragsim_status fragsim_controller_destroy(fragsim_controller_id controller);

/* Nonzero while the id names a live controller. */
FRAGSIM_API int fragsim_controller_is_valid(fragsim_controller_id controller);

/* Forgets every fragment: the next step treats all ids as new. Keeps the capacity reserved;
 * allocates nothing. */
FRAGSIM_API fragsim_status fragsim_controller_reset(fragsim_controller_id controller);

/* Since 0.5. Makes room for fragment_count fragments now (in [0, FRAGSIM_MAX_FRAGMENTS]), so the
 * explosion's step (every id new) does not pay for growing the controller's work space. A step
 * with at most that many fragments allocates nothing once the controller has seen a step of that
 * many (a step with new ids may still grow the hash table of ids it keeps). */
FRAGSIM_API fragsim_status fragsim_controller_reserve(fragsim_controller_id controller,
                                                      int32_t fragment_count);

/* Since 0.7. Sets the constants of the controller's cameras, camera_count of them in
 * [1, FRAGSIM_MAX_CAMERAS] (each checked as fragsim_camera's fields are, a failure naming
 * cameras[i] and the field; the controller then keeps its cameras as they were). Call it once, and
 * again when a constant changes (a zoom, a new body); steps then pass camera_count poses. The
 * state kept per fragment survives a change of constants; a change of camera count forgets every
 * fragment at the next step. Allocates the strategies of cameras it has not had before (from the
 * def's allocator; FRAGSIM_ERROR_OUT_OF_MEMORY leaves the controller as it was). */
FRAGSIM_API fragsim_status fragsim_controller_set_cameras(fragsim_controller_id controller,
                                                          const fragsim_camera_def* cameras,
                                                          int32_t camera_count);

/* One physics step: writes input->fragment_count forces into forces_N (the caller's array, one
 * per fragment, in the order of input->fragments; zero for most). stats may be NULL.
 *
 * On any status other than FRAGSIM_OK: forces_N, when not NULL, is filled with zeros for the
 * input's fragment count when that count is valid (an invalid count, outside
 * [0, FRAGSIM_MAX_FRAGMENTS], leaves the buffer as it was: its size is unknown), *stats is zeroed,
 * the controller's state is as before the call (also after FRAGSIM_ERROR_OUT_OF_MEMORY: the
 * next call may simply be retried) and fragsim_controller_last_error says why.
 *
 * Fragments come and go by id: a new id is examined at its first step as every fragment is at
 * the explosion (edge: a candidate until its first prediction says otherwise); an id absent from
 * a call is forgotten, and if it returns it is new again. */
FRAGSIM_API fragsim_status fragsim_controller_step(fragsim_controller_id controller,
                                                   const fragsim_step_input* input,
                                                   fragsim_vec3* forces_N,
                                                   fragsim_step_stats* stats);

/* The same with the fragments as strided arrays (input->fragments is ignored, and count is
 * used instead of input->fragment_count); forces go to arrays->force_N, as doubles or (since 0.6)
 * floats (arrays->scalar_type). */
FRAGSIM_API fragsim_status fragsim_controller_step_arrays(fragsim_controller_id controller,
                                                          const fragsim_step_input* input,
                                                          const fragsim_fragment_arrays* arrays,
                                                          int32_t count, fragsim_step_stats* stats);

/* Why the controller's last failed call failed ("" after a successful one). Valid until the next
 * call on this controller; never NULL (for a stale or null id: a static text saying so). */
FRAGSIM_API const char* fragsim_controller_last_error(fragsim_controller_id controller);

#ifdef __cplusplus
}
#endif

#endif /* FRAGSIM_CONTROL_H */
