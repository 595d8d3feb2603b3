#pragma once
// The checks of what a caller hands the C API (a def when a controller is created, a step's input
// at every step, and one fragment's numbers), each failure naming the field, its value and the
// rule. A fragment that breaks them is skipped, not refused, as engines hand over what they have.

#include <cstddef>
#include <cstdint>

#include "fragsim/control.h"

namespace fragsim::control {

// A failed check's status and message, in a fixed buffer (a check allocates nothing, so a
// controller with an allocator hook never reaches operator new).
struct Failure {
  static constexpr std::size_t kMessageSize = 320;
  fragsim_status status = FRAGSIM_OK;
  char message[kMessageSize] = {};
  explicit operator bool() const { return status != FRAGSIM_OK; }
};

[[gnu::format(printf, 2, 3)]] Failure fail(fragsim_status status, const char* format, ...);

Failure validate_def(const fragsim_controller_def& def);
// The step's input: its numbers, its camera count (in range; the controller checks it against the
// cameras it has) and each pose.
Failure validate_step_input(const fragsim_step_input& in);
// One camera's constants and one pose, each failure naming prefix.field ("cameras[1].near_m").
Failure validate_camera_def(const fragsim_camera_def& camera, const char* prefix);
Failure validate_camera_pose(const fragsim_camera_pose& pose, const char* prefix);
// The strided arrays' scalar_type, and their strides when count > 1 (each at least its element's
// size). The pointers are the caller's to check.
Failure validate_arrays(const fragsim_fragment_arrays& arrays, std::size_t count);
// Whether the force buffer's layout is known (scalar_type, and the force stride when count > 1,
// valid), so a refused call may write count zeros to it.
bool force_layout_known(const fragsim_fragment_arrays& arrays, std::size_t count);

// Whether a mass is 0 or in [FRAGSIM_MIN_MASS_KG, FRAGSIM_MAX_MASS_KG] (fragsim_fragment's rule),
// where a force (mass times a capped acceleration) is finite and not rounded to zero in a double or
// a float.
bool mass_usable(double mass_kg);
// Whether one fragment's numbers keep fragsim_fragment's rules: a finite position and velocity,
// a finite radius >= 0 and a usable mass.
bool fragment_usable(const double* position_m, const double* velocity_mps, double radius_m,
                     double mass_kg);

// The FRAGSIM_WARNING_* bits a posed camera earns for legal input that looks like a mistake.
std::uint32_t camera_warnings(const fragsim_camera_def& camera, const fragsim_camera_pose& pose);

}  // namespace fragsim::control
