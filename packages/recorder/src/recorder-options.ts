import type { Logger } from '@hal/types';
import type { ChunkCompression } from './compression.js';

/** How a recorder writes. */
export interface RecorderOptions {
  /** Chunk compression. Default 'zstd'. */
  compression?: ChunkCompression;
  /**
   * Bytes of messages per chunk before it is written out (default 64 KiB). A process killed
   * mid-run loses at most the chunk being filled (see `chunkIntervalMs`).
   */
  chunkSize?: number;
  /**
   * The longest a chunk stays open (ms, default 500): a chunk is written out when it is full or
   * when its first message is this old, whichever comes first, so a process killed mid-run loses
   * at most this much of its recording (plus what waits in the queue: see `maxHoldMs`). Shorter
   * means smaller chunks, which compress less well.
   */
  chunkIntervalMs?: number;
  /**
   * Bytes of messages the recorder holds while the disk catches up (default 16 MiB). Beyond it,
   * new messages are dropped and counted; a call never waits for the disk.
   */
  maxQueuedBytes?: number;
  /** Where warnings go (a dropped message, a failed disk). Default: nowhere. */
  logger?: Logger;
  /** The file's clock, nanoseconds since the epoch. Default: monotonic wall-clock time. */
  clock?: () => bigint;
  /**
   * The longest the recording's work waits for a moment with no recorded call on its way to the
   * robot (ms, default 250). Past it, while calls keep coming back to back, the work runs in a
   * window while each call waits for its reply. A process killed meanwhile loses what waits,
   * besides the chunk being filled.
   */
  maxHoldMs?: number;
}

/** What a recorder wrote and lost. */
export interface RecorderStats {
  /**
   * Messages handed to the MCAP writer: after `close()`, every message in the file, the
   * recorder's own `/recorder/loss` among them.
   */
  written: number;
  /** Messages dropped: the queue was full, the disk failed, or the recorder was closed. */
  dropped: number;
  /** Bytes waiting for the disk. */
  queuedBytes: number;
  /** Why the disk stopped taking writes, once it has. */
  failure?: string;
}
