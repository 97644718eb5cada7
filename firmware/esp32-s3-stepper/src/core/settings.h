// The settings set_config takes (docs/protocol.md section 5.10): each field's
// wire name, inclusive range, whether it must be whole, and unit. The host's
// one settings table (ROBOT_SETTINGS in @hal/types) and
// tests/vectors/settings.json hold the same rows; a TypeScript test reads
// this file and the defaults in cube.h and kinematics.h, and vectors_test.cpp
// checks these rows and the robot against settings.json.
#ifndef CUBE_CORE_SETTINGS_H_
#define CUBE_CORE_SETTINGS_H_

namespace cube {

struct Setting {
  const char* wire;
  double min;
  double max;
  bool integer;
  const char* unit;
};

constexpr Setting kWheelDiameterCm{"wheel_diameter_cm", 0.5, 50, false, "cm"};
constexpr Setting kWheelBaseCm{"wheel_base_cm", 1, 100, false, "cm"};
constexpr Setting kStepsPerRevolution{"steps_per_revolution", 100, 100000, true,
                                      "steps"};
constexpr Setting kMaxSpeedStepsPerS{"max_speed_steps_per_s", 1, 2048, true,
                                     "steps/s"};
constexpr Setting kAccelerationStepsPerS2{"acceleration_steps_per_s2", 1,
                                          100000, true, "steps/s^2"};
constexpr Setting kHostTimeoutMs{"host_timeout_ms", 500, 10000, true, "ms"};

// Every row, in the order the config object is written.
constexpr const Setting* kSettings[] = {
    &kWheelDiameterCm,   &kWheelBaseCm,            &kStepsPerRevolution,
    &kMaxSpeedStepsPerS, &kAccelerationStepsPerS2, &kHostTimeoutMs,
};

}  // namespace cube

#endif  // CUBE_CORE_SETTINGS_H_
