import { sanitizeEstopReason } from '@hal/types';
import {
  DEVICE_SETTING_RANGES,
  deviceGeometry,
  MAX_STEPS_PER_COMMAND,
} from '../protocol/device-config.js';
import type { DeviceSettings } from '../protocol/device-config.js';
import { LED_PATTERNS } from '../protocol/schemas.js';
import type { AuthScheme, DeviceConfig, ReplyDataOf } from '../protocol/schemas.js';
import { drive, moveCm, moveSteps, rotateDeg } from './motion-commands.js';
import { integerField, isAbsent, numberField, Refusal } from './refusal.js';
import type { Json } from './refusal.js';
import { emergencyStop, stopReport } from './robot-state.js';
import type { RobotState } from './robot-state.js';

function configJson(state: RobotState): DeviceConfig {
  return { ...state.settings, max_steps_per_command: MAX_STEPS_PER_COMMAND };
}

/** The reply data of `hello`, beside the session fields. */
export function helloData(
  state: RobotState,
  deviceId: string,
  auth: AuthScheme,
): Omit<ReplyDataOf<'hello'>, 'sid' | 'nonce'> {
  return {
    device_id: deviceId,
    firmware_version: '1.1.0-mock',
    protocol_version: '1.1',
    auth,
    capabilities: [
      'locomotion.differential:v1.0',
      `locomotion.stepper:v1.0:steps_per_rev=${state.settings.steps_per_revolution}`,
      'communication.led:v1.0',
      'safety.estop:v1.0',
      'safety.host_timeout:v1.0',
    ],
    config: configJson(state),
  };
}

function status(state: RobotState): ReplyDataOf<'get_status'> {
  const { motion } = state;
  const pose = motion.pose;
  const v = motion.velocity();
  return {
    x_cm: pose.xCm,
    y_cm: pose.yCm,
    heading_rad: pose.headingRad,
    left_steps: motion.position.left,
    right_steps: motion.position.right,
    running: motion.running,
    move_id: motion.moveId,
    move_outcome: motion.outcome,
    move_left_steps: motion.moveSteps.left,
    move_right_steps: motion.moveSteps.right,
    left_sps: v.left,
    right_sps: v.right,
    uptime_ms: state.clock.uptimeMs(),
    safety: {
      ...state.safety.report(),
      host_timeout_ms: state.settings.host_timeout_ms,
      ms_since_host: motion.msSinceHost(),
      coils_on: motion.running,
    },
    led: { ...state.led },
  };
}

function setConfig(state: RobotState, r: Json): ReplyDataOf<'set_config'> {
  const next = { ...state.settings };
  for (const [field, { min, max, integer }] of Object.entries(DEVICE_SETTING_RANGES) as Array<
    [keyof DeviceSettings, (typeof DEVICE_SETTING_RANGES)[keyof DeviceSettings]]
  >) {
    if (isAbsent(r, field)) continue;
    const value = integer ? integerField(r, field) : numberField(r, field);
    if (value < min || value > max)
      throw new Refusal('RANGE_EXCEEDED', `"${field}" must be ${min}..${max}`, {
        field,
        min,
        max,
        value,
      });
    next[field] = value;
  }
  state.settings = next;
  state.motion.setGeometry(deviceGeometry(next));
  return { config: configJson(state) };
}

function setLed(state: RobotState, r: Json): ReplyDataOf<'set_led'> {
  const pattern = typeof r['pattern'] === 'string' ? r['pattern'] : 'solid';
  if (!(LED_PATTERNS as readonly string[]).includes(pattern)) {
    throw new Refusal('INVALID_PARAMETER', `"pattern" must be one of ${LED_PATTERNS.join(', ')}`, {
      field: 'pattern',
    });
  }
  state.led =
    pattern === 'off'
      ? { r: 0, g: 0, b: 0, pattern }
      : {
          r: integerField(r, 'r'),
          g: integerField(r, 'g'),
          b: integerField(r, 'b'),
          pattern,
        };
  return { led: { ...state.led } };
}

/**
 * Executes one command (any but `hello`) and returns its reply data; throws a {@link Refusal}
 * for the error reply.
 */
export function executeCommand(state: RobotState, cmd: string | undefined, r: Json): Json {
  switch (cmd) {
    case 'heartbeat':
      return {
        uptime_ms: state.clock.uptimeMs(),
        running: state.motion.running,
        estop: state.safety.estopped,
      };
    case 'move_steps':
      return moveSteps(state, r);
    case 'move_cm':
      return moveCm(state, r);
    case 'rotate_deg':
      return rotateDeg(state, r);
    case 'drive':
      return drive(state, r);
    case 'stop': {
      const stopped = state.motion.stop('stopped');
      return { stopped, ...stopReport(state) };
    }
    case 'get_status':
      return status(state);
    case 'set_config':
      return setConfig(state, r);
    case 'set_led':
      return setLed(state, r);
    case 'estop': {
      // never refused: the same rule as every HAL's (and the firmware's) for the reason
      const reason = sanitizeEstopReason(r['reason']);
      emergencyStop(state, reason, { reason: 'estop_command', detail: reason });
      return {
        estop: true,
        estop_reason: state.safety.reason,
        estop_us: state.safety.latchedUs,
        ...stopReport(state),
      };
    }
    case 'reset_estop': {
      const was = state.safety.reset();
      return { estop: false, was_estopped: was };
    }
    default:
      throw new Refusal('UNKNOWN_COMMAND', `unknown command ${JSON.stringify(cmd)}`);
  }
}
