import { fc, it } from '@fast-check/vitest';
import { describe, expect } from 'vitest';
import { decodeFrame, encodeFrame, MAX_PAYLOAD_BYTES } from './frame.js';
import type { Frame } from './frame.js';
import { concat, frameRecorder } from './frame-recorder.fixture.js';

// Property tests of the serial framing: what the decoder delivers is always exactly a frame that
// was sent, however the bytes arrive and whatever lies between the frames.

const frameArb: fc.Arbitrary<Frame> = fc.oneof(
  fc.record({
    type: fc.constant<'data'>('data'),
    seq: fc.integer({ min: 0, max: 0xffff }),
    payload: fc.uint8Array({ maxLength: 64 }),
  }),
  fc.record({
    type: fc.constant<'ack'>('ack'),
    seq: fc.integer({ min: 0, max: 0xffff }),
    payload: fc.constant(new Uint8Array(0)),
  }),
);

const plain = (f: Frame) => ({ type: f.type, seq: f.seq, payload: Array.from(f.payload) });

/** Cuts `bytes` at the given fractions (any order, duplicates allowed). */
function cut(bytes: Uint8Array, points: number[]): Uint8Array[] {
  const at = [...new Set(points.map((p) => Math.floor(p * bytes.length)))].sort((a, b) => a - b);
  const chunks: Uint8Array[] = [];
  let from = 0;
  for (const to of [...at, bytes.length]) {
    chunks.push(bytes.subarray(from, to));
    from = to;
  }
  return chunks;
}

/**
 * Feeds chunks (each its own copy, as a port delivers them), then lets the line go quiet until
 * nothing is held back. The payloads are kept as handed out (views) and read only at the end, so
 * every property below also checks that later pushes leave them intact.
 */
function receive(chunks: Uint8Array[]): Frame[] {
  const { decoder, frames } = frameRecorder();
  for (const chunk of chunks) decoder.push(chunk.slice());
  while (decoder.pending > 0) decoder.abandon();
  return frames();
}

const cutPoints = fc.array(fc.double({ min: 0, max: 1, noNaN: true }), { maxLength: 12 });

describe('encodeFrame and decodeFrame', () => {
  it.prop([frameArb], { numRuns: 200 })('decode(encode(frame)) is the frame', (frame) => {
    const result = decodeFrame(encodeFrame(frame));
    expect(result.ok).toBe(true);
    if (result.ok) expect(plain(result.frame)).toEqual(plain(frame));
  });

  it.prop([fc.uint8Array({ maxLength: MAX_PAYLOAD_BYTES + 20 })], { numRuns: 300 })(
    'decodeFrame never throws, and only returns a frame that encodes back to its input',
    (bytes) => {
      const result = decodeFrame(bytes);
      if (result.ok) expect(Array.from(encodeFrame(result.frame))).toEqual(Array.from(bytes));
    },
  );
});

describe('FrameDecoder', () => {
  it.prop([fc.array(frameArb, { maxLength: 6 }), cutPoints], { numRuns: 150 })(
    'finds every frame in order, however the stream is cut into reads',
    (frames, points) => {
      const stream = concat(...frames.map(encodeFrame));
      expect(receive(cut(stream, points)).map(plain)).toEqual(frames.map(plain));
    },
  );

  it.prop(
    [
      fc.array(fc.tuple(fc.uint8Array({ maxLength: 24 }), frameArb), { maxLength: 5 }),
      fc.uint8Array({ maxLength: 24 }),
      cutPoints,
    ],
    { numRuns: 150 },
  )(
    'resynchronises after garbage between frames and delivers each frame once',
    (pairs, tail, points) => {
      // random garbage could hold a valid frame only by a 2^-48 chance (sync, length check, CRC)
      const stream = concat(...pairs.flatMap(([junk, f]) => [junk, encodeFrame(f)]), tail);
      const frames = pairs.map(([, f]) => plain(f));
      expect(receive(cut(stream, points)).map(plain)).toEqual(frames);
    },
  );

  it.prop(
    [frameArb, fc.uniqueArray(fc.nat(), { minLength: 1, maxLength: 3 }), frameArb, cutPoints],
    { numRuns: 200 },
  )(
    'a frame with one to three flipped bits is never delivered, and the next frame still is',
    (frame, flips, next, points) => {
      const corrupted = encodeFrame(frame).slice();
      const bits = corrupted.length * 8;
      const positions = [...new Set(flips.map((f) => f % bits))];
      for (const bit of positions)
        corrupted[bit >> 3] = (corrupted[bit >> 3] ?? 0) ^ (1 << (bit & 7));
      const received = receive(cut(concat(corrupted, encodeFrame(next)), points));
      // CRC-16/CCITT-FALSE has Hamming distance 4 at these lengths: 1..3 bit errors are detected
      expect(received.map(plain)).toEqual([plain(next)]);
    },
  );

  it.prop(
    [
      fc.array(fc.oneof(frameArb.map(encodeFrame), fc.uint8Array({ maxLength: 90 })), {
        maxLength: 6,
      }),
      cutPoints,
    ],
    { numRuns: 200 },
  )(
    'yields exactly what decodeFrame yields for each of the same pieces, under any chunking',
    (pieces, points) => {
      // each piece is a whole encoded frame or random bytes; one-shot decoding of the pieces one
      // by one is the reference (random bytes pass its length check and CRC only by a 2^-32 chance)
      const expected = pieces.flatMap((bytes) => {
        const result = decodeFrame(bytes);
        return result.ok ? [plain(result.frame)] : [];
      });
      expect(receive(cut(concat(...pieces), points)).map(plain)).toEqual(expected);
    },
  );

  it.prop([fc.array(frameArb, { maxLength: 8 }), fc.integer({ min: 1, max: 200 })], {
    numRuns: 100,
  })(
    'decodes the same frames from reads of any fixed size, holding nothing back at the end',
    (frames, size) => {
      const stream = concat(...frames.map(encodeFrame));
      const { decoder, frames: received } = frameRecorder();
      for (let at = 0; at < stream.length; at += size) {
        decoder.push(stream.subarray(at, at + size));
      }
      expect(decoder.pending).toBe(0);
      expect(received().map(plain)).toEqual(frames.map(plain));
    },
  );

  it.prop(
    [
      fc.array(
        fc.record({
          seq: fc.integer({ min: 0, max: 0xffff }),
          payload: fc.uint8Array({ maxLength: MAX_PAYLOAD_BYTES }),
        }),
        { minLength: 1, maxLength: 24 },
      ),
      fc.integer({ min: 1, max: 300 }),
      fc.integer({ min: 1, max: 4096 }),
    ],
    { numRuns: 60 },
  )(
    'hands out payloads that stay correct through every later push, up to the largest frames',
    (sent, size, blockBytes) => {
      // up to 24 kB of frames through blocks of held memory as small as one byte: the blocks
      // fill and are replaced many times while the payloads handed out earlier are kept as views
      const frames = sent.map((f): Frame => ({ type: 'data', ...f }));
      const stream = concat(...frames.map(encodeFrame));
      const { decoder, frames: received } = frameRecorder({ blockBytes });
      for (let at = 0; at < stream.length; at += size) {
        decoder.push(stream.subarray(at, at + size));
      }
      expect(received().map(plain)).toEqual(frames.map(plain));
    },
  );
});
