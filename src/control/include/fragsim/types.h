/* fragsim control's types are the structs a game fills and reads, each with a function that returns
 * its defaults, and the constants they use. The calls are in fragsim/control.h, which includes this
 * header.
 *
 * Units are SI, named in every field: _m metres, _mps metres per second, _mps2 metres per second
 * squared, _s seconds, _kg kilograms, _N newtons. Angles are in degrees: _deg degrees, _degps
 * degrees per second.
 *
 * Every number is a double (fragsim_vec3 is three doubles), except the strided arrays of
 * fragsim_fragment_arrays, which may be floats (scalar_type says which).
 *
 * Special values, each with one meaning wherever it appears:
 *   FRAGSIM_UNDECLARED (-1)  a camera bound the game does not declare; the def's assumption applies
 *   INFINITY                 no bound at all (camera bounds), no end (end_time_s)
 *   -INFINITY                no ground (ground_height_m)
 *   0                        zero as a number, so a camera whose max_speed_mps is 0 cannot move,
 *                            one whose max_turn_degps is 0 cannot turn, a fragment of mass 0
 *                            cannot be pushed
 *
 * Start every struct from its fragsim_default_* function, never from "= {0}", since a zero normal,
 * end time or field of view is refused, as is a def not from fragsim_default_controller_def. */
#ifndef FRAGSIM_TYPES_H
#define FRAGSIM_TYPES_H

#include <stddef.h>
#include <stdint.h>

/* FRAGSIM_API marks every function of the library. The static library's CMake target
 * (fragsim::control_static) defines FRAGSIM_CONTROL_STATIC; define it yourself when linking the
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

/* The most fragments one call takes, INT32_MAX / 4, so the controller's indices fit 32 bits. */
#define FRAGSIM_MAX_FRAGMENTS 536870911
/* The most controllers alive at once in one process. */
#define FRAGSIM_MAX_CONTROLLERS 65536
/* The most cameras one controller protects at once (split screen, the two eyes of a headset). */
#define FRAGSIM_MAX_CAMERAS 8
/* The most rounds edge-min spends settling one fragment's pushes for several cameras. */
#define FRAGSIM_CAMERA_ROUNDS 4
/* The most worker threads a task system may offer the controller. */
#define FRAGSIM_MAX_WORKERS 64
/* A camera bound the game does not declare (fragsim_camera_def.max_accel_mps2, max_turn_degps). */
#define FRAGSIM_UNDECLARED (-1.0)
/* The range of a fragment's mass besides 0. A force is the mass times an acceleration of at most
 * a_max_mps2 (at most 1e9) for each of up to FRAGSIM_MAX_CAMERAS cameras, and within this range it
 * is finite and not rounded to zero, as a double and as a float. A fragment outside it is skipped
 * (fragsim_step_stats.skipped). */
#define FRAGSIM_MIN_MASS_KG 1e-12
#define FRAGSIM_MAX_MASS_KG 1e24

typedef struct fragsim_vec3 {
  double x, y, z;
} fragsim_vec3;

/* A controller id is a slot and the generation of its use, so an id kept after
 * fragsim_controller_destroy, or never created (all zero), is refused with FRAGSIM_ERROR_STALE_ID
 * and never followed to freed memory. Plain data, free to copy. */
typedef struct fragsim_controller_id {
  /* The slot plus 1; 0 for no controller. */
  uint32_t index1;
  uint32_t generation;
} fragsim_controller_id;

typedef enum fragsim_status {
  FRAGSIM_OK = 0,
  /* A required pointer is NULL. */
  FRAGSIM_ERROR_NULL_ARGUMENT = 1,
  /* The def did not come from fragsim_default_controller_def. */
  FRAGSIM_ERROR_DEF_NOT_DEFAULTED = 2,
  /* A number out of range or not finite, a bad enum value, a count that does not match. */
  FRAGSIM_ERROR_INVALID_ARGUMENT = 3,
  /* Two fragments of one call share an id. */
  FRAGSIM_ERROR_DUPLICATE_ID = 4,
  /* The allocator returned NULL. The controller is unchanged, but for the one case
   * fragsim_controller_step names. */
  FRAGSIM_ERROR_OUT_OF_MEMORY = 5,
  /* A computed force was not finite. This is a library bug; please report it. */
  FRAGSIM_ERROR_INTERNAL = 6,
  /* The controller id was destroyed, or never created. */
  FRAGSIM_ERROR_STALE_ID = 7
} fragsim_status;

/* The force strategy a controller runs. fragsim's README compares them. */
typedef enum fragsim_strategy {
  /* The least constant push that takes a fragment just past the nearest screen edge before it
   * arrives, solved again every step. No gain to tune; the recommended choice. */
  FRAGSIM_STRATEGY_EDGE_MIN = 0,
  /* The 2012 thesis's method (candidates by the camera's reachable ball, force k |V| / (d^2 t)). */
  FRAGSIM_STRATEGY_EDGE = 1,
  /* Every approaching fragment within range pushed away from the view axis. A baseline. */
  FRAGSIM_STRATEGY_DEFLECT_ALL = 2
} fragsim_strategy;

/* What edge-min assumes the camera does before a fragment arrives. */
typedef enum fragsim_camera_model {
  /* The camera keeps its present velocity and orientation. */
  FRAGSIM_CAMERA_CONSTANT = 0,
  /* The camera may accelerate and turn within its bounds. */
  FRAGSIM_CAMERA_BOUNDED_ACCEL = 1,
  /* The camera may be anywhere within max_speed_mps * t of where it is now. */
  FRAGSIM_CAMERA_REACHABLE = 2
} fragsim_camera_model;

/* The path edge predicts a fragment on. */
typedef enum fragsim_edge_predictor {
  /* The parabola from the velocity as read. */
  FRAGSIM_EDGE_PREDICTOR_THESIS = 0,
  /* Semi-implicit Euler's parabola, whose velocity is the one read plus g dt / 2. */
  FRAGSIM_EDGE_PREDICTOR_DISCRETE = 1
} fragsim_edge_predictor;

/* The ball of camera positions edge examines a fragment against. */
typedef enum fragsim_edge_reach {
  /* The fixed ball of radius max_speed_mps * (t_G - t) around the camera. */
  FRAGSIM_EDGE_REACH_THESIS = 0,
  /* The ball of radius max_speed_mps * (t - now), which grows with time, for fewer candidates. */
  FRAGSIM_EDGE_REACH_GROWING = 1
} fragsim_edge_reach;

/* When edge says a fragment has landed. */
typedef enum fragsim_edge_horizon {
  /* When it falls through the camera's height. */
  FRAGSIM_EDGE_HORIZON_CAMERA = 0,
  /* When it falls through the ground's height. */
  FRAGSIM_EDGE_HORIZON_GROUND = 1
} fragsim_edge_horizon;

/* Which fragments edge examines again. */
typedef enum fragsim_edge_replan {
  /* As in the thesis, a fragment is examined only while it is a candidate. */
  FRAGSIM_EDGE_REPLAN_NEVER = 0,
  /* Also after it touched something (fragsim_fragment.touched) or was pushed. */
  FRAGSIM_EDGE_REPLAN_CONTACT = 1,
  /* Every fragment every step, the safest and slowest. */
  FRAGSIM_EDGE_REPLAN_ALWAYS = 2
} fragsim_edge_replan;

typedef struct fragsim_edge_min_def {
  /* Clearance kept beyond the screen edge. Larger is safer against camera moves and pushes more
   * fragments, further. Default 0.05. */
  double margin_m;
  /* The cap on the imposed acceleration, in [0, 1e9]. Higher saves close explosions and makes the
   * swerve visible; lower looks natural and lets close fragments through (stats.capped counts
   * them). Default 50. */
  double a_max_mps2;
  /* What the camera is assumed to do before a fragment arrives (fragsim's
   * docs/camera_models.md). CONSTANT pushes least, and a player who swerves can close on a pushed
   * fragment. BOUNDED_ACCEL promises a miss while the camera keeps within its bounds. Default
   * FRAGSIM_CAMERA_BOUNDED_ACCEL. */
  fragsim_camera_model camera_model;
  /* The camera's acceleration assumed when it declares none (fragsim_camera_def.max_accel_mps2 =
   * FRAGSIM_UNDECLARED), for the robust models. Larger pushes more fragments. Default 20. */
  double camera_accel_mps2;
  /* The turn rate assumed when the camera declares none (fragsim_camera_def.max_turn_degps =
   * FRAGSIM_UNDECLARED), for the robust models: INFINITY or a number in [0, 1e6]. INFINITY assumes
   * no bound, which is safe against any turn (mouse flicks), as each side of the protected region
   * reaches at once as far as any orientation of it can. Larger pushes more fragments. Default
   * INFINITY. */
  double camera_turn_degps;
  /* The per-step budget. At most this many fragments that survive the cheap rejection are solved
   * exactly per call, the soonest to arrive first (distance to the eye over closing speed). The
   * others are deferred and keep the force the last call that solved them gave (none for a fragment
   * never solved); stats.deferred counts them. Smaller bounds the cost of a call and gives late or
   * stale pushes when many fragments threaten at once. 0, the default, means no cap. */
  int32_t max_solves;
  /* The ways out, weighed. Each push goes toward the screen edge of least push divided by its
   * weight, in the order top, bottom, left, right. Each in [0, 1e6]; 0 forbids an edge (not all
   * four). Only pushed fragments change their way out, and a push is the least that clears the
   * camera, so a fragment may still leave by a forbidden edge (fragsim's docs/visibility.md).
   * Default 1 1 1 1. */
  double edge_weights[4];
  /* The occlusion bound. The share of the central region (cover_region of the screen's width and
   * height) that fragments are predicted to cover over the coming second may not exceed cover_max;
   * the fragments that cover most per unit of push are pushed out of it. Each fragment is seen as a
   * disc of its radius_m, so the cover is overestimated. In [0, 1]; 1, the default, turns it off.
   * Smaller gives a clearer view at much more deviation (fragsim's docs/visibility.md). */
  double cover_max;
  /* In (0, 1]. Default 0.5. */
  double cover_region;
} fragsim_edge_min_def;

typedef struct fragsim_edge_def {
  /* The gain of the thesis's force (its equation 3.4). Larger saves close explosions and
   * over-steers distant ones (the thesis's figure 4.6). Default 1. */
  double k_Nms2;
  /* The cap on the imposed acceleration, in [0, 1e9]. Default 50. */
  double a_max_mps2;
  /* Default FRAGSIM_EDGE_PREDICTOR_THESIS. */
  fragsim_edge_predictor predictor;
  /* Default FRAGSIM_EDGE_REACH_THESIS. */
  fragsim_edge_reach reach;
  /* Default FRAGSIM_EDGE_HORIZON_CAMERA. */
  fragsim_edge_horizon horizon;
  /* Default FRAGSIM_EDGE_REPLAN_NEVER. */
  fragsim_edge_replan replan;
} fragsim_edge_def;

typedef struct fragsim_deflect_all_def {
  /* The push away from the view axis, in [0, 1e9]. Larger clears faster and looks more forced.
   * Default 60. */
  double accel_mps2;
  /* Only fragments closer than this to the eye are pushed. Larger moves more fragments.
   * Default 6. */
  double range_m;
} fragsim_deflect_all_def;

/* The game's allocator. Every allocation a controller makes (the controller itself, its tables by
 * id, its work arrays, its strategies' state) is alloc_fn(size, alignment, user), freed by
 * free_fn(pointer, size, alignment, user) with the same size and alignment. alignment is a power of
 * two, at most alignof(max_align_t) in practice. alloc_fn returns NULL when it cannot, and the call
 * then returns FRAGSIM_ERROR_OUT_OF_MEMORY with the controller unchanged. Called only from within
 * the controller's own calls, on the calling thread. */
typedef void* fragsim_alloc_fn(size_t size, size_t alignment, void* user);
typedef void fragsim_free_fn(void* pointer, size_t size, size_t alignment, void* user);

/* A task the controller hands the game's task system. Call it over [start_index, end_index) on a
 * worker, worker_index in [0, worker_count) and different for ranges running at once. */
typedef void fragsim_task_fn(int32_t start_index, int32_t end_index, uint32_t worker_index,
                             void* task_context);

/* The game's task system, as in Box2D. Run task over the items [0, item_count), split into ranges
 * of at least min_range items, on the game's workers. Return a handle that finish_task waits on, or
 * NULL after running every range, which a system with no free worker may do
 * (task(0, item_count, 0, task_context) is a correct answer). */
typedef void* fragsim_enqueue_task_fn(fragsim_task_fn* task, int32_t item_count, int32_t min_range,
                                      void* task_context, void* user_context);
/* Waits until every range of the task that enqueue_task returned is done. */
typedef void fragsim_finish_task_fn(void* user_task, void* user_context);

/* The settings of one controller. Start from fragsim_default_controller_def() and change fields;
 * fragsim_controller_create refuses a def that did not, and names the field and its value when a
 * number is out of range. */
typedef struct fragsim_controller_def {
  /* Default FRAGSIM_STRATEGY_EDGE_MIN. */
  fragsim_strategy strategy;
  fragsim_edge_min_def edge_min;
  fragsim_edge_def edge;
  fragsim_deflect_all_def deflect_all;
  /* The cap of the look-ahead, in (0, 3600]. A fragment's path is examined until it reaches the
   * ground (for edge-min, its centre at ground_height_m plus its radius, going down, as the path
   * means nothing after a bounce) or falls through its horizon height (edge); a path that never
   * comes down (no ground, no gravity) is examined this far ahead and no further, nor past the step
   * input's end_time_s. Longer sees threats earlier and pushes them more gently, examines more
   * paths and makes more pushes that a later camera move makes needless. Default 3 (a fragment
   * thrown at 10 m/s covers 30 m). */
  double horizon_cap_s;
  /* The game's allocator (fragsim_alloc_fn). Both NULL, the default, use the C++ runtime's operator
   * new and delete; one without the other is refused. alloc_user, default NULL, is passed to both
   * unchanged. Two allocations never go through it. The process-wide table of controller ids grows
   * by 256 slots through operator new when the 1st, 257th, ... controller alive at once is created
   * (never freed), and the first fragsim_controller_create of a process builds the tables of the
   * settings' rules once through operator new. */
  fragsim_alloc_fn* alloc_fn;
  fragsim_free_fn* free_fn;
  void* alloc_user;
  /* The game's task system (fragsim_enqueue_task_fn). Both NULL, the default, run every step on the
   * calling thread; one without the other is refused. With one, a step splits its per-fragment work
   * into ranges that enqueue_task runs on the game's workers, and returns when finish_task has
   * waited for all of them. The forces and stats are the same, bit for bit, for any worker count
   * and any split into ranges. user_task_context, default NULL, is passed to both unchanged. */
  fragsim_enqueue_task_fn* enqueue_task;
  fragsim_finish_task_fn* finish_task;
  void* user_task_context;
  /* How many workers the task system runs ranges on at once, so worker_index is below it. In
   * [1, FRAGSIM_MAX_WORKERS]; default 1. The controller keeps one work space per worker. */
  int32_t worker_count;
  /* Set by fragsim_default_controller_def. Do not touch. */
  int32_t internal_value;
} fragsim_controller_def;

/* What a camera keeps from step to step, set with fragsim_controller_set_cameras. */
typedef struct fragsim_camera_def {
  /* The vertical field of view, in (0, 180). A value below 5 is likely radians and sets
   * FRAGSIM_WARNING_FOVY_IN_RADIANS. Default 60. */
  double fovy_deg;
  /* Width over height, in [1e-3, 1e3]. Default 16/9. */
  double aspect;
  /* The near clip distance, > 0. Default 0.1. */
  double near_m;
  /* The far clip distance, > near_m. Default 500. */
  double far_m;
  /* Half the size of the camera's body, a box centred on the eye, along the camera's own right,
   * up and forward axes; each >= 0. Default 0.15 0.1 0.15. */
  fragsim_vec3 body_half_m;
  /* The fastest the player can move the camera, >= 0 (0 if it cannot move). A camera that moves
   * faster breaks the promise the robust camera models keep, and sets
   * FRAGSIM_WARNING_CAMERA_OVER_SPEED. Default 3. */
  double max_speed_mps;
  /* The camera's declared bounds, each FRAGSIM_UNDECLARED where the game declares none (edge-min's
   * robust models then assume edge_min.camera_accel_mps2 and camera_turn_degps), INFINITY where
   * there is none (a velocity that changes at once leaves only the ball max_speed_mps * t; a view
   * that turns at once, every orientation), else the bound, >= 0 (0 if it cannot accelerate or
   * turn). Default FRAGSIM_UNDECLARED for both. */
  double max_accel_mps2;
  double max_turn_degps;
} fragsim_camera_def;

/* Where a camera is and how it moves, passed every step. */
typedef struct fragsim_camera_pose {
  fragsim_vec3 eye_m;
  /* Screen right, screen up and the view direction, in world coordinates, each of length 1 and at
   * right angles to the others, within 1e-6. Default (1, 0, 0), (0, 1, 0), (0, 0, -1). */
  fragsim_vec3 right;
  fragsim_vec3 up;
  fragsim_vec3 forward;
  /* The eye's velocity over the step being taken. Default 0. */
  fragsim_vec3 velocity_mps;
} fragsim_camera_pose;

/* One fragment as the engine sees it after its last step. A fragment that breaks a rule below (a
 * NaN position, or the negative or infinite mass of a static body) is skipped, not refused. It gets
 * a zero force, the others are protected as usual, and stats.skipped and stats.first_skipped say
 * which. */
typedef struct fragsim_fragment {
  /* The centre of mass; finite. */
  fragsim_vec3 position_m;
  /* The linear velocity; finite. */
  fragsim_vec3 velocity_mps;
  /* The bounding sphere's radius; finite, >= 0. */
  double radius_m;
  /* 0, or in [FRAGSIM_MIN_MASS_KG, FRAGSIM_MAX_MASS_KG] as a double (a float mass is converted
   * first, and the float nearest 1e-12 is below the range). The force is the mass times the chosen
   * acceleration, so a fragment of mass 0 cannot be pushed. It is examined, gets no force, and
   * stats.unprotected counts it when it threatens a camera. */
  double mass_kg;
  /* The engine's handle for this fragment, unique within a call (a repeated id refuses the call
   * with FRAGSIM_ERROR_DUPLICATE_ID). The controller keeps state per id between calls; an id it
   * did not see at its last step is a new fragment. */
  uint64_t id;
  /* Nonzero if the fragment had a contact in the last step. Read only by edge with replan =
   * FRAGSIM_EDGE_REPLAN_CONTACT; leave it 0 otherwise. */
  uint8_t touched;
} fragsim_fragment;

/* The type of the numbers in fragsim_fragment_arrays. */
typedef enum fragsim_scalar_type {
  /* double, the default. */
  FRAGSIM_SCALAR_DOUBLE = 0,
  /* float, converted to double exactly; the controller computes as for doubles, and each force is
   * the double force rounded to the nearest float. */
  FRAGSIM_SCALAR_FLOAT = 1
} fragsim_scalar_type;

/* The fragments as strided arrays the engine already has. Element i of an array is at byte offset
 * i * stride from its start, with no alignment needed. position_m, velocity_mps and force_N (the
 * output) hold 3 numbers per fragment, radius_m and mass_kg one, each a double or a float as
 * scalar_type says; id one uint64_t; touched one uint8_t, or NULL for no contacts. The number
 * arrays are void pointers so one field takes a double* or a float* without a cast. A float array
 * passed as doubles is read as garbage (numbers such as 1.6e-314) that nothing can check, so say
 * FRAGSIM_SCALAR_FLOAT. Each stride is at least its element's size (24 bytes for 3 doubles, 12 for
 * 3 floats, 8 for a double or an id, 4 for a float, 1 for touched); with more than one fragment a
 * smaller one, 0 included, is refused. */
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
  /* Default FRAGSIM_SCALAR_DOUBLE; another value is refused. */
  fragsim_scalar_type scalar_type;
} fragsim_fragment_arrays;

/* The world of one step, besides the fragments. Keep one and update what moves each step. */
typedef struct fragsim_step_input {
  /* The caller's clock at the start of this step. Only differences of times are used. Default 0. */
  double time_s;
  /* When the shot ends, if known (a cut-scene). No path is examined past it. It must be after
   * time_s, since a step at or past the end protects nothing and is refused. Default INFINITY. */
  double end_time_s;
  /* The coming physics step, > 0. Default 1/60. */
  double dt_s;
  /* Any direction. Default (0, -9.81, 0). */
  fragsim_vec3 gravity_mps2;
  /* The ground is the plane of the points p with dot(ground_normal, p) = ground_height_m.
   * -INFINITY, the default, is no ground, so every path is examined to the def's horizon_cap_s,
   * which is safe and more work. */
  double ground_height_m;
  /* The ground's unit normal, pointing up. Use (0, 1, 0), the default, for a y-up engine, (0, 0, 1)
   * for a z-up one (Unreal, Blender), any unit vector for a sloped ground. Finite, of length 1
   * within 1e-6. For a normal along a coordinate axis the controller's change of frame rounds
   * nothing; any other costs a rotation's rounding (about 1e-15 relative). The state kept per
   * fragment is in that frame, so a step whose normal differs from the last successful step's
   * forgets every fragment first, as fragsim_controller_reset does. */
  fragsim_vec3 ground_normal;
  /* The poses of the controller's cameras, as many as fragsim_controller_set_cameras set, in the
   * same order; another count is refused. With several cameras every fragment is kept off every
   * camera's near rectangle and body. Edge-min settles a fragment's pushes in rounds, where each
   * camera that still sees a threat on the pushed path adds its least extra push, until every
   * camera is clear or FRAGSIM_CAMERA_ROUNDS rounds are spent (a conflict, stats.conflicts; its
   * force is the last round's, capped at a_max_mps2). edge and deflect-all add each camera's force.
   * Default NULL and 0; set them. */
  const fragsim_camera_pose* camera_poses;
  int32_t camera_count;
} fragsim_step_input;

/* Bits of fragsim_step_stats.warnings, flagging legal input that looks like a mistake. In builds
 * without NDEBUG the library also prints each kind once per controller to stderr. */
/* A camera moves faster than its max_speed_mps. */
#define FRAGSIM_WARNING_CAMERA_OVER_SPEED 1u
/* A camera's fovy_deg is below 5, likely radians. */
#define FRAGSIM_WARNING_FOVY_IN_RADIANS 2u
/* A fragment lies wholly on the far side of the ground plane (stats.below_ground). Most often a
 * z-up engine left ground_normal at its y-up default. */
#define FRAGSIM_WARNING_BELOW_GROUND 4u
/* A fragment threatens a camera and got no force (stats.unprotected). */
#define FRAGSIM_WARNING_UNPROTECTED 8u
/* A fragment was skipped for numbers that break fragsim_fragment's rules (stats.skipped). */
#define FRAGSIM_WARNING_SKIPPED 16u

/* What one step did. */
typedef struct fragsim_step_stats {
  /* Fragments whose path was found to threaten a camera. */
  int32_t candidates;
  /* Fragments given a nonzero force. */
  int32_t pushed;
  /* Forces that a_max cut down, whose fragments may still hit. */
  int32_t capped;
  /* Singular spots guarded (a fragment at the eye, a contact now). */
  int32_t guarded;
  /* Fragments whose id the controller did not see at its last step. */
  int32_t new_ids;
  /* Ids of the last step absent from this one; their state is forgotten. */
  int32_t dropped_ids;
  /* Fragments edge_min.max_solves left unsolved; they kept their last force. */
  int32_t deferred;
  /* Fragments that edge-min's cheap rejection settled as certainly clear before any exact solve;
   * rejected_cheaply / fragment_count is the share of the step that took the fast path. 0 for edge
   * and deflect-all. */
  int32_t rejected_cheaply;
  /* Fragments skipped for numbers that break fragsim_fragment's rules (they got a zero force), and
   * the index of the first of them in the call's order (-1 if none). */
  int32_t skipped;
  int32_t first_skipped;
  /* Fragments that threaten a camera and got no force, as a mass of 0 cannot be pushed. */
  int32_t unprotected;
  /* Fragments wholly on the far side of the ground plane (the centre further beneath it than the
   * radius, deeper than an engine's contacts let a body sink), and the index of the first (-1 if
   * none). The controller examines their paths as for any other; see
   * FRAGSIM_WARNING_BELOW_GROUND. */
  int32_t below_ground;
  int32_t first_below_ground;
  /* With several cameras, the fragments whose pushes did not settle (one camera's way out leads
   * into another's box), and the index of the first (-1 if none). */
  int32_t conflicts;
  int32_t first_conflict;
  /* FRAGSIM_WARNING_* bits. */
  uint32_t warnings;
} fragsim_step_stats;

/* The defaults of every struct a caller fills. */
FRAGSIM_API fragsim_controller_def fragsim_default_controller_def(void);
/* fragsim's default frustum (fovy 60, 16:9, near 0.1 m, far 500 m), a body of 0.3 x 0.2 x 0.3 m,
 * max_speed_mps 3, acceleration and turn FRAGSIM_UNDECLARED. */
FRAGSIM_API fragsim_camera_def fragsim_default_camera_def(void);
/* At the origin, looking down -z, still. */
FRAGSIM_API fragsim_camera_pose fragsim_default_camera_pose(void);
/* At the origin, still, radius 0, mass 0, id 0, not touched. */
FRAGSIM_API fragsim_fragment fragsim_default_fragment(void);
/* Every pointer NULL, doubles, and the strides of packed arrays of doubles (24 bytes for
 * positions, velocities and forces, 8 for radii, masses and ids, 1 for touched). */
FRAGSIM_API fragsim_fragment_arrays fragsim_default_fragment_arrays(void);
/* Time 0, no end (INFINITY), dt 1/60 s, gravity (0, -9.81, 0), no ground (-INFINITY), ground
 * normal (0, 1, 0), no camera poses. */
FRAGSIM_API fragsim_step_input fragsim_default_step_input(void);

#ifdef __cplusplus
}
#endif

#endif /* FRAGSIM_TYPES_H */
