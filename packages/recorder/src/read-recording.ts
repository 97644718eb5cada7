import { McapIndexedReader } from '@mcap/core';
import type { McapTypes } from '@mcap/core';
import { DECOMPRESS_HANDLERS, zstdReady } from './compression.js';
import { checkMcapStart } from './mcap-start.js';
import { recoverRecords } from './recover-records.js';
import type { KnownChannels, RecordingGap } from './recover-records.js';
import { RecordingBuilder } from './recording-builder.js';
import type { RecordedChannel, RecordedMessage } from './recording-builder.js';
import { RecordingReadError } from './recording-read-error.js';

/** A recording read back. */
export interface Recording {
  /**
   * True when every record of the file was read, to its footer (through its summary and index
   * when they read); false when it was cut short (a killed process) or damaged, and `gaps` says
   * where.
   */
  complete: boolean;
  /**
   * For a file not read whole: where and why reading stopped, and what was read, in one sentence
   * (`cut short at byte 5120 of 5200 (...); 58 records read`).
   */
  truncation?: string;
  /** The parts of the file that could not be read, in order (empty for a complete file). */
  gaps: RecordingGap[];
  /** The file's size in bytes. */
  fileBytes: number;
  /** Each topic with its schema's name and the JSON Schema it declares. */
  channels: Map<string, RecordedChannel>;
  /** The messages in log-time order. */
  messages: RecordedMessage[];
  /** Metadata records by name. */
  metadata: Map<string, Record<string, string>>;
  /** The summary's chunk indexes, for a complete file. */
  chunkCount: number;
}

/** How {@link readRecording} names the file in what it says (default `the file`). */
export interface ReadRecordingOptions {
  name?: string;
}

function bytesReadable(bytes: Uint8Array): McapTypes.IReadable {
  return {
    size: () => Promise.resolve(BigInt(bytes.byteLength)),
    read: (offset, length) =>
      Promise.resolve(bytes.subarray(Number(offset), Number(offset + length))),
  };
}

async function readIndexed(reader: McapIndexedReader, fileBytes: number): Promise<Recording> {
  const out = new RecordingBuilder();
  for (const schema of reader.schemasById.values()) out.schema(schema);
  for (const channel of reader.channelsById.values()) out.channel(channel);
  for await (const message of reader.readMessages()) out.message(message);
  for await (const metadata of reader.readMetadata()) out.meta(metadata);
  return {
    complete: true,
    gaps: [],
    fileBytes,
    channels: out.channels,
    messages: out.messages,
    metadata: out.metadata,
    chunkCount: reader.chunkIndexes.length,
  };
}

/** One sentence of the gaps and of what was read around them. */
function gapsText(gaps: RecordingGap[], fileBytes: number, records: number): string {
  const parts = gaps.map((gap) =>
    gap.kind === 'cut-short'
      ? gap.offset === fileBytes
        ? `cut short after its last complete record, at byte ${gap.offset} (${gap.reason})`
        : `cut short at byte ${gap.offset} of ${fileBytes} (${gap.reason})`
      : `damaged at byte ${gap.offset} of ${fileBytes} (${gap.reason})${
          gap.resumedAt === undefined ? '' : `, read on from byte ${gap.resumedAt}`
        }`,
  );
  return `${parts.join('; ')}; ${records} records read`;
}

/** The file's summary, when its footer and summary still read (a file damaged in its data). */
async function summaryOf(bytes: Uint8Array): Promise<McapIndexedReader | undefined> {
  try {
    return await McapIndexedReader.Initialize({
      readable: bytesReadable(bytes),
      decompressHandlers: DECOMPRESS_HANDLERS,
    });
  } catch {
    return undefined;
  }
}

/**
 * Reads a recording: through its summary and index when it ended properly, else with MCAP's
 * recovery (record by record), as a killed process leaves it: up to its last complete record,
 * and past a damaged chunk to the next one that reads whole. What could not be read is in
 * `gaps` and `truncation`, never passed over as an empty recording.
 *
 * @throws {RecordingReadError} for a file that is not a recording: empty (`EMPTY`), not MCAP
 *   (`NOT_MCAP`), with no header (`NO_HEADER`), or damaged with not one message readable
 *   (`DAMAGED`).
 */
export async function readRecording(
  bytes: Uint8Array,
  options: ReadRecordingOptions = {},
): Promise<Recording> {
  const name = options.name ?? 'the file';
  checkMcapStart(bytes, name);
  await zstdReady();
  const indexed = await summaryOf(bytes);
  if (indexed !== undefined) {
    try {
      return await readIndexed(indexed, bytes.byteLength);
    } catch {
      // a chunk the index points to is damaged: read record by record, past it
    }
  }
  const known: KnownChannels | undefined =
    indexed === undefined
      ? undefined
      : { schemas: indexed.schemasById.values(), channels: indexed.channelsById.values() };
  const out = new RecordingBuilder();
  const read = recoverRecords(bytes, out, name, known);
  const damaged = read.gaps.find((gap) => gap.kind === 'damaged');
  if (damaged !== undefined && out.messages.length === 0) {
    throw new RecordingReadError(
      'DAMAGED',
      `${name} is damaged: not one message could be read (${gapsText(read.gaps, bytes.byteLength, read.records)})`,
      { offset: damaged.offset },
    );
  }
  return {
    complete: read.complete,
    ...(read.complete ? {} : { truncation: gapsText(read.gaps, bytes.byteLength, read.records) }),
    gaps: read.gaps,
    fileBytes: bytes.byteLength,
    channels: out.channels,
    messages: out.sortedMessages(),
    metadata: out.metadata,
    chunkCount: 0,
  };
}

/**
 * Reads the recording in the file at `path` (named by its path in what it says).
 *
 * @throws {RecordingReadError} as {@link readRecording}; the file system's error (`ENOENT`...)
 *   for a file that cannot be read.
 */
export async function readRecordingFile(path: string): Promise<Recording> {
  const { readFile } = await import('node:fs/promises');
  return readRecording(new Uint8Array(await readFile(path)), { name: path });
}
