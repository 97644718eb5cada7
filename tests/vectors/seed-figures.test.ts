import { existsSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { rotationToSteps } from '@hal/kinematics';
import { DEFAULT_UDP_PORT } from '@hal/physical';
import { crc16 } from '@hal/physical/protocol';
import { HAL_ERROR_CODES, ROBOT_SETTINGS, V1_ROBOT } from '@hal/types';

// The robot specification's figures. The repository keeps a copy, tests/vectors/seed-figures.json,
// which this test always holds the implementation to (as the kinematics tests do for the motion
// figures), so a clone of the repository alone checks them. Where the project is developed and
// tested, the specification's own file lies beside the repository in ../shared/vectors (CI lays
// it there); when it is present the copy must also be byte for byte that file. Which of the two
// ran is in the suite's name: nothing is left out without saying so.

const copyUrl = new URL('./seed-figures.json', import.meta.url);
const sharedUrl = new URL('../../../shared/vectors/seed-figures.json', import.meta.url);
const sharedPresent = existsSync(sharedUrl);
const copyText = readFileSync(copyUrl, 'utf8');

interface SeedFigures {
  robot_v1: {
    steps_per_revolution: number;
    wheel_diameter_cm: number;
    wheel_base_cm: number;
    steps_per_cm_approx: number;
    max_speed_steps_per_s: number;
    acceleration_steps_per_s2: number;
  };
  rotation: { degrees: number; steps_per_wheel: number }[];
  firmware_safety_defaults: {
    max_steps_per_s: { default: number; min: number; max: number };
    max_steps_per_command: number;
    host_heartbeat_timeout_ms: { range_min: number; range_max: number };
  };
  transports: { udp_command_port: number };
  crc16_ccitt_false: { vectors: { ascii: string; crc: string }[] };
  tafy_error_codes: string[];
}
const figures = JSON.parse(copyText) as SeedFigures;

const setting = (key: string) => {
  const row = ROBOT_SETTINGS.find((r) => r.key === key);
  if (row === undefined) throw new Error(`ROBOT_SETTINGS has no ${key}`);
  return row;
};

describe(
  sharedPresent
    ? 'seed figures: the copy in tests/vectors, checked against ../shared/vectors/seed-figures.json and the implementation'
    : 'seed figures: the copy in tests/vectors, checked against the implementation (../shared/vectors/seed-figures.json is absent here)',
  () => {
    it(
      sharedPresent
        ? 'the copy is byte for byte ../shared/vectors/seed-figures.json'
        : 'the copy is the one checked: ../shared/vectors/seed-figures.json is absent, so there is nothing else to compare it with',
      () => {
        if (sharedPresent) expect(copyText).toBe(readFileSync(sharedUrl, 'utf8'));
        else expect(existsSync(fileURLToPath(sharedUrl))).toBe(false);
        expect(figures.robot_v1.steps_per_revolution).toBeGreaterThan(0);
      },
    );

    it("the V1 robot's geometry and motion limits are the figures", () => {
      const v1 = figures.robot_v1;
      expect(V1_ROBOT.stepsPerRevolution).toBe(v1.steps_per_revolution);
      expect(V1_ROBOT.wheelDiameterCm).toBe(v1.wheel_diameter_cm);
      expect(V1_ROBOT.wheelBaseCm).toBe(v1.wheel_base_cm);
      expect(V1_ROBOT.maxSpeedStepsPerS).toBe(v1.max_speed_steps_per_s);
      expect(V1_ROBOT.accelerationStepsPerS2).toBe(v1.acceleration_steps_per_s2);
      const stepsPerCm = v1.steps_per_revolution / (Math.PI * v1.wheel_diameter_cm);
      expect(stepsPerCm).toBeCloseTo(v1.steps_per_cm_approx, 1);
    });

    it('an in-place turn takes the steps per wheel the figures give', () => {
      expect(figures.rotation.length).toBeGreaterThan(0);
      for (const turn of figures.rotation) {
        expect(rotationToSteps(turn.degrees), `${turn.degrees}°`).toEqual({
          left: -turn.steps_per_wheel,
          right: turn.steps_per_wheel,
        });
      }
    });

    it("the firmware's safety ranges in the settings table are the figures", () => {
      const safety = figures.firmware_safety_defaults;
      const speed = setting('maxSpeedStepsPerS');
      expect([speed.default, speed.min, speed.max]).toEqual([
        safety.max_steps_per_s.default,
        safety.max_steps_per_s.min,
        safety.max_steps_per_s.max,
      ]);
      expect(setting('maxStepsPerCommand').default).toBe(safety.max_steps_per_command);
      const timeout = setting('hostTimeoutMs');
      expect([timeout.min, timeout.max]).toEqual([
        safety.host_heartbeat_timeout_ms.range_min,
        safety.host_heartbeat_timeout_ms.range_max,
      ]);
    });

    it('the UDP port, the CRC-16 check values and the error codes are the figures', () => {
      expect(DEFAULT_UDP_PORT).toBe(figures.transports.udp_command_port);
      expect(figures.crc16_ccitt_false.vectors.length).toBeGreaterThan(0);
      for (const vector of figures.crc16_ccitt_false.vectors) {
        expect(crc16(new TextEncoder().encode(vector.ascii)), `"${vector.ascii}"`).toBe(
          Number(vector.crc),
        );
      }
      expect(HAL_ERROR_CODES).toEqual(expect.arrayContaining(figures.tafy_error_codes));
    });
  },
);
