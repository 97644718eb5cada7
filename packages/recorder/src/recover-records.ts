import { MCAP_MAGIC, McapRecordBuilder, McapStreamReader } from '@mcap/core';
import type { McapTypes } from '@mcap/core';
import { errorMessage } from '@hal/types';
import { DECOMPRESS_HANDLERS } from './compression.js';
import type { RecordingBuilder } from './recording-builder.js';
import { RecordingReadError } from './recording-read-error.js';

/*
 * MCAP's recovery, record by record, for a file that cannot be read through its summary: a file
 * cut short (a killed process) is read up to its last complete record; a damaged one (bytes
 * overwritten) up to the damage, and then on from the next chunk that reads whole (its CRC
 * checked), so one bad chunk does not cost the rest of the file.
 */

/** A part of a file that could not be read. */
export interface RecordingGap {
  /** `cut-short`: the file ends inside a record; `damaged`: a record there does not parse. */
  kind: 'cut-short' | 'damaged';
  /** Where the record that could not be read starts (bytes from the file's start). */
  offset: number;
  /** For damage: where reading went on (the next chunk that reads whole), if there is one. */
  resumedAt?: number;
  /** Why: the reader's error, or where the file ends. */
  reason: string;
}

/** What a recovery read. */
export interface RecoveredRecords {
  /** The file's records were all read, to its footer and closing magic. */
  complete: boolean;
  /** What could not be read, in the file's order (none for a complete file). */
  gaps: RecordingGap[];
  /** The records read (header, metadata, schemas, channels, messages, indexes, ...). */
  records: number;
}

/** Schemas and channels known from elsewhere (the file's summary), for chunks read after damage. */
export interface KnownChannels {
  schemas: Iterable<McapTypes.Schema>;
  channels: Iterable<McapTypes.Channel>;
}

const CHUNK_OPCODE = 0x06;
/** A chunk's fixed fields: start and end time, uncompressed size, CRC, compression length. */
const CHUNK_FIXED_BYTES = 8 + 8 + 8 + 4 + 4;

/** One reader over part of the file, after the schema and channel records it must know. */
class Segment {
  readonly reader: McapStreamReader;
  readonly #start: number;
  readonly #preludeBytes: number;
  readonly #appended: number;

  constructor(bytes: Uint8Array, start: number, prelude: Uint8Array | undefined) {
    this.reader = new McapStreamReader({
      decompressHandlers: DECOMPRESS_HANDLERS,
      includeChunks: true,
      noMagicPrefix: start !== 0,
    });
    this.#start = start;
    this.#preludeBytes = prelude?.byteLength ?? 0;
    if (prelude !== undefined) this.reader.append(prelude);
    const part = bytes.subarray(start);
    this.reader.append(part);
    this.#appended = this.#preludeBytes + part.byteLength;
  }

  /** Where the reader is in the file; before `start` while it reads the prelude. */
  position(): number {
    return this.#start + this.#appended - this.reader.bytesRemaining() - this.#preludeBytes;
  }

  /** Whether the reader is still inside the prelude (records given again, not the file's here). */
  inPrelude(): boolean {
    return this.#appended - this.reader.bytesRemaining() < this.#preludeBytes;
  }
}

/** The schema and channel records known so far, as bytes a reader takes before a chunk. */
function preludeOf(out: RecordingBuilder, known: KnownChannels | undefined): Uint8Array {
  const schemas = new Map<number, McapTypes.Schema>();
  const channels = new Map<number, McapTypes.Channel>();
  for (const s of known?.schemas ?? []) schemas.set(s.id, s);
  for (const c of known?.channels ?? []) channels.set(c.id, c);
  for (const s of out.schemas.values()) schemas.set(s.id, s);
  for (const c of out.channelsById.values()) channels.set(c.id, c);
  const builder = new McapRecordBuilder();
  for (const s of schemas.values()) builder.writeSchema(s);
  for (const c of channels.values()) builder.writeChannel(c);
  return builder.buffer.slice();
}

/** The end of a plausible chunk record at `at` (its fields fit together and in the file). */
function plausibleChunkEnd(bytes: Uint8Array, at: number): number | undefined {
  if (bytes[at] !== CHUNK_OPCODE || at + 9 + CHUNK_FIXED_BYTES > bytes.byteLength) return undefined;
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const length = view.getBigUint64(at + 1, true);
  if (length > BigInt(bytes.byteLength - at - 9)) return undefined;
  const compressionLength = view.getUint32(at + 9 + CHUNK_FIXED_BYTES - 4, true);
  if (compressionLength > 16) return undefined;
  const recordsAt = at + 9 + CHUNK_FIXED_BYTES + compressionLength;
  if (recordsAt + 8 > bytes.byteLength) return undefined;
  const records = view.getBigUint64(recordsAt, true);
  if (BigInt(CHUNK_FIXED_BYTES + compressionLength + 8) + records !== length) return undefined;
  return at + 9 + Number(length);
}

/** Whether the chunk at `at` (ending at `end`) reads whole: decompressed, CRC checked, parsed. */
function chunkReads(bytes: Uint8Array, at: number, end: number, prelude: Uint8Array): boolean {
  const segment = new Segment(bytes.subarray(0, end), at, prelude);
  try {
    let sawChunk = false;
    for (let r = segment.reader.nextRecord(); r !== undefined; r = segment.reader.nextRecord()) {
      if (!segment.inPrelude() && r.type === 'Chunk') sawChunk = true;
    }
    return sawChunk && segment.reader.bytesRemaining() === 0;
  } catch {
    return false;
  }
}

/** The next chunk after `from` that reads whole, where reading can go on past damage. */
function nextReadableChunk(bytes: Uint8Array, from: number, prelude: Uint8Array) {
  for (let at = bytes.indexOf(CHUNK_OPCODE, from); at >= 0;) {
    const end = plausibleChunkEnd(bytes, at);
    if (end !== undefined && chunkReads(bytes, at, end, prelude)) return at;
    at = bytes.indexOf(CHUNK_OPCODE, at + 1);
  }
  return undefined;
}

function endsWithMagic(bytes: Uint8Array): boolean {
  const tail = bytes.subarray(bytes.byteLength - MCAP_MAGIC.length);
  return bytes.byteLength >= 2 * MCAP_MAGIC.length && MCAP_MAGIC.every((b, i) => tail[i] === b);
}

type SegmentEnd =
  | { end: 'done' }
  | { end: 'stalled'; offset: number }
  | { end: 'error'; offset: number; reason: string };

/**
 * Reads `bytes` (a file that starts with MCAP's magic) record by record into `out`, past damage
 * where a later chunk reads whole. Throws {@link RecordingReadError} `NO_HEADER` when the file
 * has no complete, readable header record.
 */
export function recoverRecords(
  bytes: Uint8Array,
  out: RecordingBuilder,
  name: string,
  known?: KnownChannels,
): RecoveredRecords {
  const gaps: RecordingGap[] = [];
  let records = 0;
  let sawHeader = false;

  const readSegment = (segment: Segment): SegmentEnd => {
    let chunkAt: number | undefined;
    let chunkEnd = -1;
    for (;;) {
      const before = segment.position();
      let record: McapTypes.TypedMcapRecord | undefined;
      try {
        record = segment.reader.nextRecord();
        if (record === undefined) {
          return segment.reader.done()
            ? { end: 'done' }
            : { end: 'stalled', offset: segment.position() };
        }
        if (segment.inPrelude()) {
          // a schema or channel known from before: the builder learns it too, if it had not
          out.add(record);
          continue;
        }
        if (!sawHeader && record.type !== 'Header') {
          throw new Error(`the first record is a ${record.type}, not a Header`);
        }
        if (record.type === 'Header') sawHeader = true;
        if (record.type === 'Chunk') {
          chunkAt = before;
          chunkEnd = segment.position();
        }
        out.add(record);
        records += 1;
      } catch (error) {
        // a chunk's own records come once it is read whole: an error then is the chunk's,
        // unless the chunk reads whole and the error is in the record after it
        const inChunk =
          chunkAt !== undefined &&
          before === chunkEnd &&
          !chunkReads(bytes, chunkAt, chunkEnd, preludeOf(out, known));
        return {
          end: 'error',
          offset: inChunk && chunkAt !== undefined ? chunkAt : before,
          reason: errorMessage(error),
        };
      }
    }
  };

  let segment = new Segment(bytes, 0, undefined);
  for (;;) {
    const result = readSegment(segment);
    if (!sawHeader) {
      const why =
        result.end === 'error'
          ? `its first record (at byte ${MCAP_MAGIC.length}) is not a readable header: ${result.reason}`
          : `it ends after ${bytes.byteLength} bytes, before its header record is complete`;
      throw new RecordingReadError('NO_HEADER', `${name} holds no recording: ${why}`, {
        offset: MCAP_MAGIC.length,
      });
    }
    if (result.end === 'done') break;
    const prelude = preludeOf(out, known);
    const next = nextReadableChunk(bytes, result.offset + 1, prelude);
    if (result.end === 'stalled' && next === undefined && !endsWithMagic(bytes)) {
      gaps.push({
        kind: 'cut-short',
        offset: result.offset,
        reason:
          result.offset === bytes.byteLength
            ? 'no summary after it: its writer never finished the file'
            : `the file ends at byte ${bytes.byteLength}, inside the record that starts at byte ${result.offset}`,
      });
      break;
    }
    const reason =
      result.end === 'error'
        ? result.reason
        : `the record at byte ${result.offset} runs past the end of the file (${bytes.byteLength} bytes)`;
    gaps.push({
      kind: 'damaged',
      offset: result.offset,
      ...(next === undefined ? {} : { resumedAt: next }),
      reason,
    });
    if (next === undefined) break;
    segment = new Segment(bytes, next, prelude);
  }
  return { complete: gaps.length === 0, gaps, records };
}
