import { HAL_ERROR_CODES, HalError } from '@hal/types';
import type { HalErrorCode } from '@hal/types';
import type { MessageCodec, WireReply } from './protocol/codec.js';
import type { RequestOptions } from './transport/transport.js';

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

/**
 * Why a `hello` got no usable reply. A keyed robot answers a request whose MAC is not its own with
 * AUTH_FAILED, signed with its key (protocol section 8), so replies that failed our MAC check
 * tell a wrong key (AUTH_FAILED) apart from a robot that is not there (NOT_CONNECTED). Their
 * content is not trusted: only that they came.
 */
export function helloUnanswered(
  cause: unknown,
  options: RequestOptions | undefined,
  before: MessageCodec['macRejections'],
  codec: MessageCodec,
): HalError {
  const after = codec.macRejections;
  const waited =
    options?.timeoutMs === undefined || options.attempts === undefined
      ? ''
      : ` within ${options.timeoutMs * options.attempts} ms (${options.attempts} attempts)`;
  const details = {
    command: 'hello',
    ...(options?.attempts === undefined ? {} : { attempts: options.attempts }),
    ...(options?.timeoutMs === undefined || options.attempts === undefined
      ? {}
      : { waitedMs: options.timeoutMs * options.attempts }),
  };
  if (after.mismatched > before.mismatched) {
    return new HalError(
      'AUTH_FAILED',
      'the robot answered "hello" but its replies do not carry our MAC: the key is wrong (the robot has another one)',
      { cause, details: { ...details, reason: 'wrong-key' } },
    );
  }
  if (after.unsigned > before.unsigned) {
    return new HalError(
      'AUTH_FAILED',
      'the robot answered "hello" without a MAC: it has no key (it runs unauthenticated), so connect without one',
      { cause, details: { ...details, reason: 'robot-has-no-key' } },
    );
  }
  return new HalError('NOT_CONNECTED', `the robot did not answer "hello"${waited}`, {
    cause,
    details,
  });
}
