// A RecordWriter whose MCAP writer runs on a worker thread (mcap-worker.ts), for recordings to a
// file in Node. Each call only appends a record to a batch; batches go to the worker every few
// milliseconds (or every 16 KiB), and the worker says when each is on disk. So a chunk's CRC32
// and compression never hold up the thread that answers the robot.
import type { Worker } from 'node:worker_threads';
import type { McapTypes } from '@mcap/core';
import type { ChunkCompression } from './compression.js';
import type { RecordWriter } from './record-writer.js';
import type { WorkerOp, WorkerReply, WorkerSetup } from './worker-protocol.js';

/** A batch goes to the worker after this long, or sooner when it reaches BATCH_BYTES. */
const BATCH_MS = 50;
const BATCH_BYTES = 256 * 1024;
/** Bytes sent and not yet written beyond which the writer waits (the recorder's queue fills). */
const IN_FLIGHT_BYTES = 4 * 1024 * 1024;
/** Longest wait for the worker to open the file, or to close it. */
const WORKER_TIMEOUT_MS = 10_000;

const encoder = new TextEncoder();

// Node's modules are imported when a recording starts, not at the top: the recorder is also
// imported by pages (the demo), whose bundlers have no node:fs.
async function nodeModules() {
  const [fs, module, path, url, threads] = await Promise.all([
    import('node:fs'),
    import('node:module'),
    import('node:path'),
    import('node:url'),
    import('node:worker_threads'),
  ]);
  return { fs, module, path, url, threads };
}
type NodeModules = Awaited<ReturnType<typeof nodeModules>>;

/**
 * How to start the worker: its script beside this file (.js when built); from source, a .ts file
 * that a worker loads through tsx, registered in the worker first (module hooks are per thread).
 * Undefined when the script is not there (a single-file bundle that left it out).
 */
function workerSource({
  fs,
  module,
  path,
  url: nodeUrl,
}: NodeModules): { code: string | URL; eval: boolean } | undefined {
  const here = import.meta.url;
  const fromSource = here.endsWith('.ts');
  // a name in a variable: bundlers that rewrite `new URL('literal', import.meta.url)` leave it be
  const name = fromSource ? './mcap-worker.ts' : './mcap-worker.js';
  const url = new URL(name, here);
  if (url.protocol !== 'file:' || !fs.existsSync(nodeUrl.fileURLToPath(url))) return undefined;
  if (!fromSource) return { code: url, eval: false };
  let tsx: string;
  try {
    // tsx's ESM API, from its own export map: its register() sets its hooks for this thread
    const require = module.createRequire(here);
    const manifestPath = require.resolve('tsx/package.json');
    const manifest = JSON.parse(fs.readFileSync(manifestPath, 'utf8')) as {
      exports?: Record<string, { import?: { default?: string } }>;
    };
    const entry = manifest.exports?.['./esm/api']?.import?.default;
    if (entry === undefined) return undefined;
    tsx = nodeUrl.pathToFileURL(path.join(path.dirname(manifestPath), entry)).href;
  } catch {
    return undefined;
  }
  const code = `import(${JSON.stringify(tsx)}).then((tsx) => { tsx.register(); return import(${JSON.stringify(url.href)}); });`;
  return { code, eval: true };
}

/** Writes an MCAP file from a worker thread. */
export class WorkerWriter implements RecordWriter {
  readonly #worker: Worker;
  #batch: WorkerOp[] = [];
  #batchBytes = 0;
  #timer: ReturnType<typeof setTimeout> | undefined;
  #inFlight = 0;
  #space: (() => void)[] = [];
  #failure: string | undefined;
  #closed: ((failure: string | undefined) => void) | undefined;
  #nextSchema = 1;
  #nextChannel = 0;
  /** Told of messages handed over earlier and then lost to a failure in the worker. */
  onLost: (count: number, reason: string) => void = () => undefined;

  private constructor(worker: Worker) {
    this.#worker = worker;
  }

  /**
   * Starts the worker and opens `path` there. Undefined when no worker can be started here (its
   * script is not beside this file, as in a single-file bundle that lacks it); rejects with the
   * reason when the file cannot be opened.
   */
  static async open(
    path: string,
    options: { compression: ChunkCompression; chunkSize: number },
  ): Promise<WorkerWriter | undefined> {
    const node = await nodeModules();
    const source = workerSource(node);
    if (source === undefined) return undefined;
    const setup: WorkerSetup = { path, ...options };
    const worker = new node.threads.Worker(source.code, { workerData: setup, eval: source.eval });
    const writer = new WorkerWriter(worker);
    await new Promise<void>((resolve, reject) => {
      const timer = setTimeout(() => {
        void worker.terminate();
        reject(
          new Error(`the recording's worker did not open ${path} within ${WORKER_TIMEOUT_MS} ms`),
        );
      }, WORKER_TIMEOUT_MS);
      const first = (reply: WorkerReply) => {
        clearTimeout(timer);
        worker.off('error', failed);
        if (reply.t === 'ready') {
          resolve();
          return;
        }
        void worker.terminate();
        reject(new Error(reply.t === 'refused' ? reply.reason : `unexpected ${reply.t}`));
      };
      const failed = (error: Error) => {
        clearTimeout(timer);
        worker.off('message', first);
        reject(error);
      };
      worker.once('message', first);
      worker.once('error', failed);
    });
    worker.on('message', (reply: WorkerReply) => writer.#reply(reply));
    worker.on('error', (error) => writer.#fail(error.message));
    worker.on('exit', () => writer.#fail('the recording worker exited'));
    // the worker never keeps the program alive by itself: a program that ends closes the recorder
    worker.unref();
    return writer;
  }

  start(header: McapTypes.Header): Promise<void> {
    return this.#send({ t: 'start', bytes: 0, profile: header.profile, library: header.library });
  }

  async registerSchema(schema: Omit<McapTypes.Schema, 'id'>): Promise<number> {
    const id = this.#nextSchema++;
    await this.#send({ t: 'schema', bytes: schema.data.byteLength, id, ...schema });
    return id;
  }

  async registerChannel(channel: Omit<McapTypes.Channel, 'id'>): Promise<number> {
    const id = this.#nextChannel++;
    await this.#send({
      t: 'channel',
      bytes: 0,
      id,
      topic: channel.topic,
      schemaId: channel.schemaId,
      messageEncoding: channel.messageEncoding,
      metadata: [...channel.metadata],
    });
    return id;
  }

  addMessage(message: McapTypes.Message): Promise<void> {
    return this.#send({
      t: 'message',
      bytes: message.data.byteLength,
      channelId: message.channelId,
      sequence: message.sequence,
      logTime: message.logTime,
      publishTime: message.publishTime,
      data: message.data,
    });
  }

  addMetadata(metadata: McapTypes.Metadata): Promise<void> {
    const entries = [...metadata.metadata];
    return this.#send({
      t: 'metadata',
      bytes: encoder.encode(JSON.stringify(entries)).byteLength,
      name: metadata.name,
      entries,
    });
  }

  /** Sends the end and waits (at most 10 s) until the worker has closed the file. */
  async end(): Promise<void> {
    if (this.#failure !== undefined) throw new Error(this.#failure);
    const closed = new Promise<string | undefined>((resolve) => (this.#closed = resolve));
    this.#batch.push({ t: 'end', bytes: 0 });
    this.#flush();
    let timer: ReturnType<typeof setTimeout> | undefined;
    const failure = await Promise.race([
      closed,
      new Promise<string>((resolve) => {
        timer = setTimeout(
          () =>
            resolve(`the recording worker did not close the file within ${WORKER_TIMEOUT_MS} ms`),
          WORKER_TIMEOUT_MS,
        );
      }),
    ]);
    clearTimeout(timer);
    await this.#worker.terminate();
    if (failure !== undefined) throw new Error(failure);
  }

  async #send(op: WorkerOp): Promise<void> {
    if (this.#failure !== undefined) throw new Error(this.#failure);
    while (this.#inFlight > IN_FLIGHT_BYTES && this.#failure === undefined) {
      await new Promise<void>((resolve) => this.#space.push(resolve));
    }
    if (this.#failure !== undefined) throw new Error(this.#failure);
    this.#batch.push(op);
    this.#batchBytes += op.bytes;
    if (this.#batchBytes >= BATCH_BYTES) this.#flush();
    else this.#timer ??= setTimeout(() => this.#flush(), BATCH_MS);
  }

  #flush(): void {
    clearTimeout(this.#timer);
    this.#timer = undefined;
    if (this.#batch.length === 0) return;
    this.#inFlight += this.#batchBytes;
    this.#worker.postMessage(this.#batch);
    this.#batch = [];
    this.#batchBytes = 0;
  }

  #reply(reply: WorkerReply): void {
    if (reply.t === 'done') {
      this.#inFlight -= reply.bytes;
      if (reply.lost > 0) this.onLost(reply.lost, reply.failure ?? 'the recording worker failed');
      if (reply.failure !== undefined) this.#fail(reply.failure);
      for (const resolve of this.#space.splice(0)) resolve();
    } else if (reply.t === 'closed') {
      this.#closed?.(reply.failure);
    }
  }

  #fail(reason: string): void {
    this.#failure ??= reason;
    for (const resolve of this.#space.splice(0)) resolve();
    this.#closed?.(this.#failure);
  }
}
