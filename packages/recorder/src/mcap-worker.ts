// The worker thread of a recording (see worker-writer.ts): it owns the MCAP writer and the file,
// so finishing a chunk (its CRC32 and its compression, about 0.3 ms for 64 KiB) happens here and
// never on the thread that answers the robot.
import { parentPort, workerData } from 'node:worker_threads';
import type { MessagePort } from 'node:worker_threads';
import { McapWriter } from '@mcap/core';
import { chunkCompressor, zstdReady } from './compression.js';
import { openFileSink } from './file-sink.js';
import type { RecordingSink } from './file-sink.js';
import type { WorkerOp, WorkerReply, WorkerSetup } from './worker-protocol.js';

if (parentPort === null) throw new Error('mcap-worker.ts runs as a worker thread of a recorder');
const port: MessagePort = parentPort;
const setup = workerData as WorkerSetup;
const post = (reply: WorkerReply) => port.postMessage(reply);
const reason = (error: unknown) => (error instanceof Error ? error.message : String(error));

let sink: RecordingSink;
try {
  if (setup.compression === 'zstd') await zstdReady();
  sink = await openFileSink(setup.path);
} catch (error) {
  // said to the recorder, which rejects with it; the worker then ends with nothing open
  post({ t: 'refused', reason: reason(error) });
  port.close();
  process.exit(0);
}
const compressChunk = chunkCompressor(setup.compression);
const writer = new McapWriter({
  writable: sink,
  useChunks: true,
  chunkSize: setup.chunkSize,
  ...(compressChunk ? { compressChunk } : {}),
});
// the recorder's ids to the writer's
const schemaIds = new Map<number, number>();
const channelIds = new Map<number, number>();
let failure: string | undefined;

async function apply(op: WorkerOp): Promise<boolean> {
  switch (op.t) {
    case 'start':
      await writer.start({ profile: op.profile, library: op.library });
      return false;
    case 'schema':
      schemaIds.set(
        op.id,
        await writer.registerSchema({ name: op.name, encoding: op.encoding, data: op.data }),
      );
      return false;
    case 'channel': {
      const schemaId = schemaIds.get(op.schemaId);
      if (schemaId === undefined) throw new Error(`schema ${op.schemaId} was never registered`);
      channelIds.set(
        op.id,
        await writer.registerChannel({
          topic: op.topic,
          schemaId,
          messageEncoding: op.messageEncoding,
          metadata: new Map(op.metadata),
        }),
      );
      return false;
    }
    case 'message': {
      const channelId = channelIds.get(op.channelId);
      if (channelId === undefined) throw new Error(`channel ${op.channelId} was never registered`);
      await writer.addMessage({
        channelId,
        sequence: op.sequence,
        logTime: op.logTime,
        publishTime: op.publishTime,
        data: op.data,
      });
      return false;
    }
    case 'metadata':
      await writer.addMetadata({ name: op.name, metadata: new Map(op.entries) });
      return false;
    case 'end':
      await writer.end();
      await sink.close();
      return true;
  }
}

async function runBatch(batch: WorkerOp[]): Promise<void> {
  let bytes = 0;
  let lost = 0;
  let ended = false;
  for (const op of batch) {
    bytes += op.bytes;
    if (failure !== undefined) {
      if (op.t === 'message') lost += 1;
      continue;
    }
    try {
      ended = (await apply(op)) || ended;
    } catch (error) {
      failure = reason(error);
      if (op.t === 'message') lost += 1;
    }
  }
  post({ t: 'done', bytes, lost, ...(failure === undefined ? {} : { failure }) });
  if (!ended && batch.some((op) => op.t === 'end')) {
    // the end was skipped after a failure: the file is closed as it is
    await sink.close().catch(() => undefined);
    ended = true;
  }
  if (ended) {
    post({ t: 'closed', ...(failure === undefined ? {} : { failure }) });
    port.close();
  }
}

// one batch after the other, in order
let queue = Promise.resolve();
port.on('message', (batch: WorkerOp[]) => {
  queue = queue.then(() => runBatch(batch));
});
post({ t: 'ready' });
