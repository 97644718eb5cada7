import { HalError } from '@hal/types';
import type { NatsConnection } from '@nats-io/transport-node';
import type { CheckGroup, CheckResult } from './report.js';
import type { SpecCapability } from './spec.js';

/** What runCompliance checks, against which device, and how hard. */
export interface ComplianceOptions {
  /** An open NATS connection (the caller's: not closed by the runner). */
  connection: NatsConnection;
  /** The device to check (`hal.v1.dev.{device}...`); omitted: the spec's default device. */
  device?: string | undefined;
  /**
   * The capabilities to check. Default all the runner knows: those the device announces fully,
   * the others only for answering NOT_IMPLEMENTED (their remaining checks are skipped).
   */
  capabilities?: readonly SpecCapability[] | undefined;
  /**
   * The check groups to run: `format`, `timing`, `errors`, `capability`, `state`. Default all.
   * Leaving out `timing` checks what a device does, not how fast it does it on this network
   * (a runner on a loaded machine or over a slow link measures its own delays too).
   */
  groups?: readonly CheckGroup[] | undefined;
  /** Requests per latency measurement. Default 20. */
  samples?: number;
  /** Which percentile is held to the latency class limits. Default 'p50'. */
  judge?: 'p50' | 'p99';
  /** Longest wait for any one reply, ms. Default 3000. */
  requestTimeoutMs?: number;
  /** How long a stream is watched for its rate, ms. Default 2000. */
  streamWindowMs?: number;
  /** How long to wait for the periodic capability announcement, ms. Default 6000. */
  announceTimeoutMs?: number;
  /** Forward speed of the motion checks, m/s. Default 0.02 (small: safe on a desk). */
  driveSpeedMPerS?: number;
  /** Turn rate of the motion checks, rad/s. Default 0.3. */
  turnRateRadPerS?: number;
  /** Each motion check's `duration_ms` (the robot stops by itself then even if we vanish). Default 3000. */
  motionMs?: number;
  /**
   * Also check that the device is announced by mDNS as the spec's `_tafynode._tcp`, with its
   * device id and the capabilities it answers on NATS. Default false: mDNS reaches one network
   * segment, so ask for it only where the runner shares the device's.
   */
  mdns?: boolean;
  /** How long to browse for the mDNS announcement, ms. Default 3000. */
  mdnsTimeoutMs?: number;
  /** The envelope's `device_id` of what the runner sends. Default `hal-compliance`. */
  clientId?: string;
  /** Aborting stops the run after the running check (the robot is still stopped and reset). */
  signal?: AbortSignal | undefined;
  /** Called when a check starts and when it ends. */
  onProgress?: (event: ProgressEvent) => void;
}

export type ProgressEvent =
  | { type: 'device'; deviceId: string; caps: string[] }
  | { type: 'start'; id: string; title: string }
  | { type: 'result'; result: CheckResult };

export type ResolvedOptions = Required<
  Omit<
    ComplianceOptions,
    'device' | 'capabilities' | 'groups' | 'onProgress' | 'connection' | 'signal'
  >
>;

export function resolveOptions(options: ComplianceOptions): ResolvedOptions {
  const resolved: ResolvedOptions = {
    samples: options.samples ?? 20,
    judge: options.judge ?? 'p50',
    requestTimeoutMs: options.requestTimeoutMs ?? 3000,
    streamWindowMs: options.streamWindowMs ?? 2000,
    announceTimeoutMs: options.announceTimeoutMs ?? 6000,
    driveSpeedMPerS: options.driveSpeedMPerS ?? 0.02,
    turnRateRadPerS: options.turnRateRadPerS ?? 0.3,
    motionMs: options.motionMs ?? 3000,
    clientId: options.clientId ?? 'hal-compliance',
    mdns: options.mdns ?? false,
    mdnsTimeoutMs: options.mdnsTimeoutMs ?? 3000,
  };
  const bounds: [keyof ResolvedOptions, number, number][] = [
    ['samples', 1, 10_000],
    ['requestTimeoutMs', 1, 600_000],
    ['streamWindowMs', 100, 600_000],
    ['announceTimeoutMs', 0, 600_000],
    ['driveSpeedMPerS', 0.001, 10],
    ['turnRateRadPerS', 0.01, 20],
    ['motionMs', 500, 60_000],
    ['mdnsTimeoutMs', 100, 60_000],
  ];
  for (const [name, min, max] of bounds) {
    const value = resolved[name];
    if (typeof value !== 'number' || !Number.isFinite(value)) {
      throw new HalError(
        'INVALID_PARAMETER',
        `"${name}" must be a finite number, got ${String(value)}`,
      );
    }
    if (value < min || value > max) {
      throw new HalError(
        'RANGE_EXCEEDED',
        `"${name}" must be within ${min}..${max}, got ${value}`,
        {
          details: { parameter: name, min, max, value },
        },
      );
    }
  }
  if (!Number.isInteger(resolved.samples)) {
    throw new HalError(
      'INVALID_PARAMETER',
      `"samples" must be an integer, got ${resolved.samples}`,
    );
  }
  if (typeof resolved.mdns !== 'boolean') {
    throw new HalError(
      'INVALID_PARAMETER',
      `"mdns" must be true or false, got ${String(resolved.mdns)}`,
    );
  }
  if (resolved.judge !== 'p50' && resolved.judge !== 'p99') {
    throw new HalError(
      'INVALID_PARAMETER',
      `"judge" must be "p50" or "p99", got "${String(resolved.judge)}"`,
    );
  }
  return resolved;
}
