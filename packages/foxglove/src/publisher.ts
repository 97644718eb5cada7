// What the live view publishes, each topic at its rate and only while a viewer subscribes to it:
// the pose (PoseInFrame, /tf, the HAL's own Pose) and the e-stop latch at the pose rate, camera
// frames at the camera rate, a physical robot's wheel steps and link statistics at the link
// rate; log lines and safety events as they happen. A read still on its way when the next tick
// comes skips that tick, so a slow robot makes fewer messages, never a backlog.
import type { FoxgloveServer } from '@foxglove/ws-protocol';
import { linkTelemetry, quaternionFromEuler } from '@hal/recorder';
import type { LinkTelemetry, NamedJsonSchema, RobotNamespace, SafetyEvent } from '@hal/recorder';
import type { HALToolResult, HardwareAbstractionLayer, Pose } from '@hal/types';
import { LIVE_SCHEMAS, foxgloveTimeOfMs } from './topics.js';
import type { LiveTopic } from './topics.js';

const LOG_LEVEL: Readonly<Record<string, number>> = { debug: 1, info: 2, warn: 3, error: 4 };
const encoder = new TextEncoder();

export interface PublisherRates {
  poseRateHz: number;
  cameraRateHz: number;
  linkRateHz: number;
  deviceId: string;
}

export class LivePublisher {
  readonly #server: FoxgloveServer;
  readonly #hal: HardwareAbstractionLayer;
  readonly #space: RobotNamespace;
  readonly #rates: PublisherRates;
  readonly #channels = new Map<LiveTopic, number>();
  readonly #topicOfChannel = new Map<number, string>();
  readonly #extra = new Map<string, number>();
  readonly #subscribed = new Set<number>();
  readonly #timers: Array<ReturnType<typeof setInterval>> = [];
  readonly #telemetry: LinkTelemetry;
  #posing = false;
  #capturing = false;
  #latched: boolean | undefined;

  constructor(
    server: FoxgloveServer,
    hal: HardwareAbstractionLayer,
    names: { space: RobotNamespace; topics: Record<LiveTopic, string> },
    rates: PublisherRates,
  ) {
    this.#server = server;
    this.#hal = hal;
    this.#space = names.space;
    this.#rates = rates;
    this.#telemetry = linkTelemetry(hal);
    const offered: LiveTopic[] = ['pose', 'tf', 'halPose', 'log', 'safety'];
    if (rates.cameraRateHz > 0) offered.push('camera');
    if (this.#telemetry.steps !== undefined) offered.push('steps');
    if (this.#telemetry.link !== undefined) offered.push('link');
    for (const key of offered) {
      const { name, schema } = LIVE_SCHEMAS[key];
      const id = server.addChannel({
        topic: names.topics[key],
        encoding: 'json',
        schemaName: name,
        schema: JSON.stringify(schema),
        schemaEncoding: 'jsonschema',
      });
      this.#channels.set(key, id);
      this.#topicOfChannel.set(id, names.topics[key]);
    }
    server.on('subscribe', (id) => this.#subscribed.add(id));
    server.on('unsubscribe', (id) => this.#subscribed.delete(id));
  }

  /** Advertises one more JSON topic (another package's, as perception's); once per topic. */
  addTopic(topic: string, schema: NamedJsonSchema): void {
    if (this.#extra.has(topic)) return;
    const id = this.#server.addChannel({
      topic,
      encoding: 'json',
      schemaName: schema.name,
      schema: JSON.stringify(schema.schema),
      schemaEncoding: 'jsonschema',
    });
    this.#extra.set(topic, id);
    this.#topicOfChannel.set(id, topic);
  }

  /** Sends `value` on a topic of {@link addTopic} to its subscribers, logged at `atNs`. */
  sendOn(topic: string, value: unknown, atNs: bigint): void {
    const id = this.#extra.get(topic);
    if (id === undefined || !this.#subscribed.has(id)) return;
    this.#server.sendMessage(id, atNs, encoder.encode(JSON.stringify(value)));
  }

  /** The topic of a channel id (undefined for none of ours). */
  topicOf(channelId: number): string | undefined {
    return this.#topicOfChannel.get(channelId);
  }

  start(): void {
    const every = (hz: number, run: () => void) => {
      if (hz <= 0) return;
      const timer = setInterval(run, 1000 / hz);
      (timer as { unref?: () => void }).unref?.();
      this.#timers.push(timer);
    };
    every(this.#rates.poseRateHz, () => this.#samplePose());
    every(this.#rates.cameraRateHz, () => this.#sampleCamera());
    every(this.#rates.linkRateHz, () => this.#sampleLink());
  }

  stop(): void {
    for (const timer of this.#timers) clearInterval(timer);
    this.#timers.length = 0;
  }

  /** A log line on the log topic, from `name`. */
  log(message: string, level: unknown, name: string): void {
    this.#send('log', (at) => ({
      timestamp: foxgloveTimeOfMs(at),
      level: LOG_LEVEL[String(level)] ?? 2,
      message,
      name,
      file: '',
      line: 0,
    }));
  }

  /** An e-stop or reset made through the served HAL, as it answered. */
  safetyCall(
    event: 'emergency_stop' | 'reset',
    result: HALToolResult | undefined,
    reason?: string,
  ): void {
    const latched = this.#latch();
    this.#latched = latched;
    const message: SafetyEvent = {
      event,
      ...(event === 'emergency_stop' && reason !== undefined ? { reason } : {}),
      success: result?.success ?? false,
      ...(result?.code === undefined ? {} : { code: result.code }),
      emergency_stopped: latched,
    };
    this.#send('safety', () => message);
  }

  /** A camera frame (a data URL, as `captureFrame` answers). */
  frame(dataUrl: string): void {
    const comma = dataUrl.indexOf(',');
    const format = /^data:image\/(\w+)/.exec(dataUrl)?.[1] ?? 'jpeg';
    this.#send('camera', (at) => ({
      timestamp: foxgloveTimeOfMs(at),
      frame_id: this.#space.frame('camera'),
      data: comma >= 0 ? dataUrl.slice(comma + 1) : dataUrl,
      format,
    }));
  }

  #wanted(key: LiveTopic): boolean {
    const id = this.#channels.get(key);
    return id !== undefined && this.#subscribed.has(id);
  }

  /** Sends `make(now)` on `key` to its subscribers (nothing is made when none subscribes). */
  #send(key: LiveTopic, make: (atMs: number) => unknown): void {
    const id = this.#channels.get(key);
    if (id === undefined || !this.#subscribed.has(id)) return;
    // epoch time with the monotonic clock's resolution: a viewer's latency is read to the microsecond
    const at = performance.timeOrigin + performance.now();
    const payload = encoder.encode(JSON.stringify(make(at)));
    this.#server.sendMessage(id, BigInt(Math.round(at * 1e6)), payload);
  }

  #latch(): boolean {
    try {
      return this.#hal.safety.isEmergencyStopped();
    } catch {
      return this.#latched ?? false;
    }
  }

  /** A latch changed with no call through the view (a trip, another door's e-stop). */
  #watchLatch(): void {
    const latched = this.#latch();
    if (this.#latched === undefined || latched === this.#latched) {
      this.#latched = latched;
      return;
    }
    this.#latched = latched;
    this.#send('safety', () => ({
      event: latched ? 'latched' : 'cleared',
      success: true,
      emergency_stopped: latched,
    }));
  }

  #samplePose(): void {
    this.#watchLatch();
    if (this.#posing) return;
    if (!this.#wanted('pose') && !this.#wanted('tf') && !this.#wanted('halPose')) return;
    let ready = false;
    try {
      ready = this.#hal.isReady();
    } catch {
      ready = false;
    }
    if (!ready) return;
    this.#posing = true;
    this.#hal.locomotion
      .getPose()
      .then(
        (pose) => this.#pose(pose),
        () => undefined,
      )
      .finally(() => {
        this.#posing = false;
      });
  }

  #pose(pose: Pose): void {
    const { x, y, z } = pose.position;
    const { yaw, pitch, roll } = pose.rotation;
    const orientation = quaternionFromEuler(yaw, pitch, roll);
    this.#send('pose', (at) => ({
      timestamp: foxgloveTimeOfMs(at),
      frame_id: 'world',
      pose: { position: { x, y, z }, orientation },
    }));
    this.#send('tf', (at) => ({
      timestamp: foxgloveTimeOfMs(at),
      parent_frame_id: 'world',
      child_frame_id: this.#space.frame('base_link'),
      translation: { x, y, z },
      rotation: orientation,
    }));
    this.#send('halPose', () => pose);
  }

  #sampleCamera(): void {
    if (this.#capturing || !this.#wanted('camera')) return;
    this.#capturing = true;
    this.#hal.vision
      .captureFrame()
      .then(
        (frame) => this.frame(frame),
        () => undefined,
      )
      .finally(() => {
        this.#capturing = false;
      });
  }

  #sampleLink(): void {
    const read = <R>(reader: (() => R | undefined) | undefined): R | undefined => {
      try {
        return reader?.();
      } catch {
        return undefined;
      }
    };
    if (this.#wanted('steps')) {
      const steps = read(this.#telemetry.steps);
      if (steps !== undefined) this.#send('steps', () => steps);
    }
    if (this.#wanted('link')) {
      const link = read(this.#telemetry.link);
      if (link !== undefined) this.#send('link', () => link);
    }
  }
}
