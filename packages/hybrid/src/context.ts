import type { CallName, CallParams, HALToolResult, HardwareAbstractionLayer } from '@hal/types';

/** What the subsystems of a {@link HybridHAL} share. */
export interface HybridContext {
  physical: HardwareAbstractionLayer;
  twin: HardwareAbstractionLayer;
  /**
   * Guards and validates a call once (readiness, e-stop gating, parameters), then runs it on the
   * physical robot and, when `onTwin` is given, on the twin at the same time. Returns the physical
   * result stamped 'hybrid', with the twin's summary and the divergence in `data`. Never throws.
   */
  run<N extends CallName>(
    call: N,
    args: unknown,
    onPhysical: (params: CallParams<N>) => Promise<HALToolResult>,
    onTwin?: (params: CallParams<N>) => Promise<HALToolResult>,
  ): Promise<HALToolResult>;
  /**
   * A point of the physical robot's frame (where `moveTo` targets are given) in the twin's frame:
   * both are anchored where each robot stood at `initialize()`.
   */
  twinPoint(x: number, y: number): { x: number; y: number };
  /**
   * Guards and validates a value-returning call with the same boundary, then runs it; rejects
   * with a HalError (NOT_READY, INVALID_PARAMETER, or whatever the body rejects with).
   */
  read<N extends CallName, T>(
    call: N,
    args: unknown,
    body: (params: CallParams<N>) => Promise<T>,
  ): Promise<T>;
  /** Guards and validates `log`, then runs it; never throws, a refusal is logged at warn level. */
  notify<N extends CallName>(call: N, args: unknown, body: (params: CallParams<N>) => void): void;
}
