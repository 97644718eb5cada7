import { HAL_CALL_TABLE, HalError, invokeSpec } from '@hal/types';
import type { CallSpec, CallTable, HardwareAbstractionLayer } from '@hal/types';
import { CommandQueue } from './command-queue.js';

export interface ServedCallsOptions {
  /** The calls served; default the HAL's own call table. */
  calls?: CallTable | undefined;
  /**
   * `ordered`: the queue lane's calls run one at a time, in arrival order (a server whose
   * clients may send a burst of moves); `concurrent`: every call runs the moment it arrives,
   * and the HAL orders them itself.
   */
  order: 'ordered' | 'concurrent';
}

/**
 * How a server of a HAL (WebSocket, NATS) runs the calls its clients send. The safety lane
 * (stop, e-stop), and the safety subsystem's own commands (the e-stop's reset), run at once,
 * ahead of and beside anything queued, and are never refused for want of control; reads run at
 * once beside the queue. Arguments go to the HAL as they came, so its own boundary validates
 * them and names the parameter.
 */
export class ServedCalls {
  readonly #hal: HardwareAbstractionLayer;
  readonly #calls: ReadonlyMap<string, CallSpec>;
  readonly #order: ServedCallsOptions['order'];
  readonly #queue = new CommandQueue();

  constructor(hal: HardwareAbstractionLayer, options: ServedCallsOptions) {
    this.#hal = hal;
    this.#calls = new Map((options.calls ?? HAL_CALL_TABLE).map((spec) => [spec.name, spec]));
    this.#order = options.order;
  }

  /** The served call of that name, or undefined. */
  find(name: string): CallSpec | undefined {
    return this.#calls.get(name);
  }

  /** How many queued calls have not finished. */
  get pending(): number {
    return this.#queue.pending;
  }

  /** Whether `spec` runs at once, ahead of the queue, however it is sent. */
  static isSafety(spec: CallSpec): boolean {
    return spec.lane === 'safety' || (spec.subsystem === 'safety' && spec.kind === 'result');
  }

  /**
   * NOT_CONTROLLER for a controller-only call from a client without control; undefined when the
   * call may go (the safety lane always may).
   */
  refusal(spec: CallSpec, hasControl: boolean, hint?: string): HalError | undefined {
    if (hasControl || !spec.controllerOnly || spec.lane === 'safety') return undefined;
    return new HalError('NOT_CONTROLLER', `"${spec.name}" needs control: this client is watching`, {
      details: { call: spec.name, ...(hint === undefined ? {} : { hint }) },
    });
  }

  /**
   * Runs `spec` on the HAL with `args` in its lane: the safety lane at once, the queue lane in
   * arrival order (when ordered) unless sent with `priority`, reads at once. Resolves with the HAL's answer (nothing for
   * `log`); rejects with what the HAL threw.
   */
  run(
    spec: CallSpec,
    args: readonly unknown[],
    options: { priority?: boolean } = {},
  ): Promise<unknown> {
    const atOnce =
      this.#order === 'concurrent' || ServedCalls.isSafety(spec) || spec.lane !== 'queue';
    if (atOnce) return invokeSpec(this.#hal, spec, args);
    return this.#queue.run(() => invokeSpec(this.#hal, spec, args), options.priority === true);
  }
}
