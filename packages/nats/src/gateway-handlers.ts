// The handlers of the spec's subjects a gateway serves besides `hal.call.req`: differential
// drive, e-stop and its reset, health, camera frames and log lines.
import { HalError, findCall, sanitizeEstopReason, toHalError } from '@hal/types';
import type { CallSpec, HALToolResult } from '@hal/types';
import type { Msg } from '@nats-io/transport-node';
import { z } from 'zod';
import { decodeSpecMessage } from './codec.js';
import { cameraFrameOf, healthOf } from './device-reports.js';
import { wheelPowersFor } from './drive-mapping.js';
import { isPriority, watchMotion } from './gateway-port.js';
import type { GatewayPort } from './gateway-port.js';
import {
  CameraFrameRequestSchema,
  DifferentialCommandSchema,
  HealthRequestSchema,
  SCHEMAS,
} from './messages.js';

/** A differential drive command: the wheel powers it maps to, driven (or a stop), acknowledged. */
export async function onDrive(port: GatewayPort, msg: Msg): Promise<void> {
  const envelope = decodeSpecMessage(msg.data, DifferentialCommandSchema);
  const command = envelope.payload;
  port.controllers.heard(envelope.device_id);
  const { left, right } = wheelPowersFor(command, port.robot);
  const stop = left === 0 && right === 0 && command.duration_ms === undefined;
  watchMotion(
    port.controllers,
    envelope.device_id,
    stop ? 'locomotion.stop' : 'locomotion.drive',
    command.duration_ms === undefined,
  );
  const result = (await (stop
    ? port.served.run(callSpec('stop'), [])
    : port.served.run(callSpec('drive'), [left, right, command.duration_ms], {
        priority: isPriority(msg),
      }))) as HALToolResult;
  if (!result.success) {
    throw new HalError(result.code ?? 'HARDWARE_ERROR', result.error ?? 'drive failed', {
      details: result.details ?? {},
    });
  }
  await port.reply(msg, SCHEMAS.ack, { ok: true, left_power: left, right_power: right });
}

/** An e-stop: the robot stops, whatever the message says or fails to say. */
export async function onEstop(port: GatewayPort, msg: Msg): Promise<void> {
  // Never refused: any reason becomes a stored text (sanitizeEstopReason), and a message that
  // cannot be read at all (not JSON, another major version) still stops the robot, with a
  // reason that says so: whoever publishes on this subject wants the robot stopped.
  let reason: string | undefined;
  try {
    const body = decodeSpecMessage(msg.data, z.looseObject({ reason: z.unknown() })).payload;
    reason = body.reason === undefined ? undefined : sanitizeEstopReason(body.reason);
  } catch (error) {
    const unread = toHalError(error);
    reason = sanitizeEstopReason(`unreadable e-stop message (${unread.code})`);
    port.log.warn('an unreadable e-stop message: stopping all the same', {
      code: unread.code,
      error: unread.message,
    });
  }
  const result = await port.hal.safety.emergencyStop(reason);
  await port.reply(msg, SCHEMAS.ack, { ok: result.success, emergency_stopped: true });
}

/** An e-stop reset: the latch cleared, or the HAL's refusal as the error. */
export async function onEstopReset(port: GatewayPort, msg: Msg): Promise<void> {
  decodeSpecMessage(msg.data, z.looseObject({}));
  const result = await port.hal.safety.resetEmergencyStop();
  if (!result.success) throw new HalError(result.code ?? 'HARDWARE_ERROR', result.error ?? '');
  await port.reply(msg, SCHEMAS.ack, { ok: true, emergency_stopped: false });
}

/** A health request: uptime, CPU, and the diagnostics when asked for. */
export async function onHealth(port: GatewayPort, msg: Msg): Promise<void> {
  const request = decodeSpecMessage(msg.data, HealthRequestSchema).payload;
  const health = healthOf(port.hal, {
    uptimeS: (Date.now() - port.started) / 1000,
    cpuPercent: port.cpu.percent(),
    includeDiagnostics: request.include_diagnostics === true,
  });
  await port.reply(msg, SCHEMAS.health, health);
}

/** A camera frame request: the frame the HAL captures. */
export async function onCamera(port: GatewayPort, msg: Msg): Promise<void> {
  decodeSpecMessage(msg.data, CameraFrameRequestSchema);
  await port.reply(msg, SCHEMAS.cameraFrame, await cameraFrameOf(port.hal));
}

/** A log line, handed to the HAL's own log. */
export async function onLog(port: GatewayPort, msg: Msg): Promise<void> {
  const body = decodeSpecMessage(
    msg.data,
    z.looseObject({ message: z.unknown(), level: z.unknown().optional() }),
  ).payload;
  port.hal.communication.log(body.message as string, body.level as 'info' | undefined);
}

/** A call of the HAL's own table (the spec's drive subject maps onto drive and stop). */
function callSpec(name: 'drive' | 'stop'): CallSpec {
  const spec = findCall(name);
  if (spec === undefined) throw new HalError('HARDWARE_ERROR', `the call table has no "${name}"`);
  return spec;
}
