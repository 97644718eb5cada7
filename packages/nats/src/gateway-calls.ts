import type { HardwareAbstractionLayer } from '@hal/types';
import type { Msg } from '@nats-io/transport-node';
import { decodeArgs, decodeMessage } from './codec.js';
import { errorPayload } from './error-payload.js';
import { isPriority, watchMotion } from './gateway-port.js';
import type { GatewayPort } from './gateway-port.js';
import type { NatsCall } from './hal-calls.js';
import { HalCallSchema, SCHEMAS } from './messages.js';
import type { HalCallReply } from './messages.js';

const DEDUP_ENTRIES = 1024;

/**
 * `hal.call.req`, the whole HAL contract for NatsHAL. A call repeated with the same `request_id`
 * (a client retrying after a reconnect) is answered from the first execution, never run twice;
 * the last {@link DEDUP_ENTRIES} replies are kept.
 */
export class CallReplies {
  readonly #replies = new Map<string, Promise<Uint8Array>>();

  constructor(
    readonly port: GatewayPort,
    readonly calls: Readonly<Record<string, NatsCall>>,
  ) {}

  /** Runs (or finds the run of) the call `msg` carries, and answers it. */
  async onCall(msg: Msg): Promise<void> {
    const envelope = decodeMessage(msg.data, HalCallSchema);
    const call = envelope.payload;
    const id = call.request_id;
    this.port.controllers.heard(envelope.device_id);
    let reply = this.#replies.get(id);
    if (reply === undefined) {
      watchMotion(this.port.controllers, envelope.device_id, call.call, call.args.length < 3);
      reply = this.#execute(call.call, decodeArgs(call.args), isPriority(msg)).then((body) =>
        this.port.encode(SCHEMAS.callReply, { request_id: id, ...body }),
      );
      this.#replies.set(id, reply);
      if (this.#replies.size > DEDUP_ENTRIES) {
        const oldest = this.#replies.keys().next().value;
        if (oldest !== undefined) this.#replies.delete(oldest);
      }
    }
    const data = await reply;
    if (msg.reply !== undefined && msg.reply !== '') msg.respond(data);
  }

  /** Runs one call: its result or value, or its error, with the e-stop latch beside. */
  async #execute(
    name: string,
    args: unknown[],
    priority: boolean,
  ): Promise<Omit<HalCallReply, 'request_id'>> {
    const { hal, served } = this.port;
    const spec = Object.hasOwn(this.calls, name) ? this.calls[name] : undefined;
    if (spec === undefined) {
      return {
        error: { code: 'UNKNOWN_COMMAND', message: `"call" is not a HAL call: "${name}"` },
        ...safetyOf(hal),
      };
    }
    try {
      const out = await served.run(spec.spec, args, { priority });
      return spec.kind === 'result'
        ? { result: out, ...safetyOf(hal) }
        : { value: out, ...safetyOf(hal) };
    } catch (thrown) {
      return { error: errorPayload(thrown), ...safetyOf(hal) };
    }
  }
}

/** The latch, and its reason while latched: every reply carries both, so a client's status has them. */
function safetyOf(
  hal: HardwareAbstractionLayer,
): Pick<HalCallReply, 'emergency_stopped' | 'emergency_stop_reason'> {
  const emergency_stopped = hal.safety.isEmergencyStopped();
  const reason = emergency_stopped ? hal.safety.getSafetyStatus().emergencyStopReason : undefined;
  return reason === undefined
    ? { emergency_stopped }
    : { emergency_stopped, emergency_stop_reason: reason };
}
