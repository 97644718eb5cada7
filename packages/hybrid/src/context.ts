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
  /** Throws NOT_READY unless the hybrid HAL is initialised. */
  ensureReady(what: string): void;
}
