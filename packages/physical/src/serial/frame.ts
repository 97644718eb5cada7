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
 * A chunk this short that follows a partial frame is appended whole and parsed in the held buffer:
 * copying 64 bytes costs less than parsing the chunk in two places.
 */
const SHORT_CHUNK_BYTES = 64;

/**
 * The receiving half of the serial link: feed it bytes as they arrive and it returns the frames
 * and the errors it found. After garbage, a bad header or a bad CRC it drops one byte and hunts
 * for the next sync, so the link resynchronises by itself. `abandon()` drops a partial frame
 * (call it when no byte has arrived for 200 ms).
 *
 * It parses each chunk where it lies. Only a frame cut by the end of a chunk is copied, into a
 * reused buffer: the next chunk tops it up with just the bytes that frame still lacks (first its
 * header, then the length the header gives) and the rest of that chunk is again parsed in place.
 * So each byte is copied at most once, and only if its frame straddles two reads (a chunk of at
 * most {@link SHORT_CHUNK_BYTES} after a partial frame is appended whole: that is cheaper).
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
    let from = 0;
    if (this.#start !== this.#end) {
      if (chunk.length <= SHORT_CHUNK_BYTES) return this.#pushShort(chunk, events);
      from = this.#topUp(chunk, events);
    }
    if (this.#start === this.#end) {
      const used = scan(chunk, from, chunk.length, events);
      this.#start = this.#end = 0;
      this.#append(chunk, used, chunk.length);
    }
    return events;
  }

  /** Appends a short chunk whole to the held partial frame and parses them together. */
  #pushShort(chunk: Uint8Array, events: FrameEvent[]): FrameEvent[] {
    if (this.#held.length - this.#end < chunk.length) this.#make(chunk.length);
    this.#held.set(chunk, this.#end);
    this.#end += chunk.length;
    this.#start = scan(this.#held, this.#start, this.#end, events);
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

  /**
   * Completes the held partial frame from the front of `chunk`, copying only the bytes it needs;
   * returns how many bytes of `chunk` it used. The held bytes are empty afterwards unless the
   * chunk ran out first.
   */
  #topUp(chunk: Uint8Array, events: FrameEvent[]): number {
    let from = 0;
    while (this.#start !== this.#end && from < chunk.length) {
      const need = this.#needed();
      if (need > 0) {
        const take = Math.min(need - (this.#end - this.#start), chunk.length - from);
        this.#append(chunk, from, from + take);
        from += take;
        if (this.#end - this.#start < need) break; // the chunk ran out
        if (need === HEADER_BYTES) continue; // the header is complete: now its length decides
      }
      this.#start = scan(this.#held, this.#start, this.#end, events);
      if (this.#start === this.#end) this.#start = this.#end = 0;
    }
    return from;
  }

  /**
   * How many bytes the held partial frame must reach before it can be decoded, or 0 when the held
   * bytes can already be decided (a broken sync or header: scan() drops a byte and hunts on).
   */
  #needed(): number {
    const pending = this.#end - this.#start;
    if (pending >= 2 && this.#held[this.#start + 1] !== SYNC_1) return 0;
    if (pending < HEADER_BYTES) return HEADER_BYTES;
    const len = checkHeader(this.#held, this.#start, this.#end);
    if (typeof len !== 'number') return 0;
    const total = HEADER_BYTES + len + CRC_BYTES;
    return pending < total ? total : 0;
  }

  /** Appends `bytes[from, to)` to the held bytes. */
  #append(bytes: Uint8Array, from: number, to: number): void {
    const count = to - from;
    if (count <= 0) return;
    if (this.#held.length - this.#end < count) this.#make(count);
    this.#held.set(bytes.subarray(from, to), this.#end);
    this.#end += count;
  }

  /** Makes room for `count` more held bytes: moves them to the front, or into a larger buffer. */
  #make(count: number): void {
    const pending = this.#end - this.#start;
    const target =
      pending + count <= this.#held.length
        ? this.#held
        : new Uint8Array(Math.max(this.#held.length * 2, pending + count));
    target.set(this.#held.subarray(this.#start, this.#end), 0);
    this.#held = target;
    this.#start = 0;
    this.#end = pending;
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
