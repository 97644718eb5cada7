import type { ControllerWatch, ServedCalls } from '@hal/runtime';
import type { HardwareAbstractionLayer, RobotConfig, ScopedLogger } from '@hal/types';
import type { Msg } from '@nats-io/transport-node';
import type { CpuMeter } from './cpu-meter.js';
import type { SubjectName } from './subjects.js';

/** What the gateway's handlers and stream share: the HAL, how it is served, and how to answer. */
export interface GatewayPort {
  readonly hal: HardwareAbstractionLayer;
  /** Runs the HAL's calls, one at a time (priority calls ahead of the queue). */
  readonly served: ServedCalls;
  /** The controller of an open-ended drive, whose silence stops it. */
  readonly controllers: ControllerWatch;
  readonly robot: RobotConfig;
  readonly log: ScopedLogger;
  /** `Date.now()` as the gateway started. */
  readonly started: number;
  readonly cpu: CpuMeter;
  /** Whether the gateway is closed (a stream tick then publishes nothing). */
  readonly closed: boolean;
  /** A message of the spec, from this device, with its capabilities. */
  encode(schema: string, payload: unknown): Uint8Array;
  /** Publishes on the device's subject (and the default one, for the default device). */
  publish(name: SubjectName, schema: string, payload: unknown): void;
  /** Answers `msg` when its sender waits for an answer. */
  reply(msg: Msg, schema: string, payload: unknown): Promise<void>;
}

/** Whether `msg` was sent with the header `Priority: high` (run at once, ahead of the queue). */
export function isPriority(msg: Msg): boolean {
  return msg.headers?.get('Priority').toLowerCase() === 'high';
}

/** Keeps the watchdog on an open-ended drive, and off once any other motion or stop replaces it. */
export function watchMotion(
  controllers: ControllerWatch,
  client: string,
  call: string,
  noDuration: boolean,
): void {
  if (call === 'locomotion.drive' && noDuration) {
    controllers.forget(); // one open-ended drive at a time: the latest
    controllers.watch(client);
  } else if (call.startsWith('locomotion.') && call !== 'locomotion.getPose') {
    controllers.forget();
  } else if (call === 'safety.emergencyStop') controllers.forget();
}
