import { scoped, silentLogger, withTimeout, errorMessage } from '@hal/types';
import type { ScopedLogger } from '@hal/types';
import { BackgroundWork } from './background-work.js';
import { period } from './call-values.js';
import { ChunkedMcapWriter } from './chunked-writer.js';
import { epochNsAt, monotonicEpochClock } from './clock.js';
import { chunkCompressor, zstdReady } from './compression.js';
import { Fifo } from './fifo.js';
import type { RecordingSink } from './file-sink.js';
import { openFileSink } from './file-sink.js';
import type { NamedJsonSchema } from './foxglove-schemas.js';
import { RECORDER_LOSS, TOPICS } from './messages.js';
import type { RecorderOptions, RecorderStats } from './recorder-options.js';
import { utf8 } from './utf8.js';

/** A message for the writer: data, not a closure, as there is one for every record. */
interface QueuedMessage {
  kind: 'message';
  topic: string;
  logTime: bigint;
  /** The JSON text (made UTF-8 as it is written). */
  json: string;
  /** Its length, counted against `maxQueuedBytes` (the UTF-8 bytes, for ASCII text). */
  bytes: number;
}

/** A schema, channel, metadata or end record (few, counted neither as written nor dropped). */
interface QueuedRecord {
  kind: 'record';
  bytes: number;
  run: (writer: ChunkedMcapWriter) => Promise<void>;
}

type QueuedOp = QueuedMessage | QueuedRecord;

/** The longest one turn of the recording's work runs before a reply or a call may go first. */
const WORK_SLICE_MS = 1;
/** How often waiting work looks for a moment with no recorded call on its way. */
const WORK_TICK_MS = 10;
/** The longest {@link McapRecorder.drained} and `close` wait for deferred tasks still waiting. */
const DEFERRED_WAIT_MS = 2000;
/** The longest a chunk stays open (ms) by default: what a killed process may lose of its file. */
const DEFAULT_CHUNK_INTERVAL_MS = 500;

/**
 * An MCAP file being written, chunked and compressed, with JSON-encoded channels. Every method
 * but {@link close} returns at once: records wait in a bounded queue that a single background
 * loop hands to the writer in order, so no caller ever waits for the disk. The loop works in
 * the moments no recorded call is on its way to the robot ({@link callBegan}), so a reply
 * never waits for the recording's work; once work has waited `maxHoldMs`, it goes on in short
 * windows while calls wait for their replies. A full queue or a failed disk drops messages,
 * counts them, logs it, and says so in the file at close.
 */
export class McapRecorder {
  readonly #writer: ChunkedMcapWriter;
  readonly #chunkIntervalMs: number;
  /** Closes the chunk being filled once it has been open `chunkIntervalMs`. */
  #chunkTimer: ReturnType<typeof setTimeout> | undefined;
  readonly #sink: RecordingSink;
  readonly #log: ScopedLogger;
  readonly #maxQueuedBytes: number;
  readonly #queue = new Fifo<QueuedOp>();
  readonly #channels = new Map<string, number>();
  readonly #schemas = new Map<string, number>();
  readonly #pendingTopics = new Set<string>();
  /** Deferred tasks not yet run. */
  readonly #tasks = new Fifo<() => void | PromiseLike<void>>();
  /** Deferred tasks that ran and wait for something (a pose) before they write. */
  readonly #waitingTasks = new Set<Promise<void>>();
  readonly #work: BackgroundWork;
  #queuedBytes = 0;
  #written = 0;
  #dropped = 0;
  #dropReason: string | undefined;
  #failure: string | undefined;
  #closed = false;
  readonly clock: () => bigint;
  readonly #ownClock: boolean;

  private constructor(sink: RecordingSink, options: RecorderOptions) {
    const compression = options.compression ?? 'zstd';
    const compressChunk = chunkCompressor(compression);
    this.#sink = sink;
    this.#log = scoped(options.logger ?? silentLogger, 'hal:recorder');
    this.#maxQueuedBytes = options.maxQueuedBytes ?? 16 * 1024 * 1024;
    this.clock = options.clock ?? monotonicEpochClock();
    this.#ownClock = options.clock !== undefined;
    this.#chunkIntervalMs = period(
      'chunkIntervalMs',
      options.chunkIntervalMs ?? DEFAULT_CHUNK_INTERVAL_MS,
    );
    this.#writer = new ChunkedMcapWriter({
      writable: sink,
      chunkSize: options.chunkSize ?? 64 * 1024,
      ...(compressChunk ? { compressChunk } : {}),
    });
    this.#work = new BackgroundWork({
      step: () => this.#step(),
      hasWork: () => this.#tasks.length > 0 || this.#queue.length > 0,
      maxHoldMs: period('maxHoldMs', options.maxHoldMs ?? 250),
      sliceMs: WORK_SLICE_MS,
      tickMs: WORK_TICK_MS,
    });
  }

  /** Starts a recording into `sink` (a file's, a memory buffer's, or your own writable). */
  static async create(sink: RecordingSink, options: RecorderOptions = {}): Promise<McapRecorder> {
    if ((options.compression ?? 'zstd') === 'zstd') await zstdReady();
    const recorder = new McapRecorder(sink, options);
    recorder.#enqueue({
      kind: 'record',
      bytes: 0,
      run: (writer) => writer.start({ profile: '', library: 'hal-recorder' }),
    });
    return recorder;
  }

  /** Starts a recording into a new file at `path` (replacing one that is there). */
  static async toFile(path: string, options: RecorderOptions = {}): Promise<McapRecorder> {
    return McapRecorder.create(await openFileSink(path), options);
  }

  /**
   * A reading of the file's clock, to be made a time with {@link timeOf} later: with the default
   * clock, `performance.now()`, which costs a call's path less than {@link clock}.
   */
  stamp(): number | bigint {
    return this.#ownClock ? this.clock() : performance.now();
  }

  /** The file's time (ns) of a {@link stamp}. */
  timeOf(stamp: number | bigint): bigint {
    return typeof stamp === 'bigint' ? stamp : epochNsAt(stamp);
  }

  /** Declares a JSON channel on `topic` with `schema` (once per topic; later calls are no-ops). */
  channel(topic: string, schema: NamedJsonSchema): void {
    if (this.#pendingTopics.has(topic) || this.#closed) return;
    this.#pendingTopics.add(topic);
    const data = utf8(JSON.stringify(schema.schema));
    this.#enqueue({
      kind: 'record',
      bytes: data.byteLength,
      run: async (writer) => {
        let schemaId = this.#schemas.get(schema.name);
        if (schemaId === undefined) {
          schemaId = await writer.registerSchema({
            name: schema.name,
            encoding: 'jsonschema',
            data,
          });
          this.#schemas.set(schema.name, schemaId);
        }
        const id = await writer.registerChannel({
          topic,
          schemaId,
          messageEncoding: 'json',
          metadata: new Map(),
        });
        this.#channels.set(topic, id);
      },
    });
  }

  /**
   * Queues `value` as a JSON message on `topic` (declared with {@link channel}) at `logTime`
   * (default now). Never throws and never waits.
   */
  write(topic: string, value: unknown, logTime: bigint = this.clock()): void {
    if (!this.#pendingTopics.has(topic)) {
      this.#drop(`message on undeclared topic ${topic}`);
      return;
    }
    let json: string | undefined;
    try {
      json = JSON.stringify(value);
    } catch (error) {
      this.#drop(`a message on ${topic} could not be encoded: ${String(error)}`);
      return;
    }
    if (json === undefined) {
      this.#drop(`a message on ${topic} has no JSON form (${typeof value})`);
      return;
    }
    this.#enqueue({ kind: 'message', topic, logTime, json, bytes: json.length });
  }

  /** Queues a metadata record (strings only, as MCAP has them). */
  metadata(name: string, values: Record<string, string>): void {
    const metadata = new Map(Object.entries(values));
    this.#enqueue({
      kind: 'record',
      bytes: JSON.stringify(values).length,
      run: (writer) => writer.addMetadata({ name, metadata }),
    });
  }

  /**
   * Runs `task` off the caller's path, with the rest of the recording's work: in a later turn
   * of the event loop with no recorded call on its way (or once work has waited `maxHoldMs`).
   * {@link drained} and {@link close} wait for deferred tasks (at most 2 s for one that waits on
   * a promise). A task that throws is ignored.
   */
  defer(task: () => void | PromiseLike<void>): void {
    this.#tasks.push(task);
    this.#work.kick();
  }

  /**
   * Marks a call on its way to the robot: until the function it returns is called (once the
   * call has answered), the recording's work waits, so the call's reply never waits for it.
   * Past `maxHoldMs` of calls back to back, a window of it runs while the call waits for its
   * reply, of a quarter of a typical call's round trip. The call's start and answer, as
   * `performance.now()` times, may be given where the caller has read them already.
   * (`recordHal` uses {@link callBegan} and {@link callEnded}, the same with no closure.)
   */
  callStarted(startedAt?: number): (answeredAt?: number) => void {
    return this.#work.callStarted(startedAt);
  }

  /**
   * {@link callStarted} without the closure, for a caller that pairs each call of it with exactly
   * one {@link callEnded} (`recordHal` does, as a paced loop's call pays for every allocation).
   */
  callBegan(): void {
    this.#work.callBegan();
  }

  /** Marks a call begun with {@link callBegan} answered, `durationMs` after it began. */
  callEnded(durationMs: number): void {
    this.#work.callEnded(durationMs);
  }

  /** What has been written and lost so far. */
  stats(): RecorderStats {
    return {
      written: this.#written,
      dropped: this.#dropped,
      queuedBytes: this.#queuedBytes,
      ...(this.#failure !== undefined ? { failure: this.#failure } : {}),
    };
  }

  /**
   * Resolves once everything queued and deferred so far has gone through the writer to the
   * sink, and the sink has it (a file: the operating system), calls on their way or not. A
   * deferred task waiting on a promise is waited for at most 2 s.
   */
  async drained(): Promise<void> {
    const deadline = performance.now() + DEFERRED_WAIT_MS;
    for (;;) {
      await this.#work.flush();
      await this.#sink.flushed?.();
      const left = deadline - performance.now();
      if (this.#waitingTasks.size === 0 || left <= 0) return;
      // the waiting tasks never reject (#runTask): this ends when they are done or time is up
      await withTimeout(Promise.all([...this.#waitingTasks]), left);
    }
  }

  /**
   * Writes what is queued, the loss record (on `/recorder/loss` and as metadata
   * `recorder.loss`), the summary and index, and closes the sink. Safe to call twice.
   */
  async close(): Promise<RecorderStats> {
    if (this.#closed) {
      await this.drained();
      return this.stats();
    }
    // what was deferred before close is part of the recording (a task may defer another)
    await this.drained();
    this.channel(TOPICS.loss, RECORDER_LOSS);
    const lossLater = (): Record<string, unknown> => ({
      written: this.#written,
      dropped: this.#dropped,
      ...(this.#dropReason !== undefined ? { reason: this.#dropReason } : {}),
    });
    // The loss record is built when its turn comes, so it counts everything before it, and
    // itself: `written` is then every message in the file, as stats() says after close.
    this.#enqueue({
      kind: 'record',
      bytes: 0,
      run: async (writer) => {
        const withMessage = this.#channels.has(TOPICS.loss);
        if (withMessage) this.#written += 1;
        const loss = lossLater();
        if (withMessage) {
          try {
            await this.#writeMessage(TOPICS.loss, this.clock(), loss);
          } catch (error) {
            this.#written -= 1;
            throw error;
          }
        }
        await writer.addMetadata({
          name: 'recorder.loss',
          metadata: new Map(Object.entries(loss).map(([k, v]) => [k, String(v)])),
        });
      },
    });
    this.#enqueue({ kind: 'record', bytes: 0, run: (writer) => writer.end() });
    this.#closed = true;
    await this.drained();
    this.#work.stop();
    if (this.#chunkTimer !== undefined) clearTimeout(this.#chunkTimer);
    try {
      await this.#sink.close();
    } catch (error) {
      this.#fail(error);
    }
    if (this.#dropped > 0) {
      this.#log.warn(`recording closed with ${this.#dropped} messages dropped`, {
        dropped: this.#dropped,
        reason: this.#dropReason,
      });
    }
    return this.stats();
  }

  #enqueue(op: QueuedOp): void {
    if (this.#closed || this.#failure !== undefined) {
      if (op.kind === 'message') this.#drop(this.#failure ?? 'the recording was closed');
      return;
    }
    if (op.kind === 'message' && this.#queuedBytes + op.bytes > this.#maxQueuedBytes) {
      this.#drop(`the disk is behind: ${this.#queuedBytes} bytes already waiting`);
      return;
    }
    this.#queue.push(op);
    this.#queuedBytes += op.bytes;
    this.#work.kick();
  }

  /** One piece of the background work: a deferred task, else the next record for the writer. */
  async #step(): Promise<boolean> {
    const task = this.#tasks.shift();
    if (task !== undefined) {
      this.#runTask(task);
      return true;
    }
    const op = this.#queue.shift();
    if (op === undefined) return false;
    this.#queuedBytes -= op.bytes;
    if (this.#failure !== undefined) {
      if (op.kind === 'message') this.#drop(this.#failure);
      return true;
    }
    try {
      if (op.kind === 'record') await op.run(this.#writer);
      else {
        await this.#writeMessage(op.topic, op.logTime, op.json);
        this.#written += 1;
        if (this.#writer.openChunkMessages === 1) this.#closeChunkLater();
      }
    } catch (error) {
      if (op.kind === 'message') this.#drop(String(error));
      this.#fail(error);
    }
    return true;
  }

  /** Hands one message to the writer: `json` is its JSON text, or a value made into it here. */
  #writeMessage(topic: string, logTime: bigint, json: string | object): Promise<void> {
    const channelId = this.#channels.get(topic);
    if (channelId === undefined) throw new Error(`channel ${topic} was never registered`);
    return this.#writer.addMessage({
      channelId,
      sequence: this.#written,
      logTime,
      publishTime: logTime,
      data: utf8(typeof json === 'string' ? json : JSON.stringify(json)),
    });
  }

  /**
   * A chunk has just opened: in `chunkIntervalMs`, it is closed (if it is still the one open),
   * through the queue, in its turn after the messages before it. The timer is armed here, in
   * the background work, never on a call's path.
   */
  #closeChunkLater(): void {
    if (this.#chunkTimer !== undefined) clearTimeout(this.#chunkTimer);
    const chunk = this.#writer.chunksWritten;
    this.#chunkTimer = setTimeout(() => {
      this.#chunkTimer = undefined;
      this.#enqueue({
        kind: 'record',
        bytes: 0,
        run: (writer) => (writer.chunksWritten === chunk ? writer.closeChunk() : Promise.resolve()),
      });
    }, this.#chunkIntervalMs);
    (this.#chunkTimer as { unref?: () => void }).unref?.();
  }

  #runTask(task: () => void | PromiseLike<void>): void {
    let result: void | PromiseLike<void>;
    try {
      result = task();
    } catch {
      return;
    }
    if (result === undefined) return;
    const waiting = Promise.resolve(result).then(
      () => undefined,
      () => undefined,
    );
    this.#waitingTasks.add(waiting);
    void waiting.finally(() => this.#waitingTasks.delete(waiting));
  }

  #fail(error: unknown): void {
    if (this.#failure !== undefined) return;
    this.#failure = `the recording's disk failed: ${errorMessage(error)}`;
    this.#log.warn(`${this.#failure}; the robot goes on, records are dropped and counted`);
  }

  #drop(reason: string): void {
    this.#dropped += 1;
    if (this.#dropReason === undefined) {
      this.#dropReason = reason;
      this.#log.warn(`recorder dropped a message: ${reason}`, { reason });
    }
  }
}
