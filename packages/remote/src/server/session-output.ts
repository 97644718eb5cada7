import { HalError } from '@hal/types';
import type { HalErrorCode, HardwareAbstractionLayer } from '@hal/types';
import { MESSAGE_SCHEMAS, encodeMessage } from '../protocol.js';
import type { MessageSchema, Role } from '../protocol.js';
import type { ClientSession } from './client-session.js';

/** What a server sends its clients. */
export interface SessionOutput {
  /** Sends one message to a client whose socket is open (to a closed one, nothing). */
  send<K extends MessageSchema>(
    session: ClientSession,
    schema: K,
    payload: Parameters<typeof encodeMessage<K>>[2],
  ): void;
  /** Answers request `id` with its value, or with `error`; every reply carries the safety status. */
  reply(session: ClientSession, id: string | null, outcome: unknown, error?: HalError): void;
  /** Gives a client a new role and tells it why. */
  setRole(session: ClientSession, role: Role, reason: string): void;
}

/** The messages a server of `hal` sends, as the device `deviceId` (default the HAL's own id). */
export function sessionOutput(
  hal: HardwareAbstractionLayer,
  deviceId: string | undefined,
): SessionOutput {
  const sender = () => ({
    deviceId: deviceId ?? hal.getDeviceInfo().id,
    caps: hal.getDeviceInfo().capabilities,
  });
  const send: SessionOutput['send'] = (session, schema, payload) => {
    if (session.socket.readyState !== session.socket.OPEN) return;
    session.socket.send(encodeMessage(schema, sender(), payload));
  };
  return {
    send,
    reply(session, id, outcome, error) {
      const safety = hal.safety.getSafetyStatus();
      if (error === undefined) {
        send(session, MESSAGE_SCHEMAS.reply, { id, ok: true, value: outcome ?? null, safety });
      } else {
        const shape: { code: string; message: string; details?: Record<string, unknown> } = {
          code: error.code,
          message: error.message,
        };
        if (error.details !== undefined) shape.details = error.details;
        send(session, MESSAGE_SCHEMAS.reply, { id, ok: false, error: shape, safety });
      }
    },
    setRole(session, role, reason) {
      session.role = role;
      send(session, MESSAGE_SCHEMAS.control, { role, reason });
    },
  };
}

/** A HalError with `details` only when there are some. */
export function errorOf(
  code: HalErrorCode,
  message: string,
  details?: Record<string, unknown>,
): HalError {
  return new HalError(code, message, details === undefined ? {} : { details });
}
