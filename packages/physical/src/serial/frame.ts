// the Buffer-free calculator: works on Uint8Array, in Node and in a browser alike
import crc16ccitt from 'crc/calculators/crc16ccitt';

/*
 * Serial framing of protocol 1.0, section 7:
 *   A5 5A | type (1) | seq (u16 LE) | len (u16 LE) | len ^ 0xFFFF (u16 LE) | payload | CRC (u16 BE)
 * The CRC is CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF, no reflection, xorout 0) over every
 * byte from the sync through the payload, so the header is protected too.
 */

export const SYNC_0 = 0xa5;
export const SYNC_1 = 0x5a;
export const FRAME_DATA = 0x01;
export const FRAME_ACK = 0x02;
export const HEADER_BYTES = 9;
export const CRC_BYTES = 2;
export const MAX_PAYLOAD_BYTES = 1024;

/** A frame's type. */
export type FrameType = 'data' | 'ack';

/** A decoded frame. */
export interface Frame {
  type: FrameType;
  /** Link sequence number, 0..65535. */
  seq: number;
  payload: Uint8Array;
}

/** Why bytes were not a frame (the names of tests/vectors/serial-frames.json). */
export type FrameError =
  'bad_sync' | 'bad_crc' | 'bad_length' | 'oversize' | 'bad_type' | 'incomplete';

/** CRC-16/CCITT-FALSE of `bytes`. */
export function crc16(bytes: Uint8Array): number {
  return crc16ccitt(bytes);
}

/** Encodes one frame. */
export function encodeFrame(frame: Frame): Uint8Array {
  const { payload } = frame;
  if (frame.type === 'ack' && payload.length !== 0)
    throw new RangeError('an ACK carries no payload');
  if (payload.length > MAX_PAYLOAD_BYTES) {
    throw new RangeError(`a frame payload is at most ${MAX_PAYLOAD_BYTES} bytes`);
  }
  if (!Number.isInteger(frame.seq) || frame.seq < 0 || frame.seq > 0xffff) {
    throw new RangeError('a link seq is 0..65535');
  }
  const bytes = new Uint8Array(HEADER_BYTES + payload.length + CRC_BYTES);
  const view = new DataView(bytes.buffer);
  bytes[0] = SYNC_0;
  bytes[1] = SYNC_1;
  bytes[2] = frame.type === 'data' ? FRAME_DATA : FRAME_ACK;
  view.setUint16(3, frame.seq, true);
  view.setUint16(5, payload.length, true);
  view.setUint16(7, payload.length ^ 0xffff, true);
  bytes.set(payload, HEADER_BYTES);
  view.setUint16(
    HEADER_BYTES + payload.length,
    crc16(bytes.subarray(0, HEADER_BYTES + payload.length)),
    false,
  );
  return bytes;
}

/** What {@link FrameDecoder.push} found, in order. */
export type FrameEvent =
  | { kind: 'frame'; frame: Frame }
  | { kind: 'error'; error: FrameError; dropped: number }
  | { kind: 'garbage'; dropped: number }
  | { kind: 'oversize'; length: number };

/**
 * Checks the header at `bytes[at]` (whose sync is already found). Returns the payload length, an
 * error, or undefined when more bytes are needed.
 */
function checkHeader(
  bytes: Uint8Array,
  at = 0,
  to = bytes.length,
): number | FrameError | undefined {
  if (to - at < HEADER_BYTES) return undefined;
  const type = bytes[at + 2];
  const len = (bytes[at + 5] ?? 0) | ((bytes[at + 6] ?? 0) << 8);
  const inv = (bytes[at + 7] ?? 0) | ((bytes[at + 8] ?? 0) << 8);
  if ((len ^ 0xffff) !== inv) return 'bad_length';
  if (type !== FRAME_DATA && type !== FRAME_ACK) return 'bad_type';
  if (type === FRAME_ACK && len !== 0) return 'bad_length';
  if (len > MAX_PAYLOAD_BYTES) return 'oversize';
  return len;
}

/**
 * Decodes exactly one frame from `bytes` (a whole golden frame); never throws. Trailing bytes
 * after the frame are an error too (`bad_length`).
 */
export function decodeFrame(
  bytes: Uint8Array,
): { ok: true; frame: Frame } | { ok: false; error: FrameError } {
  if (bytes.length < 2 || bytes[0] !== SYNC_0 || bytes[1] !== SYNC_1) {
    return { ok: false, error: bytes.length < 2 ? 'incomplete' : 'bad_sync' };
  }
  const len = checkHeader(bytes);
  if (len === undefined) return { ok: false, error: 'incomplete' };
  if (typeof len === 'string') return { ok: false, error: len };
  const total = HEADER_BYTES + len + CRC_BYTES;
  if (bytes.length < total) return { ok: false, error: 'incomplete' };
  if (bytes.length > total) return { ok: false, error: 'bad_length' };
  const crc = ((bytes[total - 2] ?? 0) << 8) | (bytes[total - 1] ?? 0);
  if (crc16(bytes.subarray(0, total - CRC_BYTES)) !== crc) return { ok: false, error: 'bad_crc' };
  return {
    ok: true,
    frame: {
      type: bytes[2] === FRAME_DATA ? 'data' : 'ack',
      seq: (bytes[3] ?? 0) | ((bytes[4] ?? 0) << 8),
      payload: bytes.slice(HEADER_BYTES, HEADER_BYTES + len),
    },
  };
}

/**
 * The receiving half of the serial link: feed it bytes as they arrive and it returns the frames
 * and the errors it found. After garbage, a bad header or a bad CRC it drops one byte and hunts
 * for the next sync, so the link resynchronises by itself. `abandon()` drops a partial frame
 * (call it when no byte has arrived for 200 ms).
 *
 * It parses each chunk where it lies: only the unfinished tail of a chunk (at most one frame) is
 * copied into a reused buffer, so the cost per byte is that of the one-shot {@link decodeFrame}.
 */
export class FrameDecoder {
  #held = new Uint8Array(256);
  #start = 0;
  #end = 0;

  /** Bytes held while waiting for the rest of a frame. */
  get pending(): number {
    return this.#end - this.#start;
  }

  push(chunk: Uint8Array): FrameEvent[] {
    const events: FrameEvent[] = [];
    if (this.#start === this.#end) {
      const used = scan(chunk, 0, chunk.length, events);
      this.#start = 0;
      this.#end = 0;
      this.#append(chunk.subarray(used));
    } else {
      this.#append(chunk);
      this.#start = scan(this.#held, this.#start, this.#end, events);
    }
    if (this.#start === this.#end) this.#start = this.#end = 0;
    return events;
  }

  /** Drops a partial frame (no byte for 200 ms), resuming the hunt one byte later. */
  abandon(): FrameEvent[] {
    if (this.#start === this.#end) return [];
    const rest = this.#held.slice(this.#start + 1, this.#end);
    this.#start = this.#end = 0;
    return [{ kind: 'error', error: 'incomplete', dropped: 1 }, ...this.push(rest)];
  }

  #append(bytes: Uint8Array): void {
    if (bytes.length === 0) return;
    if (this.#held.length - this.#end < bytes.length) {
      const pending = this.#end - this.#start;
      const target =
        pending + bytes.length <= this.#held.length
          ? this.#held
          : new Uint8Array(Math.max(this.#held.length * 2, pending + bytes.length));
      target.set(this.#held.subarray(this.#start, this.#end), 0);
      this.#held = target;
      this.#start = 0;
      this.#end = pending;
    }
    this.#held.set(bytes, this.#end);
    this.#end += bytes.length;
  }
}

/**
 * Finds the frames in `bytes[from, to)`, appending what it found to `events`; returns where the
 * bytes it could not finish with (a partial frame, or a trailing 0xA5) begin.
 */
function scan(bytes: Uint8Array, from: number, to: number, events: FrameEvent[]): number {
  let at = from;
  let garbage = 0;
  while (at < to) {
    const sync = bytes.indexOf(SYNC_0, at);
    if (sync < 0 || sync >= to) {
      garbage += to - at;
      at = to;
      break;
    }
    if (sync + 1 === to) {
      // keep a trailing 0xA5: it may be the start of the next sync
      garbage += sync - at;
      at = sync;
      break;
    }
    if (bytes[sync + 1] !== SYNC_1) {
      garbage += sync + 1 - at;
      at = sync + 1;
      continue;
    }
    garbage += sync - at;
    at = sync;
    const len = checkHeader(bytes, at, to);
    if (len === undefined) break;
    if (typeof len === 'string') {
      garbage = flushGarbage(events, garbage);
      if (len === 'oversize') {
        events.push({
          kind: 'oversize',
          length: (bytes[at + 5] ?? 0) | ((bytes[at + 6] ?? 0) << 8),
        });
      }
      events.push({ kind: 'error', error: len, dropped: 1 });
      at += 1;
      continue;
    }
    const total = HEADER_BYTES + len + CRC_BYTES;
    if (to - at < total) break;
    garbage = flushGarbage(events, garbage);
    const crcAt = at + total - CRC_BYTES;
    const crc = ((bytes[crcAt] ?? 0) << 8) | (bytes[crcAt + 1] ?? 0);
    if (crc16(bytes.subarray(at, crcAt)) !== crc) {
      events.push({ kind: 'error', error: 'bad_crc', dropped: 1 });
      at += 1;
      continue;
    }
    events.push({
      kind: 'frame',
      frame: {
        type: bytes[at + 2] === FRAME_DATA ? 'data' : 'ack',
        seq: (bytes[at + 3] ?? 0) | ((bytes[at + 4] ?? 0) << 8),
        payload: bytes.slice(at + HEADER_BYTES, crcAt),
      },
    });
    at += total;
  }
  flushGarbage(events, garbage);
  return at;
}

/** Reports `garbage` dropped bytes, if any; returns the new count (0). */
function flushGarbage(events: FrameEvent[], garbage: number): number {
  if (garbage > 0) events.push({ kind: 'garbage', dropped: garbage });
  return 0;
}
