import { checkSetting, FIRMWARE_SETTINGS } from '@hal/kinematics';
import { sanitizeEstopReason } from '@hal/types';
import type { RobotConfig } from '@hal/types';
import { deviceSettingsOf, MAX_STEPS_PER_COMMAND } from '../protocol/device-config.js';
import { LED_PATTERNS } from '../protocol/schemas.js';
import type { AuthScheme, DeviceConfig, ReplyDataOf } from '../protocol/schemas.js';
import { drive, moveCm, moveSteps, rotateDeg } from './motion-commands.js';
import { integerField, numberField, isAbsent, Refusal } from './refusal.js';
import type { Json } from './refusal.js';
import { moveOutcome, stopReport } from './robot-state.js';
import type { RobotState } from './robot-state.js';

function configJson(state: RobotState): DeviceConfig {
  return { ...deviceSettingsOf(state.model.config), max_steps_per_command: MAX_STEPS_PER_COMMAND };
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
      `locomotion.stepper:v1.0:steps_per_rev=${state.model.config.stepsPerRevolution}`,
      'communication.led:v1.0',
      'safety.estop:v1.0',
      'safety.host_timeout:v1.0',
    ],
    config: configJson(state),
  };
}

function status(state: RobotState): ReplyDataOf<'get_status'> {
  const { model } = state;
  const pose = model.pose;
  const v = model.wheelSpeeds();
  const trip = model.lastTrip;
  return {
    x_cm: pose.xCm,
    y_cm: pose.yCm,
    heading_rad: pose.headingRad,
    left_steps: model.leftSteps,
    right_steps: model.rightSteps,
    running: model.running,
    move_id: model.motion?.moveId ?? 0,
    move_outcome: moveOutcome(model),
    move_left_steps: model.motion?.doneLeft ?? 0,
    move_right_steps: model.motion?.doneRight ?? 0,
    left_sps: v.left,
    right_sps: v.right,
    uptime_ms: state.clock.uptimeMs(),
    safety: {
      estop: model.emergencyStopped,
      estop_reason: model.emergencyStopReason,
      trips: model.trips,
      last_trip:
        trip === undefined
          ? null
          : { reason: trip.reason, detail: trip.detail, uptime_ms: Math.floor(trip.atUs / 1000) },
      host_timeout_ms: model.config.hostTimeoutMs,
      ms_since_host: Math.max(0, Math.floor((model.nowUs - model.lastHostUs) / 1000)),
      coils_on: model.running,
    },
    led: { ...state.led },
  };
}

/** `set_config`: each field read by its wire type, checked against the firmware's range. */
function setConfig(state: RobotState, r: Json): ReplyDataOf<'set_config'> {
  const overrides: Partial<RobotConfig> = {};
  for (const setting of FIRMWARE_SETTINGS) {
    if (isAbsent(r, setting.field)) continue;
    const value = setting.integer ? integerField(r, setting.field) : numberField(r, setting.field);
    checkSetting(setting, value, setting.field);
    overrides[setting.key] = value;
  }
  state.model.setConfig(overrides);
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
 * (or the robot model's HalError) for the error reply.
 */
export function executeCommand(state: RobotState, cmd: string | undefined, r: Json): Json {
  switch (cmd) {
    case 'heartbeat':
      return {
        uptime_ms: state.clock.uptimeMs(),
        running: state.model.running,
        estop: state.model.emergencyStopped,
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
      const stopped = state.model.stop();
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
      state.model.emergencyStop(reason);
      return {
        estop: true,
        estop_reason: state.model.emergencyStopReason,
        estop_us: state.model.emergencyStopUs,
        ...stopReport(state),
      };
    }
    case 'reset_estop': {
      const was = state.model.resetEmergencyStop();
      return { estop: false, was_estopped: was };
    }
    default:
      throw new Refusal('UNKNOWN_COMMAND', `unknown command ${JSON.stringify(cmd)}`);
  }
}
