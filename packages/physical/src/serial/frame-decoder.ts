import {
  checkHeader,
  crc16,
  CRC_BYTES,
  FRAME_DATA,
  HEADER_BYTES,
  SYNC_0,
  SYNC_1,
} from './frame.js';
import type { FrameError, FrameType } from './frame.js';

/**
 * What a {@link FrameDecoder} found, in stream order: the frames, and why bytes were dropped.
 * The decoder calls these as methods of the object you give it, during `push()` or `abandon()`;
 * a handler must not push into the same decoder.
 */
export interface FrameHandlers {
  /**
   * A frame whose header and CRC check out. `payload` is a view, never a fresh copy: of the chunk
   * you pushed when the frame lay whole in it, else of the decoder's own memory, which it writes
   * once and never again. So a payload stays correct after later pushes as long as you do not
   * change the chunks you pushed (`serialport`'s chunks are never written again). Copy it
   * (`payload.slice()`) if you reuse a chunk's memory, or to keep a payload long without keeping
   * the whole buffer it lies in alive.
   */
  onFrame(type: FrameType, seq: number, payload: Uint8Array): void;
  /**
   * A sync whose header or CRC did not check out (`incomplete`: a partial frame given up by
   * `abandon()`): `dropped` bytes (1) are skipped and the hunt for the next sync goes on.
   */
  onError?(error: FrameError, dropped: number): void;
  /** `dropped` bytes that were not the start of a frame. */
  onGarbage?(dropped: number): void;
  /** A header announced a payload of `length` bytes, above the maximum (its `oversize` error follows). */
  onOversize?(length: number): void;
}

/**
 * A chunk this short that follows a partial frame is appended whole and parsed in the held memory:
 * copying 64 bytes costs less than parsing the chunk in two places.
 */
const SHORT_CHUNK_BYTES = 64;

/**
 * The decoder's held memory is carved from blocks of this size, written once each, as
 * `serialport` carves its reads from a 64 KB pool: the payload views it hands out are never
 * overwritten, and a frame cut by a read costs no allocation of its own. (With 8 KB blocks, 64-byte
 * reads ran about 5 % slower: a block is zeroed and collected, which costs by the byte and by the
 * block.) A kept payload keeps its block alive.
 */
const BLOCK_BYTES = 65536;

/** The held memory of a decoder that has held nothing yet (its first block comes when needed). */
const NO_BLOCK = new Uint8Array(0);

/**
 * The receiving half of the serial link: push bytes as they arrive and it calls your
 * {@link FrameHandlers} with the frames and the errors it finds: no result array and no event
 * object per frame, and each payload is a view (no memory of its own).
 * After garbage, a bad header or a bad CRC it drops one byte and hunts for the next sync, so the
 * link resynchronises by itself. `abandon()` drops a partial frame (call it when no byte has
 * arrived for 200 ms).
 *
 * It parses each chunk where it lies. Only a frame cut by the end of a chunk is copied, into the
 * held memory: the next chunk tops it up with just the bytes that frame still lacks (first its
 * header, then the length the header gives) and the rest of that chunk is again parsed in place.
 * So each byte is copied at most once, and only if its frame straddles two reads (a chunk of at
 * most {@link SHORT_CHUNK_BYTES} after a partial frame is appended whole: that is cheaper). The
 * held memory is append-only (new bytes go after the old, into a fresh block when one is full),
 * so a frame assembled there can be handed out as a view too.
 */
export class FrameDecoder {
  readonly #handlers: FrameHandlers;
  readonly #blockBytes: number;
  #held = NO_BLOCK;
  #start = 0;
  #end = 0;

  /**
   * @param handlers told what the decoder finds.
   * @param blockBytes the size of each block of held memory (default 64 KB; smaller blocks keep
   *   less memory alive per kept payload and cost more time).
   */
  constructor(handlers: FrameHandlers, blockBytes: number = BLOCK_BYTES) {
    if (!Number.isInteger(blockBytes) || blockBytes <= 0) {
      throw new RangeError(`"blockBytes" must be a positive integer, got ${blockBytes}`);
    }
    this.#handlers = handlers;
    this.#blockBytes = blockBytes;
  }

  /** Bytes held while waiting for the rest of a frame. */
  get pending(): number {
    return this.#end - this.#start;
  }

  /** Decodes `chunk`, calling the handlers for what it finds (with what was held before it). */
  push(chunk: Uint8Array): void {
    let from = 0;
    if (this.#start !== this.#end) {
      if (chunk.length <= SHORT_CHUNK_BYTES) {
        this.#append(chunk, 0, chunk.length);
        this.#start = scan(this.#held, this.#start, this.#end, this.#handlers);
        return;
      }
      from = this.#topUp(chunk);
    }
    if (this.#start === this.#end) {
      const used = scan(chunk, from, chunk.length, this.#handlers);
      this.#append(chunk, used, chunk.length);
    }
  }

  /** Drops a partial frame (no byte for 200 ms), resuming the hunt one byte later. */
  abandon(): void {
    if (this.#start === this.#end) return;
    this.#handlers.onError?.('incomplete', 1);
    this.#start = scan(this.#held, this.#start + 1, this.#end, this.#handlers);
  }

  /**
   * Completes the held partial frame from the front of `chunk`, copying only the bytes it needs;
   * returns how many bytes of `chunk` it used. The held bytes are empty afterwards unless the
   * chunk ran out first.
   */
  #topUp(chunk: Uint8Array): number {
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
      this.#start = scan(this.#held, this.#start, this.#end, this.#handlers);
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
    if (this.#held.length - this.#end < count) this.#newBlock(count);
    this.#held.set(from === 0 && to === bytes.length ? bytes : bytes.subarray(from, to), this.#end);
    this.#end += count;
  }

  /**
   * Moves the held bytes into a fresh block with room for `count` more. The old block is left as
   * it is: payload views handed out from it stay correct, and it is freed once none is kept.
   */
  #newBlock(count: number): void {
    const pending = this.#end - this.#start;
    const block = new Uint8Array(Math.max(this.#blockBytes, pending + count));
    block.set(this.#held.subarray(this.#start, this.#end), 0);
    this.#held = block;
    this.#start = 0;
    this.#end = pending;
  }
}

/**
 * Finds the frames in `bytes[from, to)`, telling `handlers` what it found; returns where the
 * bytes it could not finish with (a partial frame, or a trailing 0xA5) begin.
 */
function scan(bytes: Uint8Array, from: number, to: number, handlers: FrameHandlers): number {
  let at = from;
  let garbage = 0;
  while (at < to) {
    // frames mostly follow one another: look at the next byte before searching
    const sync = bytes[at] === SYNC_0 ? at : bytes.indexOf(SYNC_0, at);
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
      garbage = flushGarbage(handlers, garbage);
      if (len === 'oversize')
        handlers.onOversize?.((bytes[at + 5] ?? 0) | ((bytes[at + 6] ?? 0) << 8));
      handlers.onError?.(len, 1);
      at += 1;
      continue;
    }
    const total = HEADER_BYTES + len + CRC_BYTES;
    if (to - at < total) break;
    garbage = flushGarbage(handlers, garbage);
    const crcAt = at + total - CRC_BYTES;
    const crc = ((bytes[crcAt] ?? 0) << 8) | (bytes[crcAt + 1] ?? 0);
    if (crc16(bytes.subarray(at, crcAt)) !== crc) {
      handlers.onError?.('bad_crc', 1);
      at += 1;
      continue;
    }
    handlers.onFrame(
      bytes[at + 2] === FRAME_DATA ? 'data' : 'ack',
      (bytes[at + 3] ?? 0) | ((bytes[at + 4] ?? 0) << 8),
      bytes.subarray(at + HEADER_BYTES, crcAt),
    );
    at += total;
  }
  flushGarbage(handlers, garbage);
  return at;
}

/** Reports `garbage` dropped bytes, if any; returns the new count (0). */
function flushGarbage(handlers: FrameHandlers, garbage: number): number {
  if (garbage > 0) handlers.onGarbage?.(garbage);
  return 0;
}
