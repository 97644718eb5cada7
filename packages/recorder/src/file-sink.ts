import type { IWritable } from '@mcap/core';

/** Where a recorder's bytes go: MCAP's writable, plus a close. */
export interface RecordingSink extends IWritable {
  close(): Promise<void>;
}

/**
 * A file opened for a recording. Each write goes to the operating system as it comes, so a
 * process killed mid-run leaves every chunk the writer finished on disk.
 */
export async function openFileSink(path: string): Promise<RecordingSink> {
  const { open } = await import('node:fs/promises');
  const handle = await open(path, 'w');
  let position = 0n;
  return {
    position: () => position,
    async write(buffer: Uint8Array) {
      let offset = 0;
      while (offset < buffer.byteLength) {
        const { bytesWritten } = await handle.write(buffer, offset, buffer.byteLength - offset);
        offset += bytesWritten;
      }
      position += BigInt(buffer.byteLength);
    },
    close: () => handle.close(),
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
