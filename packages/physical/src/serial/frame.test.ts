import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { crc16, decodeFrame, encodeFrame, FrameDecoder } from './frame.js';
import type { Frame, FrameEvent } from './frame.js';

interface Vector {
  name: string;
  hex: string;
  decoded?: { type: 'data' | 'ack'; seq: number; payload: string };
  error?: string;
}

const vectors = JSON.parse(
  readFileSync(new URL('../../../../tests/vectors/serial-frames.json', import.meta.url), 'utf8'),
) as Vector[];
const valid = vectors.filter((v) => v.decoded !== undefined);
const invalid = vectors.filter((v) => v.error !== undefined);
const bytes = (hex: string) => new Uint8Array(Buffer.from(hex, 'hex'));
const text = (payload: Uint8Array) => new TextDecoder().decode(payload);
const frames = (events: FrameEvent[]) =>
  events.filter((e): e is { kind: 'frame'; frame: Frame } => e.kind === 'frame');

describe('crc16', () => {
  it('is CRC-16/CCITT-FALSE: 0x29B1 for "123456789"', () => {
    expect(crc16(new TextEncoder().encode('123456789'))).toBe(0x29b1);
  });
});

describe('decodeFrame', () => {
  it('has golden vectors to check', () => {
    expect(valid.length).toBeGreaterThan(3);
    expect(invalid.length).toBeGreaterThan(3);
  });

  for (const vector of valid) {
    it(`decodes the golden frame ${vector.name}`, () => {
      const result = decodeFrame(bytes(vector.hex));
      expect(result.ok).toBe(true);
      if (!result.ok) return;
      expect(result.frame.type).toBe(vector.decoded?.type);
      expect(result.frame.seq).toBe(vector.decoded?.seq);
      expect(text(result.frame.payload)).toBe(vector.decoded?.payload);
    });

    it(`encodes ${vector.name} to the golden bytes`, () => {
      const d = vector.decoded!;
      const encoded = encodeFrame({
        type: d.type,
        seq: d.seq,
        payload: new TextEncoder().encode(d.payload),
      });
      expect(Buffer.from(encoded).toString('hex')).toBe(vector.hex);
    });

    it(`rejects every single-bit error anywhere in ${vector.name}`, () => {
      const good = bytes(vector.hex);
      let rejected = 0;
      for (let bit = 0; bit < good.length * 8; bit++) {
        const bad = good.slice();
        bad[bit >> 3]! ^= 1 << (bit & 7);
        const result = decodeFrame(bad);
        const streamed = frames(new FrameDecoder().push(bad));
        if (!result.ok && streamed.length === 0) rejected += 1;
      }
      expect(rejected).toBe(good.length * 8);
    });
  }

  for (const vector of invalid) {
    it(`rejects ${vector.name} as ${vector.error}`, () => {
      const result = decodeFrame(bytes(vector.hex));
      expect(result).toEqual({ ok: false, error: vector.error });
    });
  }
});

describe('FrameDecoder', () => {
  const golden = valid.map((v) => bytes(v.hex));

  it('finds every frame in a stream with random garbage between them', () => {
    let seed = 42;
    const random = () => {
      seed = (seed * 1103515245 + 12345) & 0x7fffffff;
      return seed / 0x7fffffff;
    };
    const chunks: number[] = [];
    for (const frame of golden) {
      const garbage = Array.from({ length: Math.floor(random() * 40) }, () =>
        random() < 0.1 ? 0xa5 : Math.floor(random() * 256),
      );
      chunks.push(...garbage, ...frame);
    }
    const stream = new Uint8Array(chunks);
    const decoder = new FrameDecoder();
    const found: Frame[] = [];
    // in uneven pieces, as a serial port delivers them
    for (let at = 0; at < stream.length;) {
      const size = 1 + Math.floor(random() * 64);
      found.push(...frames(decoder.push(stream.subarray(at, at + size))).map((e) => e.frame));
      at += size;
    }
    expect(found.map((f) => f.seq)).toEqual(valid.map((v) => v.decoded!.seq));
  });

  it('resynchronises on the next frame after a corrupted one', () => {
    const corrupted = golden[0]!.slice();
    corrupted[12]! ^= 0x10;
    const found = frames(new FrameDecoder().push(new Uint8Array([...corrupted, ...golden[1]!])));
    expect(found.map((e) => e.frame.seq)).toEqual([valid[1]!.decoded!.seq]);
  });

  it('keeps frame payloads intact when the caller reuses its chunk buffer', () => {
    const decoder = new FrameDecoder();
    const chunk = new Uint8Array(golden[0]!.length + 5);
    chunk.set(golden[0]!, 0);
    chunk.set(golden[1]!.subarray(0, 5), golden[0]!.length);
    const first = frames(decoder.push(chunk));
    const expected = first[0]!.frame.payload.slice();
    chunk.fill(0xa5); // a serial binding may hand out the same memory again
    const second = frames(decoder.push(golden[1]!.subarray(5)));
    expect(first[0]!.frame.payload).toEqual(expected);
    expect(second[0]!.frame.seq).toBe(valid[1]!.decoded!.seq);
  });

  it('holds no more than the unfinished frame between pushes', () => {
    const decoder = new FrameDecoder();
    const stream = new Uint8Array(golden.reduce((n, f) => n + f.length, 0));
    let at = 0;
    for (const frame of golden) {
      stream.set(frame, at);
      at += frame.length;
    }
    const cut = golden[0]!.length + 3;
    decoder.push(stream.subarray(0, cut));
    expect(decoder.pending).toBe(3);
    decoder.push(stream.subarray(cut));
    expect(decoder.pending).toBe(0);
  });

  it('abandons a partial frame and finds a frame that starts inside it', () => {
    const decoder = new FrameDecoder();
    expect(frames(decoder.push(golden[0]!.subarray(0, 20)))).toEqual([]);
    expect(decoder.pending).toBe(20);
    decoder.abandon();
    expect(frames(decoder.push(golden[1]!))).toHaveLength(1);
  });
});
