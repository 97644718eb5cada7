import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { crc16, decodeFrame, encodeFrame } from './frame.js';
import { frameRecorder } from './frame-recorder.fixture.js';

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
        const { decoder, frames } = frameRecorder();
        decoder.push(bad);
        if (!result.ok && frames().length === 0) rejected += 1;
      }
      expect(rejected).toBe(good.length * 8);
    });
  }

  it('hands out the payload as a view of the bytes it was given, not a copy', () => {
    const frame = bytes(valid[0]!.hex);
    const result = decodeFrame(frame);
    if (!result.ok) throw new Error(`golden frame refused: ${result.error}`);
    expect(result.frame.payload.buffer).toBe(frame.buffer);
    expect(result.frame.payload.byteOffset).toBe(frame.byteOffset + 9);
  });

  for (const vector of invalid) {
    it(`rejects ${vector.name} as ${vector.error}`, () => {
      const result = decodeFrame(bytes(vector.hex));
      expect(result).toEqual({ ok: false, error: vector.error });
    });
  }
});
