import { scoped, silentLogger } from '@hal/types';
import type { Logger, ScopedLogger } from '@hal/types';
import { McapWriter } from '@mcap/core';
import { monotonicEpochClock } from './clock.js';
import { chunkCompressor, zstdReady } from './compression.js';
import type { ChunkCompression } from './compression.js';
import type { RecordingSink } from './file-sink.js';
import { openFileSink } from './file-sink.js';
import type { NamedJsonSchema } from './foxglove-schemas.js';
import { RECORDER_LOSS, TOPICS } from './messages.js';

/** How a recorder writes. */
export interface RecorderOptions {
  /** Chunk compression. Default 'zstd'. */
  compression?: ChunkCompression;
  /**
   * Bytes of messages per chunk before it is written out (default 64 KiB). A process killed
   * mid-run loses at most the chunk being filled.
   */
  chunkSize?: number;
  /**
   * Bytes of messages the recorder holds while the disk catches up (default 16 MiB). Beyond it,
   * new messages are dropped and counted; a call never waits for the disk.
   */
  maxQueuedBytes?: number;
  /** Where warnings go (a dropped message, a failed disk). Default: nowhere. */
  logger?: Logger;
  /** The file's clock, nanoseconds since the epoch. Default: monotonic wall-clock time. */
  clock?: () => bigint;
}

/** What a recorder wrote and lost. */
export interface RecorderStats {
  /** Messages handed to the MCAP writer. */
  written: number;
  /** Messages dropped: the queue was full, the disk failed, or the recorder was closed. */
  dropped: number;
  /** Bytes waiting for the disk. */
  queuedBytes: number;
  /** Why the disk stopped taking writes, once it has. */
  failure?: string;
}

interface QueuedOp {
  bytes: number;
  run: (writer: McapWriter) => Promise<void>;
  /** A message (counted as written or dropped); schema, channel and metadata records are not. */
  message: boolean;
}

const encoder = new TextEncoder();

/** A later turn of the event loop: setImmediate in Node, a zero timeout in a browser. */
const nextTurn: (run: () => void) => void =
  typeof setImmediate === 'function' ? (run) => setImmediate(run) : (run) => setTimeout(run, 0);

/**
 * An MCAP file being written, chunked and compressed, with JSON-encoded channels. Every method
 * but {@link close} returns at once: records wait in a bounded queue that a single background
 * loop hands to the writer in order, so no caller ever waits for the disk. A full queue or a
 * failed disk drops messages, counts them, logs it, and says so in the file at close.
 */
export class McapRecorder {
  readonly #writer: McapWriter;
  readonly #sink: RecordingSink;
  readonly #log: ScopedLogger;
  readonly #maxQueuedBytes: number;
  readonly #queue: QueuedOp[] = [];
  readonly #channels = new Map<string, number>();
  readonly #schemas = new Map<string, number>();
  readonly #pendingTopics = new Set<string>();
  readonly #deferred = new Set<Promise<void>>();
  #queuedBytes = 0;
  #written = 0;
  #dropped = 0;
  #dropReason: string | undefined;
  #failure: string | undefined;
  #pump: Promise<void> | undefined;
  #closed = false;
  readonly clock: () => bigint;

  private constructor(sink: RecordingSink, options: RecorderOptions) {
    const compression = options.compression ?? 'zstd';
    const compressChunk = chunkCompressor(compression);
    this.#sink = sink;
    this.#log = scoped(options.logger ?? silentLogger, 'hal:recorder');
    this.#maxQueuedBytes = options.maxQueuedBytes ?? 16 * 1024 * 1024;
    this.clock = options.clock ?? monotonicEpochClock();
    this.#writer = new McapWriter({
      writable: sink,
      useChunks: true,
      chunkSize: options.chunkSize ?? 64 * 1024,
      ...(compressChunk ? { compressChunk } : {}),
    });
  }

  /** Starts a recording into `sink` (a file's, a memory buffer's, or your own writable). */
  static async create(sink: RecordingSink, options: RecorderOptions = {}): Promise<McapRecorder> {
    if ((options.compression ?? 'zstd') === 'zstd') await zstdReady();
    const recorder = new McapRecorder(sink, options);
    recorder.#enqueue({
      bytes: 0,
      message: false,
      run: (writer) => writer.start({ profile: '', library: 'hal-recorder' }),
    });
    return recorder;
  }

  /** Starts a recording into a new file at `path` (replacing one that is there). */
  static async toFile(path: string, options: RecorderOptions = {}): Promise<McapRecorder> {
    return McapRecorder.create(await openFileSink(path), options);
  }

  /** Declares a JSON channel on `topic` with `schema` (once per topic; later calls are no-ops). */
  channel(topic: string, schema: NamedJsonSchema): void {
    if (this.#pendingTopics.has(topic) || this.#closed) return;
    this.#pendingTopics.add(topic);
    const data = encoder.encode(JSON.stringify(schema.schema));
    this.#enqueue({
      bytes: data.byteLength,
      message: false,
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
    let data: Uint8Array;
    try {
      data = encoder.encode(JSON.stringify(value));
    } catch (error) {
      this.#drop(`a message on ${topic} could not be encoded: ${String(error)}`);
      return;
    }
    this.#enqueue({
      bytes: data.byteLength,
      message: true,
      run: async (writer) => {
        const channelId = this.#channels.get(topic);
        if (channelId === undefined) throw new Error(`channel ${topic} was never registered`);
        await writer.addMessage({
          channelId,
          sequence: this.#written,
          logTime,
          publishTime: logTime,
          data,
        });
      },
    });
  }

  /** Queues a metadata record (strings only, as MCAP has them). */
  metadata(name: string, values: Record<string, string>): void {
    const metadata = new Map(Object.entries(values));
    this.#enqueue({
      bytes: JSON.stringify(values).length,
      message: false,
      run: (writer) => writer.addMetadata({ name, metadata }),
    });
  }

  /**
   * Runs `task` off the caller's path: after the current turn of the event loop, so the caller
   * (the robot's next command) goes first and the recording work overlaps its wait for the
   * robot. {@link close} waits for deferred tasks (at most 2 s). A task that throws is ignored.
   */
  defer(task: () => void | PromiseLike<void>): void {
    const run = new Promise<void>((resolve) => nextTurn(resolve)).then(task).catch(() => undefined);
    this.#deferred.add(run);
    void run.finally(() => this.#deferred.delete(run));
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

  /** Resolves once everything queued so far has reached the writer. */
  async drained(): Promise<void> {
    while (this.#pump) await this.#pump;
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
    const deadline = performance.now() + 2000;
    while (this.#deferred.size > 0 && performance.now() < deadline) {
      await Promise.race([
        Promise.all([...this.#deferred]),
        new Promise((resolve) => setTimeout(resolve, Math.max(0, deadline - performance.now()))),
      ]);
    }
    this.channel(TOPICS.loss, RECORDER_LOSS);
    const lossLater = (): Record<string, unknown> => ({
      written: this.#written,
      dropped: this.#dropped,
      ...(this.#dropReason !== undefined ? { reason: this.#dropReason } : {}),
    });
    // The loss record is built when its turn comes, so it counts everything before it.
    this.#enqueue({
      bytes: 0,
      message: false,
      run: async (writer) => {
        const channelId = this.#channels.get(TOPICS.loss);
        const loss = lossLater();
        const logTime = this.clock();
        if (channelId !== undefined) {
          await writer.addMessage({
            channelId,
            sequence: this.#written,
            logTime,
            publishTime: logTime,
            data: encoder.encode(JSON.stringify(loss)),
          });
        }
        await writer.addMetadata({
          name: 'recorder.loss',
          metadata: new Map(Object.entries(loss).map(([k, v]) => [k, String(v)])),
        });
      },
    });
    this.#enqueue({ bytes: 0, message: false, run: (writer) => writer.end() });
    this.#closed = true;
    await this.drained();
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
      if (op.message) this.#drop(this.#failure ?? 'the recording was closed');
      return;
    }
    if (op.message && this.#queuedBytes + op.bytes > this.#maxQueuedBytes) {
      this.#drop(`the disk is behind: ${this.#queuedBytes} bytes already waiting`);
      return;
    }
    this.#queue.push(op);
    this.#queuedBytes += op.bytes;
    this.#pump ??= this.#run();
  }

  async #run(): Promise<void> {
    // Start on a later turn, so the caller that queued the first record is never held up.
    await Promise.resolve();
    for (let op = this.#queue.shift(); op; op = this.#queue.shift()) {
      this.#queuedBytes -= op.bytes;
      if (this.#failure !== undefined) {
        if (op.message) this.#drop(this.#failure);
        continue;
      }
      try {
        await op.run(this.#writer);
        if (op.message) this.#written += 1;
      } catch (error) {
        if (op.message) this.#drop(String(error));
        this.#fail(error);
      }
    }
    this.#pump = undefined;
  }

  #fail(error: unknown): void {
    if (this.#failure !== undefined) return;
    this.#failure = `the recording's disk failed: ${error instanceof Error ? error.message : String(error)}`;
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
