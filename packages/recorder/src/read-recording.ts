import { McapIndexedReader, McapStreamReader } from '@mcap/core';
import type { McapTypes } from '@mcap/core';
import { DECOMPRESS_HANDLERS, zstdReady } from './compression.js';

/** One message of a recording, its JSON decoded. */
export interface RecordedMessage {
  topic: string;
  schemaName: string;
  logTime: bigint;
  value: unknown;
}

/** A recording read back. */
export interface Recording {
  /**
   * True when the file ended properly (summary and index present, read through them); false when
   * it was cut short (a killed process) and was read record by record up to its last complete one.
   */
  complete: boolean;
  /** Why reading stopped early, for a file that was cut short. */
  truncation?: string;
  /** Each topic with its schema's name and the JSON Schema it declares. */
  channels: Map<string, { schemaName: string; schema: unknown; messageCount: number }>;
  /** The messages in log-time order. */
  messages: RecordedMessage[];
  /** Metadata records by name. */
  metadata: Map<string, Record<string, string>>;
  /** The summary's chunk indexes, for a complete file. */
  chunkCount: number;
}

const decoder = new TextDecoder();

function bytesReadable(bytes: Uint8Array): McapTypes.IReadable {
  return {
    size: () => Promise.resolve(BigInt(bytes.byteLength)),
    read: (offset, length) =>
      Promise.resolve(bytes.subarray(Number(offset), Number(offset + length))),
  };
}

class RecordingBuilder {
  readonly schemas = new Map<number, McapTypes.Schema>();
  readonly channelTopics = new Map<number, McapTypes.Channel>();
  readonly channels: Recording['channels'] = new Map();
  readonly messages: RecordedMessage[] = [];
  readonly metadata = new Map<string, Record<string, string>>();

  schema(record: McapTypes.Schema): void {
    this.schemas.set(record.id, record);
  }

  channel(record: McapTypes.Channel): void {
    this.channelTopics.set(record.id, record);
    const schema = this.schemas.get(record.schemaId);
    if (!this.channels.has(record.topic)) {
      this.channels.set(record.topic, {
        schemaName: schema?.name ?? '',
        schema: schema ? (JSON.parse(decoder.decode(schema.data)) as unknown) : undefined,
        messageCount: 0,
      });
    }
  }

  message(record: McapTypes.Message): void {
    const channel = this.channelTopics.get(record.channelId);
    if (!channel) throw new Error(`message on unknown channel ${record.channelId}`);
    const entry = this.channels.get(channel.topic);
    if (entry) entry.messageCount += 1;
    this.messages.push({
      topic: channel.topic,
      schemaName: entry?.schemaName ?? '',
      logTime: record.logTime,
      value: JSON.parse(decoder.decode(record.data)) as unknown,
    });
  }

  meta(record: McapTypes.Metadata): void {
    this.metadata.set(record.name, Object.fromEntries(record.metadata));
  }
}

async function readIndexed(bytes: Uint8Array): Promise<Recording> {
  const reader = await McapIndexedReader.Initialize({
    readable: bytesReadable(bytes),
    decompressHandlers: DECOMPRESS_HANDLERS,
  });
  const out = new RecordingBuilder();
  for (const schema of reader.schemasById.values()) out.schema(schema);
  for (const channel of reader.channelsById.values()) out.channel(channel);
  for await (const message of reader.readMessages()) out.message(message);
  for await (const metadata of reader.readMetadata()) out.meta(metadata);
  return {
    complete: true,
    channels: out.channels,
    messages: out.messages,
    metadata: out.metadata,
    chunkCount: reader.chunkIndexes.length,
  };
}

/** MCAP's recovery: every record in order, up to the last complete one. */
function readStream(bytes: Uint8Array): Recording {
  const reader = new McapStreamReader({ decompressHandlers: DECOMPRESS_HANDLERS });
  reader.append(bytes);
  const out = new RecordingBuilder();
  let chunkCount = 0;
  let truncation: string | undefined;
  try {
    for (let record = reader.nextRecord(); record; record = reader.nextRecord()) {
      if (record.type === 'Schema') out.schema(record);
      else if (record.type === 'Channel') out.channel(record);
      else if (record.type === 'Message') out.message(record);
      else if (record.type === 'Metadata') out.meta(record);
      else if (record.type === 'ChunkIndex') chunkCount += 1;
    }
  } catch (error) {
    truncation = error instanceof Error ? error.message : String(error);
  }
  if (!reader.done()) truncation ??= `the file ends after ${bytes.byteLength} bytes, mid-record`;
  out.messages.sort((a, b) => (a.logTime < b.logTime ? -1 : a.logTime > b.logTime ? 1 : 0));
  return {
    complete: reader.done(),
    ...(truncation !== undefined ? { truncation } : {}),
    channels: out.channels,
    messages: out.messages,
    metadata: out.metadata,
    chunkCount,
  };
}

/**
 * Reads a recording: through its summary and index when it ended properly, else with MCAP's
 * recovery (record by record, up to the last complete chunk), as a killed process leaves it.
 */
export async function readRecording(bytes: Uint8Array): Promise<Recording> {
  await zstdReady();
  try {
    return await readIndexed(bytes);
  } catch {
    return readStream(bytes);
  }
}

/** Reads the recording in the file at `path`. */
export async function readRecordingFile(path: string): Promise<Recording> {
  const { readFile } = await import('node:fs/promises');
  return readRecording(new Uint8Array(await readFile(path)));
}
