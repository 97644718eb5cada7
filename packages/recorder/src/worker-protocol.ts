// The messages between a recorder and the worker thread that writes its file (mcap-worker.ts).
import type { ChunkCompression } from './compression.js';

/** What the worker is started with. */
export interface WorkerSetup {
  path: string;
  compression: ChunkCompression;
  chunkSize: number;
}

/**
 * One record for the writer, in order. Schema and channel ids are the recorder's own; the worker
 * maps them to the writer's. `bytes` is what the op weighs in the recorder's queue.
 */
export type WorkerOp = { bytes: number } & (
  | { t: 'start'; profile: string; library: string }
  | { t: 'schema'; id: number; name: string; encoding: string; data: Uint8Array }
  | {
      t: 'channel';
      id: number;
      topic: string;
      schemaId: number;
      messageEncoding: string;
      metadata: [string, string][];
    }
  | {
      t: 'message';
      channelId: number;
      sequence: number;
      logTime: bigint;
      publishTime: bigint;
      data: Uint8Array;
    }
  | { t: 'metadata'; name: string; entries: [string, string][] }
  | { t: 'end' }
);

/** What the worker says back. */
export type WorkerReply =
  /** The file is open; records may come. */
  | { t: 'ready' }
  /** The file could not be opened (the worker then exits). */
  | { t: 'refused'; reason: string }
  /**
   * A batch was written: its `bytes`, and how many of its messages were lost to a failure (the
   * first failure's reason with them; everything after a failure is lost too).
   */
  | { t: 'done'; bytes: number; lost: number; failure?: string }
  /** The summary and footer are written and the file is closed. */
  | { t: 'closed'; failure?: string };
