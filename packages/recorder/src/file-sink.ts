import type { IWritable } from '@mcap/core';

/** Where a recorder's bytes go: MCAP's writable, plus a close. */
export interface RecordingSink extends IWritable {
  close(): Promise<void>;
  /** Resolves once every write so far has reached its destination (a sink that writes behind). */
  flushed?(): Promise<void>;
}

/** Bytes a file sink holds for the disk before the writer waits for it (then the recorder drops). */
const MAX_PENDING_BYTES = 8 * 1024 * 1024;

/**
 * A file opened for a recording. Each write is handed to the operating system as it comes, in
 * order, behind the writer: the writer goes on at once (a finished chunk never holds up the
 * recording's work, or a call's reply, until the disk has it), unless 8 MiB already wait for
 * the disk. A process killed mid-run leaves every chunk the writer finished on disk. A write
 * that fails fails the next write and the close.
 */
export async function openFileSink(path: string): Promise<RecordingSink> {
  const { open } = await import('node:fs/promises');
  const handle = await open(path, 'w');
  let position = 0n;
  let pendingBytes = 0;
  let failure: unknown;
  let chain: Promise<void> = Promise.resolve();
  const writeAll = async (buffer: Uint8Array): Promise<void> => {
    let offset = 0;
    while (offset < buffer.byteLength) {
      const { bytesWritten } = await handle.write(buffer, offset, buffer.byteLength - offset);
      offset += bytesWritten;
    }
  };
  const failed = (): Promise<void> =>
    failure === undefined ? Promise.resolve() : Promise.reject(failure as Error);
  return {
    position: () => position,
    write(buffer: Uint8Array) {
      if (failure !== undefined) return failed();
      // the writer reuses its buffer once this resolves
      const bytes = buffer.slice();
      position += BigInt(bytes.byteLength);
      pendingBytes += bytes.byteLength;
      chain = chain
        .then(() => (failure === undefined ? writeAll(bytes) : undefined))
        .catch((error: unknown) => {
          failure ??= error;
        })
        .finally(() => {
          pendingBytes -= bytes.byteLength;
        });
      return pendingBytes > MAX_PENDING_BYTES ? chain.then(failed) : Promise.resolve();
    },
    flushed: () => chain,
    async close() {
      await chain;
      await handle.close();
      await failed();
    },
  };
}

/** A sink that keeps the file in memory (for a browser download, or a test). */
export function memorySink(): RecordingSink & { bytes(): Uint8Array } {
  const parts: Uint8Array[] = [];
  let position = 0n;
  return {
    position: () => position,
    write(buffer: Uint8Array) {
      parts.push(buffer.slice());
      position += BigInt(buffer.byteLength);
      return Promise.resolve();
    },
    close: () => Promise.resolve(),
    bytes() {
      const out = new Uint8Array(Number(position));
      let at = 0;
      for (const part of parts) {
        out.set(part, at);
        at += part.byteLength;
      }
      return out;
    },
  };
}
