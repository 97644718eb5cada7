import type { HardwareAbstractionLayer } from '@hal/types';

/**
 * Every call of the HAL contract that crosses NATS, and how the gateway runs it:
 * - `queue`: one at a time, in order (motions and other commands);
 * - `priority`: at once, ahead of the queue (stop, e-stop, its reset: never queued behind a move);
 * - `direct`: at once, beside the queue (reads, which change nothing).
 * `result` calls answer a HALToolResult; `value` calls a value or a HalError.
 */
export type CallLane = 'queue' | 'priority' | 'direct';
export type CallKind = 'result' | 'value';

export interface CallSpec {
  kind: CallKind;
  lane: CallLane;
  invoke(hal: HardwareAbstractionLayer, args: unknown[]): Promise<unknown>;
}

/* The gateway passes arguments as received; the served HAL's boundary validates them. */
const n = (v: unknown) => v as number;
const s = (v: unknown) => v as string;

export const HAL_CALLS: Readonly<Record<string, CallSpec>> = Object.freeze({
  'locomotion.drive': {
    kind: 'result',
    lane: 'queue',
    invoke: (h, a) => h.locomotion.drive(n(a[0]), n(a[1]), a[2] as number | undefined),
  },
  'locomotion.moveTo': {
    kind: 'result',
    lane: 'queue',
    invoke: (h, a) => h.locomotion.moveTo(n(a[0]), n(a[1]), n(a[2]), a[3] as number | undefined),
  },
  'locomotion.rotate': {
    kind: 'result',
    lane: 'queue',
    invoke: (h, a) => h.locomotion.rotate(a[0] as 'left' | 'right', n(a[1])),
  },
  'locomotion.moveForward': {
    kind: 'result',
    lane: 'queue',
    invoke: (h, a) => h.locomotion.moveForward(n(a[0])),
  },
  'locomotion.moveBackward': {
    kind: 'result',
    lane: 'queue',
    invoke: (h, a) => h.locomotion.moveBackward(n(a[0])),
  },
  'locomotion.stop': { kind: 'result', lane: 'priority', invoke: (h) => h.locomotion.stop() },
  'locomotion.getPose': { kind: 'value', lane: 'direct', invoke: (h) => h.locomotion.getPose() },
  'vision.captureFrame': { kind: 'value', lane: 'direct', invoke: (h) => h.vision.captureFrame() },
  'vision.scan': {
    kind: 'value',
    lane: 'direct',
    invoke: (h, a) => h.vision.scan(a[0] as 'quick' | undefined),
  },
  'vision.getDistanceSensors': {
    kind: 'value',
    lane: 'direct',
    invoke: (h) => h.vision.getDistanceSensors(),
  },
  'vision.getLineSensors': {
    kind: 'value',
    lane: 'direct',
    invoke: (h) => h.vision.getLineSensors(),
  },
  'vision.getIMU': { kind: 'value', lane: 'direct', invoke: (h) => h.vision.getIMU() },
  'communication.speak': {
    kind: 'result',
    lane: 'queue',
    invoke: (h, a) => h.communication.speak(s(a[0]), a[1] as 'info' | undefined),
  },
  'communication.setLED': {
    kind: 'result',
    lane: 'queue',
    invoke: (h, a) =>
      h.communication.setLED(n(a[0]), n(a[1]), n(a[2]), a[3] as 'solid' | undefined),
  },
  'communication.playSound': {
    kind: 'result',
    lane: 'queue',
    invoke: (h, a) => h.communication.playSound(s(a[0])),
  },
  'safety.emergencyStop': {
    kind: 'result',
    lane: 'priority',
    invoke: (h, a) => h.safety.emergencyStop(a[0] as string | undefined),
  },
  'safety.resetEmergencyStop': {
    kind: 'result',
    lane: 'priority',
    invoke: (h) => h.safety.resetEmergencyStop(),
  },
});
