import { HAL_ERROR_CODES, HalError } from '@hal/types';
import type { HalErrorCode } from '@hal/types';
import type { WireReply } from './protocol/codec.js';

/* What a session makes of the robot's refusals, and its hello nonces. */

/** A fresh `hello` nonce: 16 hex digits. */
export function randomNonce(): string {
  const bytes = new Uint8Array(8);
  globalThis.crypto.getRandomValues(bytes);
  return Array.from(bytes, (b) => b.toString(16).padStart(2, '0')).join('');
}

/** The HalError for a refused request, carrying the robot's own code. */
export function robotError(cmd: string, reply: WireReply): HalError {
  const error = reply.error;
  const robotCode = error?.code ?? 'UNKNOWN';
  const code: HalErrorCode = (HAL_ERROR_CODES as readonly string[]).includes(robotCode)
    ? (robotCode as HalErrorCode)
    : 'HARDWARE_ERROR';
  return new HalError(code, `the robot refused "${cmd}": ${error?.message ?? 'no reason given'}`, {
    details: { command: cmd, robotCode, robotDetails: error?.details ?? {} },
  });
}
