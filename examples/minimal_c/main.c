/* The smallest use of fragsim_control: a still camera, four fragments flying at it, one step.
 * Prints the force on each fragment; the two aimed at the lens get a push toward a screen edge,
 * the two that would miss get none. */
#include <fragsim/control.h>
#include <math.h>
#include <stdio.h>

int main(void) {
  fragsim_controller_def def = fragsim_default_controller_def(); /* edge-min, 3 s look-ahead */
  fragsim_controller_id ctl;
  char message[256];
  fragsim_fragment fragments[4];
  fragsim_vec3 forces[4];
  /* Start every struct from its defaults function, never from "= {0}". The camera: fragsim's
   * default frustum and body; its pose at the origin, looking down -z, still. */
  fragsim_camera_def camera = fragsim_default_camera_def();
  fragsim_camera_pose pose = fragsim_default_camera_pose();
  /* No end, dt 1/60 s, gravity -9.81 m/s^2 in y. */
  fragsim_step_input in = fragsim_default_step_input();
  fragsim_step_stats stats;
  fragsim_status status;
  int i;

  if (fragsim_controller_create(&def, &ctl, message, sizeof message) != FRAGSIM_OK) {
    fprintf(stderr, "create: %s\n", message);
    return 1;
  }
  /* The camera's constants, once: a controller has no camera until they are set. */
  if (fragsim_controller_set_cameras(ctl, &camera, 1) != FRAGSIM_OK) {
    fprintf(stderr, "set_cameras: %s\n", fragsim_controller_last_error(ctl));
    fragsim_controller_destroy(ctl);
    return 1;
  }
  for (i = 0; i < 4; ++i) {
    fragments[i] = fragsim_default_fragment();
    /* 6 m in front of the eye (the camera looks down -z), coming at 12 m/s; the first two
     * straight at the lens, the others 1.5 m to the side. */
    fragments[i].position_m.x = i < 2 ? 0.02 * i : 1.5;
    fragments[i].position_m.y = 1.6 + (i == 1 ? -0.03 : 0.0);
    fragments[i].position_m.z = -6.0 - 0.5 * i;
    fragments[i].velocity_mps.y = 2.45; /* up, and back down to the lens as they arrive */
    fragments[i].velocity_mps.z = 12.0;
    fragments[i].radius_m = 0.05;
    fragments[i].mass_kg = 0.5;
    fragments[i].id = 100 + (uint64_t)i;
  }
  in.ground_height_m = 0.0;
  pose.eye_m.y = 1.6;
  in.camera_poses = &pose;
  in.camera_count = 1;

  status = fragsim_controller_step(ctl, &in, fragments, 4, forces, &stats);
  if (status != FRAGSIM_OK) {
    fprintf(stderr, "step: %s: %s\n", fragsim_status_string(status),
            fragsim_controller_last_error(ctl));
    fragsim_controller_destroy(ctl);
    return 1;
  }
  printf("fragsim_control %s: %d candidates, %d pushed\n", fragsim_version_string(),
         (int)stats.candidates, (int)stats.pushed);
  for (i = 0; i < 4; ++i) {
    printf("fragment %llu: force %.6f %.6f %.6f N\n", (unsigned long long)fragments[i].id,
           forces[i].x, forces[i].y, forces[i].z);
  }
  fragsim_controller_destroy(ctl);
  return stats.pushed == 2 ? 0 : 1;
}
