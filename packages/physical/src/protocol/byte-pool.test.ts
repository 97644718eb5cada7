import { describe, expect, it } from 'vitest';
import { BytePool } from './byte-pool.js';
import { MessageCodec } from './codec.js';
import { createAuthenticator } from './auth.js';

function write(pool: BytePool, text: string): Uint8Array {
  const room = pool.room(text.length);
  for (let i = 0; i < text.length; i++) room[i] = text.charCodeAt(i);
  return pool.take(text.length);
}

const ascii = (bytes: Uint8Array) => String.fromCharCode(...bytes);

describe('BytePool', () => {
  it('hands out views that later writes never change, across full slabs', () => {
    const pool = new BytePool(64);
    const taken = Array.from({ length: 50 }, (_, i) => [write(pool, `message ${i}`), i] as const);
    for (const [bytes, i] of taken) expect(ascii(bytes)).toBe(`message ${i}`);
  });

  it('gives room for a request larger than a slab', () => {
    const pool = new BytePool(16);
    const bytes = write(pool, 'x'.repeat(40));
    expect(bytes.length).toBe(40);
    expect(ascii(write(pool, 'after'))).toBe('after');
    expect(ascii(bytes)).toBe('x'.repeat(40));
  });

  it('hands out again what was not taken', () => {
    const pool = new BytePool(64);
    const first = pool.room(8);
    first[0] = 1;
    const again = pool.room(8);
    expect(again.byteOffset).toBe(first.byteOffset);
    expect(again.buffer).toBe(first.buffer);
  });
});

describe('MessageCodec request bytes', () => {
  it('stay as sent while thousands of later requests are encoded (a resend sends the same bytes)', async () => {
    for (const codec of [
      new MessageCodec(),
      new MessageCodec(await createAuthenticator('ab'.repeat(16))),
    ]) {
      const first = codec.encode({
        cmd: 'set_led',
        seq: 1,
        sid: 7,
        r: 1,
        g: 2,
        b: 3,
        pattern: 'solid',
      });
      const copy = first.slice();
      for (let seq = 2; seq < 5000; seq++) {
        codec.encode({ cmd: 'set_led', seq, sid: 7, r: seq % 256, g: 0, b: 0, pattern: 'blink' });
      }
      expect(first).toEqual(copy);
    }
  });

  it('encodes text beyond ASCII as UTF-8 and counts its bytes against the limit', () => {
    const codec = new MessageCodec();
    const bytes = codec.encode({ cmd: 'log', seq: 1, text: 'é✓😀' });
    expect(new TextDecoder().decode(bytes)).toBe('{"cmd":"log","seq":1,"text":"é✓😀"}');
    // 300 three-byte characters: under 1024 UTF-16 code units, over 1024 bytes
    expect(() => codec.encode({ cmd: 'log', seq: 1, text: '✓'.repeat(340) })).toThrow(
      expect.objectContaining({ code: 'RANGE_EXCEEDED' }),
    );
  });
});
