import { z } from 'zod';
import { CAPABILITIES } from '../capabilities.js';
import { ESTOP_REASON_MAX_BYTES, sanitizeEstopReason } from '../estop-reason.js';
import { HalError } from '../errors.js';
import { V1_ROBOT } from '../robot-config.js';
import { LedDataSchema, MOTION_DATA_SCHEMA, PoseDataSchema } from './call-data.js';
import { tableOf } from './call-spec.js';
import type {
  CallDeclaration,
  CallMotion,
  CallSpec,
  CallSubsystem,
  CallTable,
} from './call-spec.js';
import { createReadSchemas, READ_RESULT_SCHEMAS } from './reads.js';

export type {
  CallKind,
  CallLane,
  CallMotion,
  CallSpec,
  CallSubsystem,
  CallTable,
  CallToolSpec,
} from './call-spec.js';

const DRIVE = CAPABILITIES.differentialDrive;
const driving = {
  subsystem: 'locomotion',
  kind: 'motion',
  lane: 'queue',
  controllerOnly: true,
  data: MOTION_DATA_SCHEMA,
} as const;
const read = (subsystem: CallSubsystem) =>
  ({ subsystem, kind: 'value', lane: 'direct', controllerOnly: false }) as const;
const command = (subsystem: CallSubsystem) =>
  ({ subsystem, kind: 'result', lane: 'queue', controllerOnly: true }) as const;
// the read calls' parameters depend on no robot limit
const READS = createReadSchemas();

/**
 * Every call of the HAL contract, in the order tools are listed: what it is, its parameters (the
 * `.describe()` texts name units and limits and become the LLM tool descriptions), the `data` it
 * answers with (loose objects: a world may add fields, never rename them) and its tool.
 */
const CALLS = {
  moveForward: {
    ...driving,
    motion: 'forward',
    params: (p) => z.object({ distanceCm: p.distanceCm }).describe('Drive straight ahead'),
    tool: {
      name: 'move_forward',
      requires: DRIVE,
      summary: 'Drive straight ahead (REP-103: +x of the robot) and stop; returns when done.',
    },
  },
  moveBackward: {
    ...driving,
    motion: 'backward',
    params: (p) => z.object({ distanceCm: p.distanceCm }).describe('Drive straight back'),
    tool: {
      name: 'move_backward',
      requires: DRIVE,
      summary: 'Drive straight back (-x of the robot) and stop; returns when done.',
    },
  },
  rotate: {
    ...driving,
    motion: 'turn',
    params: (p) =>
      z
        .object({
          direction: z
            .enum(['left', 'right'])
            .describe('left: counter-clockwise (yaw increases); right: clockwise'),
          degrees: z
            .number()
            .gt(0)
            .max(p.maxDeg)
            .describe(`Angle, degrees, greater than 0 and at most ${p.maxDeg}`),
        })
        .describe('Turn in place'),
    tool: {
      name: 'rotate',
      requires: DRIVE,
      summary:
        'Turn in place; left is counter-clockwise (REP-103 yaw increases). Returns when done.',
    },
  },
  moveTo: {
    ...driving,
    motion: 'point',
    params: ({ extent, minSpeed, maxSpeed }) =>
      z
        .object({
          x: z
            .number()
            .min(-extent)
            .max(extent)
            .describe(`Target x, metres, -${extent}..${extent}`),
          y: z
            .number()
            .min(-extent)
            .max(extent)
            .describe(`Target y, metres, -${extent}..${extent}`),
          z: z.number().describe('Target z, metres (ignored by wheeled robots)'),
          speed: z
            .number()
            .min(minSpeed)
            .max(maxSpeed)
            .optional()
            .describe(
              `Cruise speed, m/s, ${minSpeed}..${maxSpeed} (the robot's slowest and top speeds); default top speed`,
            ),
        })
        .describe('Turn toward a point and drive straight to it (REP-103: x forward, y left)'),
    tool: {
      name: 'move_to',
      requires: DRIVE,
      summary:
        'Drive to a point of the world frame (REP-103: metres, x forward, y left of the start ' +
        'pose): turns toward it in place, then drives straight. Returns on arrival.',
    },
  },
  drive: {
    ...driving,
    motion: 'wheels',
    params: (p) =>
      z
        .object({
          left: p.power('Left'),
          right: p.power('Right'),
          durationMs: z
            .number()
            .gt(0)
            .max(p.maxDriveDurationMs)
            .optional()
            .describe(
              `Stop after this many ms, at most ${p.maxDriveDurationMs}; omit to drive until stop()`,
            ),
        })
        .describe('Drive the wheels at the given powers'),
    data: z.looseObject({
      leftSps: z.number().describe('left wheel speed, steps/s'),
      rightSps: z.number().describe('right wheel speed, steps/s'),
      running: z.boolean().describe('the wheels keep turning after the call answered'),
    }),
    tool: {
      name: 'drive',
      requires: DRIVE,
      summary:
        'Set the wheel powers directly (equal powers: straight; opposite: turn in place). Give ' +
        'durationMs, or the wheels keep turning until stop.',
    },
  },
  stop: {
    subsystem: 'locomotion',
    kind: 'result',
    lane: 'safety',
    controllerOnly: false,
    params: () => z.object({}).describe('Stop all wheel motion now'),
    data: z.looseObject({ stopped: z.boolean(), pose: PoseDataSchema.optional() }),
    tool: { name: 'stop', safety: 'stop', summary: 'Stop the wheels now. Always allowed.' },
  },
  emergencyStop: {
    subsystem: 'safety',
    kind: 'result',
    lane: 'safety',
    controllerOnly: false,
    params: () =>
      z
        .object({
          // never refused for its argument: any value becomes a stored reason (estop-reason.ts)
          reason: z
            .preprocess(sanitizeEstopReason, z.string().max(ESTOP_REASON_MAX_BYTES))
            .describe(
              `Why (optional text; control characters become spaces, cut to ${ESTOP_REASON_MAX_BYTES} UTF-8 bytes)`,
            ),
        })
        .describe('Stop everything and latch until reset; never refused for its argument'),
    data: z.looseObject({ estop: z.literal(true), reason: z.string() }),
    tool: {
      name: 'emergency_stop',
      safety: 'estop',
      summary:
        'Emergency stop: stops everything and latches; motion is refused until ' +
        'reset_emergency_stop. Always allowed, whatever the reason given.',
    },
  },
  resetEmergencyStop: {
    ...command('safety'),
    params: () => z.object({}).describe('Clear a latched emergency stop'),
    data: z.looseObject({
      estop: z.literal(false),
      wasEmergencyStopped: z.boolean().describe('the emergency stop was latched before the reset'),
    }),
    tool: {
      name: 'reset_emergency_stop',
      summary: 'Clear a latched emergency stop so the robot may move again.',
    },
  },
  getPose: {
    ...read('locomotion'),
    params: () => READS.getPose,
    data: READ_RESULT_SCHEMAS.getPose,
    tool: { name: 'get_pose', summary: 'Where the robot is.' },
  },
  captureFrame: {
    ...read('vision'),
    params: () => READS.captureFrame,
    data: READ_RESULT_SCHEMAS.captureFrame,
    tool: {
      name: 'capture_frame',
      requires: CAPABILITIES.camera,
      summary: 'Look through the camera: returns the latest frame as a JPEG image.',
    },
  },
  getDistanceSensors: {
    ...read('vision'),
    params: () => READS.getDistanceSensors,
    data: READ_RESULT_SCHEMAS.getDistanceSensors,
    tool: {
      name: 'get_distance_sensors',
      requires: CAPABILITIES.rangeSensors,
      summary: 'How far the nearest obstacles are.',
    },
  },
  scan: {
    ...read('vision'),
    params: () => READS.scan,
    data: READ_RESULT_SCHEMAS.scan,
    tool: {
      name: 'scan',
      requires: CAPABILITIES.rangeSensors,
      summary: 'Look around for obstacles.',
    },
  },
  getLineSensors: {
    ...read('vision'),
    params: () => READS.getLineSensors,
    data: READ_RESULT_SCHEMAS.getLineSensors,
    tool: {
      name: 'get_line_sensors',
      requires: CAPABILITIES.lineSensors,
      summary: 'Read the floor line sensors.',
    },
  },
  getIMU: {
    ...read('vision'),
    params: () => READS.getIMU,
    data: READ_RESULT_SCHEMAS.getIMU,
    tool: { name: 'get_imu', summary: 'Read the inertial sensors.' },
  },
  getSafetyStatus: {
    ...read('safety'),
    cached: true,
    params: () => READS.getSafetyStatus,
    data: READ_RESULT_SCHEMAS.getSafetyStatus,
    tool: { name: 'get_safety_status', summary: 'Read the safety state.' },
  },
  isEmergencyStopped: {
    ...read('safety'),
    cached: true,
    params: () => READS.isEmergencyStopped,
    data: READ_RESULT_SCHEMAS.isEmergencyStopped,
    tool: {
      name: 'is_emergency_stopped',
      summary: 'Whether the emergency stop is latched.',
      answer: (value) => ({ emergencyStopped: value }),
    },
  },
  setLED: {
    ...command('communication'),
    params: () =>
      z
        .object({
          r: z.number().int().min(0).max(255).describe('Red, 0..255'),
          g: z.number().int().min(0).max(255).describe('Green, 0..255'),
          b: z.number().int().min(0).max(255).describe('Blue, 0..255'),
          pattern: z
            .enum(['solid', 'blink', 'pulse'])
            .optional()
            .describe('Light pattern, default solid'),
        })
        .describe('Set the status LED'),
    data: z.looseObject({ led: LedDataSchema }),
    tool: {
      name: 'set_led',
      requires: CAPABILITIES.led,
      summary: 'Set the status LED colour and pattern.',
    },
  },
  speak: {
    ...command('communication'),
    params: () =>
      z
        .object({
          text: z.string().min(1).max(500).describe('What to say, 1..500 characters'),
          urgency: z.enum(['info', 'warning', 'alert']).optional().describe('How to say it'),
        })
        .describe('Say something through the speaker'),
    data: z.looseObject({ spoken: z.string() }),
    tool: { name: 'speak', requires: CAPABILITIES.speaker, summary: 'Say something aloud.' },
  },
  playSound: {
    ...command('communication'),
    params: () =>
      z
        .object({ soundId: z.string().min(1).max(100).describe('Sound effect id') })
        .describe('Play a sound effect'),
    data: z.looseObject({ soundId: z.string() }),
    tool: { name: 'play_sound', requires: CAPABILITIES.sound, summary: 'Play a sound effect.' },
  },
  log: {
    subsystem: 'communication',
    kind: 'void',
    lane: 'direct',
    controllerOnly: true,
    params: () => READS.log,
    data: z.undefined().describe('log answers nothing'),
    tool: {
      name: 'log',
      summary: 'Write a message to the robot log.',
      answer: () => ({ logged: true }),
    },
  },
} satisfies Readonly<Record<string, CallDeclaration>>;

/** The name of a HAL call. */
export type CallName = keyof typeof CALLS;

/** The parameter schema of every HAL call, by name. */
export type CallSchemas = {
  readonly [N in CallName]: ReturnType<(typeof CALLS)[N]['params']>;
};

/** Every call of the HAL contract, in the order tools are listed (see the declarations above). */
export const HAL_CALL_TABLE: CallTable = tableOf(CALLS, V1_ROBOT);

/** Calls that move the robot: refused while the emergency stop is latched. */
export const MOTION_CALLS: readonly CallName[] = Object.freeze(
  HAL_CALL_TABLE.filter((spec) => spec.kind === 'motion').map((spec) => spec.name as CallName),
);

/** The entry of `name` in `table`, or undefined for a name the table does not have. */
export function findCall(name: string, table: CallTable = HAL_CALL_TABLE): CallSpec | undefined {
  return table.find((spec) => spec.name === name);
}

/**
 * The call of `table` that does `motion` (`backward`: the straight drive back), for code that
 * knows what the robot should do rather than which call does it. Throws INVALID_PARAMETER when
 * the table has none.
 */
export function motionCall(motion: CallMotion, table: CallTable = HAL_CALL_TABLE): CallSpec {
  const spec = table.find((entry) => entry.motion === motion);
  if (spec === undefined) {
    throw new HalError(
      'INVALID_PARAMETER',
      `the call table has no call whose motion is "${motion}"`,
      { details: { motion } },
    );
  }
  return spec;
}
