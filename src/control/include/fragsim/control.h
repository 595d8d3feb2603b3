/* fragsim control keeps explosion debris off a game camera's near plane.
 *
 * Once per physics step, before the engine integrates, the game hands the controller the poses of
 * its cameras and its fragments (position, velocity, size, mass, an id); the controller writes one
 * force per fragment, in newtons, for the engine to apply during that step. Most forces are zero,
 * as only the fragments whose paths would meet a camera are pushed, toward the nearest screen edge,
 * so they leave the picture through its border instead of being cut open by the near plane.
 *
 *   fragsim_controller_def def = fragsim_default_controller_def();
 *   fragsim_controller_id ctl;
 *   fragsim_controller_create(&def, &ctl, message, sizeof message);
 *   fragsim_camera_def camera = fragsim_default_camera_def();    (its frustum, body and bounds)
 *   fragsim_controller_set_cameras(ctl, &camera, 1);
 *   fragsim_camera_pose pose = fragsim_default_camera_pose();
 *   fragsim_step_input in = fragsim_default_step_input();
 *   in.camera_poses = &pose;  in.camera_count = 1;
 *   each physics step: set pose, in.time_s and in.dt_s, then
 *     fragsim_controller_step(ctl, &in, fragments, fragment_count, forces_N, &stats);
 *   and apply the forces (below)
 *   fragsim_controller_destroy(ctl);
 *
 * The structs, their fields, units and defaults are in fragsim/types.h.
 *
 * Applying the forces, in an engine with a fixed physics substep (Bullet, PhysX, Jolt, ODE):
 *   1. Call fragsim_controller_step once per physics substep, before it, with that substep's dt_s
 *      and the state the last substep left (not once per rendered frame).
 *   2. Apply each force for that one substep only, never as a force that persists. In Bullet, an
 *      impulse F dt_s (applyCentralImpulse) from the pre-tick callback.
 *   3. Wake a sleeping body you push (in Bullet, activate(true)).
 *   4. Pass each camera as the physics sees it at the start of the substep, with its pose
 *      interpolated to the substep's time and its velocity over the substep. Declare the camera's
 *      bounds as the game enforces them.
 *   5. fragsim_fragment.touched is read only by edge with replan = CONTACT, so leave it 0, or the
 *      array NULL, and do not walk the engine's contact lists for it.
 *
 * The library creates no threads. One controller must be used by one thread at a time, and
 * different controllers may be used from different threads at once. A controller given a task
 * system (fragsim_controller_def.enqueue_task) runs the ranges of its steps on the game's workers;
 * the call that steps still returns only when they are done. The defaults functions,
 * fragsim_version, fragsim_version_string and fragsim_status_string are safe from any thread.
 *
 * Every function that can fail returns a fragsim_status. No function throws, aborts or writes a
 * non-finite number to the caller. A refused call leaves the controller unchanged and says why in
 * fragsim_controller_last_error, naming the field and the value refused (the step's comment lists
 * the two failures that forget every fragment instead).
 *
 * A 1.x library runs a program built against any earlier 1.y header. A 1.x release may add
 * functions, enum values and warning bits, and fix bugs; it never changes a struct, a function's
 * signature, a default or a rule that a call is refused by. C99; also compiles as C++. */
#ifndef FRAGSIM_CONTROL_H
#define FRAGSIM_CONTROL_H

#include "fragsim/types.h"

#define FRAGSIM_CONTROL_VERSION_MAJOR 1
#define FRAGSIM_CONTROL_VERSION_MINOR 0
#define FRAGSIM_CONTROL_VERSION_PATCH 0
/* major * 10000 + minor * 100 + patch, for #if comparisons. */
#define FRAGSIM_CONTROL_VERSION                                                  \
  (FRAGSIM_CONTROL_VERSION_MAJOR * 10000 + FRAGSIM_CONTROL_VERSION_MINOR * 100 + \
   FRAGSIM_CONTROL_VERSION_PATCH)

#ifdef __cplusplus
extern "C" {
#endif

/* The library's version, the FRAGSIM_CONTROL_VERSION it was built with (compare with the
 * header's), and as text ("1.0.0"). */
FRAGSIM_API int32_t fragsim_version(void);
FRAGSIM_API const char* fragsim_version_string(void);

/* A short English name of a status ("invalid argument"); never NULL. */
FRAGSIM_API const char* fragsim_status_string(fragsim_status status);

/* True for the all-zero id (no controller); says nothing of whether a nonzero id is alive. */
static inline int fragsim_controller_id_is_null(fragsim_controller_id id) {
  return id.index1 == 0;
}

/* Creates a controller. On failure *out_controller is the null id and, when message is not NULL,
 * a NUL-terminated reason naming the field and its value is written there, cut to message_size.
 * The controller has no cameras until fragsim_controller_set_cameras. */
FRAGSIM_API fragsim_status fragsim_controller_create(const fragsim_controller_def* def,
                                                     fragsim_controller_id* out_controller,
                                                     char* message, size_t message_size);

/* Destroys a controller. FRAGSIM_OK for the null id (nothing to do); FRAGSIM_ERROR_STALE_ID for an
 * id already destroyed, so destroying twice is refused, not a crash. */
FRAGSIM_API fragsim_status fragsim_controller_destroy(fragsim_controller_id controller);

/* Nonzero while the id names a live controller. */
FRAGSIM_API int fragsim_controller_is_valid(fragsim_controller_id controller);

/* Forgets every fragment, so the next step treats every id as new. Keeps the room reserved and
 * allocates nothing. */
FRAGSIM_API fragsim_status fragsim_controller_reset(fragsim_controller_id controller);

/* Makes room for fragment_count fragments now, in [0, FRAGSIM_MAX_FRAGMENTS], so the explosion's
 * step (every id new) does not pay for growing the controller's work space. A step with at most
 * that many fragments then allocates nothing. */
FRAGSIM_API fragsim_status fragsim_controller_reserve(fragsim_controller_id controller,
                                                      int32_t fragment_count);

/* Sets the constants of the controller's cameras, camera_count of them in
 * [1, FRAGSIM_MAX_CAMERAS], each checked field by field (a refusal names cameras[i] and the field,
 * and keeps the cameras as they were). Call it once before the first step, and again when a
 * constant changes (a zoom, a new body); each step then passes camera_count poses. The state kept
 * per fragment survives a change of constants; a change of camera count forgets every fragment at
 * the next step. */
FRAGSIM_API fragsim_status fragsim_controller_set_cameras(fragsim_controller_id controller,
                                                          const fragsim_camera_def* cameras,
                                                          int32_t camera_count);

/* One physics step over fragment_count fragments, in [0, FRAGSIM_MAX_FRAGMENTS]. It writes one
 * force per fragment into forces_N, in the order of fragments (zero for most). stats may be NULL.
 *
 * On any status other than FRAGSIM_OK, forces_N (when not NULL and fragment_count is in range) is
 * filled with zeros, *stats is zeroed, fragsim_controller_last_error says why, and the controller's
 * state is unchanged, so the call may be retried. Two failures cannot be undone, and forget every
 * fragment instead, as fragsim_controller_reset does (the message says so):
 * FRAGSIM_ERROR_OUT_OF_MEMORY with the occlusion bound on (edge_min.cover_max < 1), which allocates
 * as it steps, and a task system that ran a range on a worker index not below worker_count or did
 * not run every item (FRAGSIM_ERROR_INVALID_ARGUMENT).
 *
 * Fragments come and go by id. A new id is examined at its first step as every fragment is at the
 * explosion; an id absent from a call is forgotten, and if it returns it is new again. */
FRAGSIM_API fragsim_status fragsim_controller_step(fragsim_controller_id controller,
                                                   const fragsim_step_input* input,
                                                   const fragsim_fragment* fragments,
                                                   int32_t fragment_count, fragsim_vec3* forces_N,
                                                   fragsim_step_stats* stats);

/* The same with the fragments as the engine's strided arrays; the forces go to arrays->force_N, as
 * doubles or floats (arrays->scalar_type). A refused call writes zeros to force_N only where its
 * layout is known (a valid scalar_type and, with more than one fragment, force stride). */
FRAGSIM_API fragsim_status fragsim_controller_step_arrays(fragsim_controller_id controller,
                                                          const fragsim_step_input* input,
                                                          const fragsim_fragment_arrays* arrays,
                                                          int32_t fragment_count,
                                                          fragsim_step_stats* stats);

/* Why the controller's last failed call failed ("" after a successful one). Valid until the next
 * call on this controller; never NULL (for a stale or null id, a static text saying so). */
FRAGSIM_API const char* fragsim_controller_last_error(fragsim_controller_id controller);

#ifdef __cplusplus
}
#endif

#endif /* FRAGSIM_CONTROL_H */
