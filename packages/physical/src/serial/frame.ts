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

/**
 * Checks the header at `bytes[at]` (whose sync is already found). Returns the payload length, an
 * error, or undefined when more bytes are needed. (Shared with the streaming decoder.)
 */
export function checkHeader(
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
 * after the frame are an error too (`bad_length`). The payload is a view of `bytes`, not a copy:
 * it changes if `bytes` does, so copy it (`payload.slice()`) to keep it past a reuse of `bytes`.
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
      payload: bytes.subarray(HEADER_BYTES, HEADER_BYTES + len),
    },
  };
}
