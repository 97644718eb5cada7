import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { encodeFrame, MAX_PAYLOAD_BYTES } from './frame.js';
import type { Frame } from './frame.js';
import { FrameDecoder } from './frame-decoder.js';
import { concat, frameRecorder } from './frame-recorder.fixture.js';

interface Vector {
  name: string;
  hex: string;
  decoded?: { type: 'data' | 'ack'; seq: number; payload: string };
}

const valid = (
  JSON.parse(
    readFileSync(new URL('../../../../tests/vectors/serial-frames.json', import.meta.url), 'utf8'),
  ) as Vector[]
).filter((v) => v.decoded !== undefined);
const golden = valid.map((v) => new Uint8Array(Buffer.from(v.hex, 'hex')));

/** A DATA frame whose payload says which it is: `frame N` padded with `N % 251` to `size` bytes. */
function numbered(n: number, size = 60): Frame {
  const payload = new Uint8Array(size).fill(n % 251);
  payload.set(new TextEncoder().encode(`frame ${n}`));
  return { type: 'data', seq: n & 0xffff, payload };
}

describe('FrameDecoder', () => {
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
    const { decoder, frames } = frameRecorder();
    // in uneven pieces, as a serial port delivers them
    for (let at = 0; at < stream.length;) {
      const size = 1 + Math.floor(random() * 64);
      decoder.push(stream.subarray(at, at + size));
      at += size;
    }
    expect(frames().map((f) => f.seq)).toEqual(valid.map((v) => v.decoded!.seq));
  });

  it('resynchronises on the next frame after a corrupted one and accounts for every byte dropped', () => {
    const corrupted = golden[0]!.slice();
    corrupted[12]! ^= 0x10;
    const noise = new Uint8Array([0x00, 0x17, 0xa5, 0x00]);
    const { decoder, events, frames } = frameRecorder();
    decoder.push(concat(noise, corrupted, golden[1]!));
    expect(frames().map((f) => f.seq)).toEqual([valid[1]!.decoded!.seq]);
    const errors = events.filter((e) => e.kind === 'error');
    expect(errors).toEqual([{ kind: 'error', error: 'bad_crc', dropped: 1 }]);
    const dropped = events.reduce(
      (n, e) => n + (e.kind === 'error' || e.kind === 'garbage' ? e.dropped : 0),
      0,
    );
    expect(dropped).toBe(noise.length + corrupted.length);
  });

  it('reports a header announcing more than the maximum payload as oversize, then resynchronises', () => {
    const length = MAX_PAYLOAD_BYTES + 1;
    const header = new Uint8Array([0xa5, 0x5a, 0x01, 0x07, 0x00, 0, 0, 0, 0]);
    new DataView(header.buffer).setUint16(5, length, true);
    new DataView(header.buffer).setUint16(7, length ^ 0xffff, true);
    const { decoder, events, frames } = frameRecorder();
    decoder.push(concat(header, golden[1]!));
    expect(events.slice(0, 2)).toEqual([
      { kind: 'oversize', length },
      { kind: 'error', error: 'oversize', dropped: 1 },
    ]);
    expect(frames().map((f) => f.seq)).toEqual([valid[1]!.decoded!.seq]);
  });

  it('hands out a frame that lies whole in a chunk as a view of that chunk, not a copy', () => {
    const chunk = concat(golden[0]!, golden[1]!.subarray(0, 5));
    const { decoder, frames } = frameRecorder();
    decoder.push(chunk);
    const payload = frames()[0]!.payload;
    expect(payload.buffer).toBe(chunk.buffer);
    expect(payload.byteOffset).toBe(9);
  });

  it('keeps a frame assembled from two reads intact when the caller then reuses its chunk memory', () => {
    const { decoder, frames } = frameRecorder();
    const read = new Uint8Array(golden[1]!.length); // one buffer a port reads into, again and again
    read.set(golden[1]!.subarray(0, 20));
    decoder.push(read.subarray(0, 20));
    read.set(golden[1]!.subarray(20));
    decoder.push(read.subarray(0, golden[1]!.length - 20));
    read.fill(0xa5);
    decoder.push(read.subarray(0, 3));
    const expected = new TextEncoder().encode(valid[1]!.decoded!.payload);
    expect(frames().map((f) => Array.from(f.payload))).toEqual([Array.from(expected)]);
  });

  it('keeps every payload it handed out intact while later reads fill its held memory many times over', () => {
    // 7-byte reads: every frame is assembled in the decoder's held memory (71 bytes a frame,
    // 2,000 frames: over 140 kB through it, two 64 kB blocks and more); nothing is copied by the
    // caller
    const sent = Array.from({ length: 2000 }, (_, n) => numbered(n));
    const stream = concat(...sent.map(encodeFrame));
    const { decoder, frames } = frameRecorder();
    for (let at = 0; at < stream.length; at += 7) decoder.push(stream.subarray(at, at + 7));
    const plain = (f: Frame) => ({ type: f.type, seq: f.seq, payload: Array.from(f.payload) });
    expect(frames().map(plain)).toEqual(sent.map(plain));
  });

  it('refuses a block size that is not a positive integer', () => {
    for (const bad of [0, -1, 1.5, Number.NaN, Number.POSITIVE_INFINITY]) {
      expect(() => new FrameDecoder({ onFrame: () => undefined }, bad)).toThrow(
        /"blockBytes" must be a positive integer/,
      );
    }
  });

  it('holds no more than the unfinished frame between pushes', () => {
    const { decoder } = frameRecorder();
    const stream = concat(...golden);
    const cut = golden[0]!.length + 3;
    decoder.push(stream.subarray(0, cut));
    expect(decoder.pending).toBe(3);
    decoder.push(stream.subarray(cut));
    expect(decoder.pending).toBe(0);
  });

  it('abandons a partial frame, reports it incomplete and finds a frame that starts inside it', () => {
    const { decoder, events, frames } = frameRecorder();
    decoder.push(concat(golden[0]!.subarray(0, 20)));
    expect(frames()).toEqual([]);
    expect(decoder.pending).toBe(20);
    decoder.abandon();
    expect(events[0]).toEqual({ kind: 'error', error: 'incomplete', dropped: 1 });
    expect(decoder.pending).toBe(0);
    decoder.push(golden[1]!);
    expect(frames()).toHaveLength(1);
  });

  it('needs only a frame handler: errors and garbage without handlers are dropped quietly', () => {
    const seqs: number[] = [];
    const decoder = new FrameDecoder({ onFrame: (_type, seq) => seqs.push(seq) });
    const corrupted = golden[0]!.slice();
    corrupted[12]! ^= 0x10;
    decoder.push(
      concat(new Uint8Array([1, 2, 3]), corrupted, golden[1]!, golden[0]!.subarray(0, 9)),
    );
    decoder.abandon();
    expect(seqs).toEqual([valid[1]!.decoded!.seq]);
    expect(decoder.pending).toBe(0);
  });
});
