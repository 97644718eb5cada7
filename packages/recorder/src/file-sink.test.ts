import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import { openFileSink } from './file-sink.js';

describe('openFileSink', () => {
  const dirs: string[] = [];
  afterEach(() => {
    for (const dir of dirs.splice(0)) rmSync(dir, { recursive: true, force: true });
  });

  it('writes behind the writer, in order, from a copy: the writer may reuse its buffer at once', async () => {
    const dir = mkdtempSync(join(tmpdir(), 'hal-file-sink-'));
    dirs.push(dir);
    const path = join(dir, 'out.bin');
    const sink = await openFileSink(path);
    const buffer = new Uint8Array(4);
    for (let n = 0; n < 100; n += 1) {
      buffer.fill(n);
      await sink.write(buffer);
    }
    expect(sink.position()).toBe(400n);
    await sink.flushed?.();
    const bytes = readFileSync(path);
    expect(bytes).toHaveLength(400);
    for (let n = 0; n < 100; n += 1)
      expect([...bytes.subarray(n * 4, n * 4 + 4)]).toEqual([n, n, n, n]);
    await sink.close();
  });

  it('fails the next write and the close once the disk has refused one, and writes no more', async () => {
    // /dev/full takes the open and refuses every write with ENOSPC
    const sink = await openFileSink('/dev/full');
    await sink.write(new Uint8Array(16));
    await sink.flushed?.();
    await expect(sink.write(new Uint8Array(16))).rejects.toThrow(/ENOSPC/);
    await expect(sink.close()).rejects.toThrow(/ENOSPC/);
  });
});
