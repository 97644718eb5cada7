import {
  AckSchema,
  CameraFrameSchema,
  CapabilityAnnouncementSchema,
  DifferentialStateSchema,
  HealthSchema,
  ImuDataSchema,
  RangeDataSchema,
} from '@hal/nats';
import type {
  CapabilityAnnouncement,
  DifferentialState,
  Health,
  ImuData,
  RangeData,
} from '@hal/nats';
import type { z } from 'zod';
import { inspect } from './inspect.js';
import type { Inspected } from './inspect.js';
import type { ResolvedOptions } from './options.js';
import { CHECK_GROUPS } from './report.js';
import type { CheckGroup } from './report.js';
import { StreamCollector } from './streams.js';
import type { DeviceWire, Outcome } from './wire.js';

/** The kinds of message the format checks look at, each with its payload schema. */
export const KINDS = {
  ack: AckSchema,
  health: HealthSchema,
  capabilities: CapabilityAnnouncementSchema,
  state: DifferentialStateSchema,
  imu: ImuDataSchema,
  range: RangeDataSchema,
  frame: CameraFrameSchema,
} as const;
export type MessageKind = keyof typeof KINDS;

/** A reply the runner received, and what kind it should have been. */
export interface SeenReply {
  kind: MessageKind;
  subject: string;
  inspected: Inspected<unknown>;
}

/** An answer to a request: the outcome, and the reply checked when there was one. */
export interface Answer<T> {
  outcome: Outcome;
  inspected: Inspected<T> | undefined;
}

/** Below this (m/s, rad/s) a state shows the robot at rest. */
const REST_EPS = 1e-3;

/** Everything a check needs: the wire, the device, its streams, and what has been seen. */
export class RunContext {
  readonly replies: SeenReply[] = [];
  readonly state: StreamCollector<DifferentialState>;
  readonly imu: StreamCollector<ImuData>;
  readonly range: StreamCollector<RangeData>;
  readonly announcements: StreamCollector<CapabilityAnnouncement>;
  /** Set while an e-stop the runner sent is latched: it must reset it before it leaves. */
  estopHeld = false;

  constructor(
    readonly wire: DeviceWire,
    readonly deviceId: string,
    readonly announcement: CapabilityAnnouncement,
    readonly options: ResolvedOptions,
    /** The check groups this run runs. */
    readonly groups: readonly CheckGroup[] = CHECK_GROUPS,
  ) {
    this.state = new StreamCollector(
      wire,
      wire.subject('differentialState'),
      DifferentialStateSchema,
      deviceId,
    );
    this.imu = new StreamCollector(wire, wire.subject('imuData'), ImuDataSchema, deviceId);
    this.range = new StreamCollector(wire, wire.subject('rangeData'), RangeDataSchema, deviceId);
    this.announcements = new StreamCollector(
      wire,
      wire.subject('capabilityAnnounce'),
      CapabilityAnnouncementSchema,
      deviceId,
    );
  }

  get caps(): string[] {
    return this.announcement.caps;
  }

  /** Sends `data` as a request and checks the reply as `kind` (or the spec's error shape). */
  async ask<K extends MessageKind>(
    subject: string,
    data: Uint8Array,
    kind: K,
    options: { timeoutMs?: number; priority?: 'high' } = {},
  ): Promise<Answer<z.output<(typeof KINDS)[K]>>> {
    const outcome = await this.wire.request(subject, data, {
      timeoutMs: options.timeoutMs ?? this.options.requestTimeoutMs,
      ...(options.priority === undefined ? {} : { priority: options.priority }),
    });
    if (outcome.kind !== 'reply') return { outcome, inspected: undefined };
    const inspected = inspect(outcome.data, KINDS[kind], this.deviceId);
    this.replies.push({ kind, subject, inspected });
    return { outcome, inspected: inspected as Inspected<z.output<(typeof KINDS)[K]>> };
  }

  /** A drive command (an envelope around the spec's payload). */
  drive(payload: Record<string, unknown>): Uint8Array {
    return this.wire.envelope('hal/motor/differential/cmd/1.0', payload);
  }

  /** Asks for health; undefined when no valid health reply came. */
  async health(): Promise<Health | undefined> {
    const answer = await this.ask(
      this.wire.subject('health'),
      this.wire.envelope('hal/system/health/req/1.0', {}),
      'health',
    );
    return answer.inspected?.payload;
  }

  /** Stops the robot: an all-zero drive command, sent with priority. */
  async stop(): Promise<Answer<unknown>> {
    return this.ask(
      this.wire.subject('differentialCmd'),
      this.drive({ linear_vel_m_per_s: 0, angular_vel_rad_per_s: 0 }),
      'ack',
      { priority: 'high' },
    );
  }

  /**
   * Stops the robot and waits (up to `timeoutMs`) for the state stream to show it at rest, so
   * that what one check set moving cannot be taken for a change made by the next. False when no
   * state at rest arrived in time.
   */
  async bringToRest(timeoutMs = 1000): Promise<boolean> {
    const atRest = this.state.next(
      timeoutMs,
      (s) =>
        Math.abs(s.linear_vel_m_per_s) <= REST_EPS && Math.abs(s.angular_vel_rad_per_s) <= REST_EPS,
    );
    await this.stop();
    return (await atRest) !== undefined;
  }

  /** A state read fresh from the stream (arriving from now on), or undefined. */
  freshState(timeoutMs = 1000): Promise<DifferentialState | undefined> {
    return this.state.next(timeoutMs);
  }
}

/** Says what an answer was, for a failure reason. */
export function describeAnswer(answer: Answer<unknown>): string {
  if (answer.outcome.kind === 'no-responders') return 'no responder on the subject';
  if (answer.outcome.kind === 'timeout')
    return `no reply within ${answer.outcome.latencyMs.toFixed(0)} ms`;
  const inspected = answer.inspected;
  if (inspected === undefined) return 'no reply';
  if (inspected.error !== undefined)
    return `error ${inspected.error.code}: ${inspected.error.message}`;
  if (inspected.issues.length > 0) return `a malformed reply (${inspected.issues.join('; ')})`;
  return `a success reply ${JSON.stringify(inspected.envelope?.payload)}`;
}
