import { crc32, crc32Final, crc32Init, crc32Update } from '@foxglove/crc';
import { McapChunkBuilder, McapRecordBuilder, Opcode } from '@mcap/core';
import type { IWritable, McapTypes } from '@mcap/core';

/** Compresses a chunk's records: the compression's name (as readers know it) and the bytes. */
export type ChunkCompressor = (records: Uint8Array) => {
  compression: string;
  compressedData: Uint8Array;
};

/** How a {@link ChunkedMcapWriter} writes. */
export interface ChunkedMcapWriterOptions {
  writable: IWritable;
  /** Bytes of records in a chunk before it is closed by size. */
  chunkSize: number;
  /** Compression of every chunk; none when absent. */
  compressChunk?: ChunkCompressor;
}

/** A footer's opcode, length, summary start and summary offset start: what its CRC covers. */
const FOOTER_START_BYTES = 1 + 8 + 8 + 8;
/** A footer's content: summary start, summary offset start, summary CRC. */
const FOOTER_CONTENT_BYTES = 8n + 8n + 4n;

/**
 * An MCAP writer that closes a chunk when it is full, as `@mcap/core`'s `McapWriter` does, and
 * also when its owner says ({@link closeChunk}): the recorder closes a chunk on time, so a
 * process killed mid-run leaves its last moments on disk. `McapWriter` (2.2) closes chunks only
 * by size and at `end()`; this writer is built from the same library's own blocks
 * (`McapChunkBuilder`, `McapRecordBuilder`) and writes the file `McapWriter` writes: chunked
 * messages with their message indexes, metadata records, a data section CRC, and a summary
 * (schemas, channels, statistics, metadata and chunk indexes, summary offsets) with its CRC.
 *
 * As with `McapWriter`, each call must finish before the next is made.
 */
export class ChunkedMcapWriter {
  readonly #writable: IWritable;
  readonly #chunkSize: number;
  readonly #compress: ChunkCompressor | undefined;
  readonly #records = new McapRecordBuilder();
  readonly #chunk = new McapChunkBuilder({ useMessageIndex: true });
  readonly #schemas = new Map<number, McapTypes.Schema>();
  readonly #channels = new Map<number, McapTypes.Channel>();
  readonly #inFile = new Set<string>();
  readonly #chunkIndexes: McapTypes.ChunkIndex[] = [];
  readonly #metadataIndexes: McapTypes.MetadataIndex[] = [];
  readonly #statistics: McapTypes.Statistics = {
    messageCount: 0n,
    schemaCount: 0,
    channelCount: 0,
    attachmentCount: 0,
    metadataCount: 0,
    chunkCount: 0,
    messageStartTime: 0n,
    messageEndTime: 0n,
    channelMessageCounts: new Map(),
  };
  #dataCrc = crc32Init();
  #nextSchemaId = 1;
  #nextChannelId = 0;

  constructor(options: ChunkedMcapWriterOptions) {
    this.#writable = options.writable;
    this.#chunkSize = options.chunkSize;
    this.#compress = options.compressChunk;
  }

  /** Messages in the chunk being filled (0: none is open). */
  get openChunkMessages(): number {
    return this.#chunk.numMessages;
  }

  /** Chunks written so far (the number of the one being filled, counting from 0). */
  get chunksWritten(): number {
    return this.#statistics.chunkCount;
  }

  /** Writes the magic and the header record. */
  async start(header: McapTypes.Header): Promise<void> {
    this.#records.writeMagic();
    this.#records.writeHeader(header);
    await this.#flushData();
  }

  /** Declares a schema; its record goes into the first chunk with a message that uses it. */
  registerSchema(info: Omit<McapTypes.Schema, 'id'>): Promise<number> {
    const id = this.#nextSchemaId++;
    this.#schemas.set(id, { ...info, id });
    this.#statistics.schemaCount += 1;
    return Promise.resolve(id);
  }

  /** Declares a channel; its record goes into the first chunk with a message on it. */
  registerChannel(info: Omit<McapTypes.Channel, 'id'>): Promise<number> {
    const id = this.#nextChannelId++;
    this.#channels.set(id, { ...info, id });
    this.#statistics.channelCount += 1;
    return Promise.resolve(id);
  }

  /** Adds a message to the chunk being filled, and closes the chunk once it is full. */
  async addMessage(message: McapTypes.Message): Promise<void> {
    const channel = this.#channels.get(message.channelId);
    if (channel === undefined) throw new Error(`no channel ${message.channelId} was registered`);
    const stats = this.#statistics;
    if (stats.messageCount === 0n || message.logTime < stats.messageStartTime) {
      stats.messageStartTime = message.logTime;
    }
    if (stats.messageCount === 0n || message.logTime > stats.messageEndTime) {
      stats.messageEndTime = message.logTime;
    }
    stats.messageCount += 1n;
    const counts = stats.channelMessageCounts;
    counts.set(message.channelId, (counts.get(message.channelId) ?? 0n) + 1n);
    if (!this.#inFile.has(`c${channel.id}`)) {
      const schema = this.#schemas.get(channel.schemaId);
      if (schema !== undefined && !this.#inFile.has(`s${schema.id}`)) {
        this.#chunk.addSchema(schema);
        this.#inFile.add(`s${schema.id}`);
      }
      this.#chunk.addChannel(channel);
      this.#inFile.add(`c${channel.id}`);
    }
    this.#chunk.addMessage(message);
    if (this.#chunk.byteLength > this.#chunkSize) await this.closeChunk();
  }

  /** Writes a metadata record (outside the chunks, as MCAP has them). */
  async addMetadata(metadata: McapTypes.Metadata): Promise<void> {
    const offset = this.#writable.position();
    const length = this.#records.writeMetadata(metadata);
    this.#metadataIndexes.push({ name: metadata.name, offset, length });
    this.#statistics.metadataCount += 1;
    await this.#flushData();
  }

  /**
   * Closes the chunk being filled, if it holds a message: writes it (compressed) and its
   * message indexes, so a reader of the file as it is now finds them.
   */
  async closeChunk(): Promise<void> {
    const chunk = this.#chunk;
    if (chunk.numMessages === 0) return;
    const records = chunk.buffer;
    const compressed = this.#compress?.(records) ?? { compression: '', compressedData: records };
    const chunkStartOffset = this.#writable.position();
    const chunkLength = this.#records.writeChunk({
      messageStartTime: chunk.messageStartTime,
      messageEndTime: chunk.messageEndTime,
      uncompressedSize: BigInt(records.byteLength),
      uncompressedCrc: crc32(records),
      compression: compressed.compression,
      records: compressed.compressedData,
    });
    const indexStart = chunkStartOffset + chunkLength;
    const messageIndexOffsets = new Map<number, bigint>();
    let messageIndexLength = 0n;
    for (const index of chunk.indices) {
      messageIndexOffsets.set(index.channelId, indexStart + messageIndexLength);
      messageIndexLength += this.#records.writeMessageIndex(index);
    }
    this.#chunkIndexes.push({
      messageStartTime: chunk.messageStartTime,
      messageEndTime: chunk.messageEndTime,
      chunkStartOffset,
      chunkLength,
      messageIndexOffsets,
      messageIndexLength,
      compression: compressed.compression,
      compressedSize: BigInt(compressed.compressedData.byteLength),
      uncompressedSize: BigInt(records.byteLength),
    });
    this.#statistics.chunkCount += 1;
    chunk.reset();
    await this.#flushData();
  }

  /** Closes the open chunk and writes the data end, the summary, the footer and the magic. */
  async end(): Promise<void> {
    await this.closeChunk();
    this.#records.writeDataEnd({ dataSectionCrc: crc32Final(this.#dataCrc) });
    await this.#flush();

    const summaryStart = this.#writable.position();
    const b = this.#records;
    const offsets: McapTypes.SummaryOffset[] = [];
    const group = (opcode: Opcode, write: () => bigint): void => {
      const groupStart = summaryStart + BigInt(b.length);
      const groupLength = write();
      if (groupLength > 0n) offsets.push({ groupOpcode: opcode, groupStart, groupLength });
    };
    const each =
      <T>(items: Iterable<T>, write: (item: T) => bigint) =>
      () => {
        let length = 0n;
        for (const item of items) length += write(item);
        return length;
      };
    group(
      Opcode.SCHEMA,
      each(this.#schemas.values(), (s) => b.writeSchema(s)),
    );
    group(
      Opcode.CHANNEL,
      each(this.#channels.values(), (c) => b.writeChannel(c)),
    );
    group(Opcode.STATISTICS, () => b.writeStatistics(this.#statistics));
    group(
      Opcode.METADATA_INDEX,
      each(this.#metadataIndexes, (m) => b.writeMetadataIndex(m)),
    );
    group(
      Opcode.CHUNK_INDEX,
      each(this.#chunkIndexes, (c) => b.writeChunkIndex(c)),
    );
    const summaryOffsetStart = summaryStart + BigInt(b.length);
    for (const offset of offsets) b.writeSummaryOffset(offset);
    // the summary CRC covers the summary, its offsets and the footer up to the CRC itself
    const footerStart = new DataView(new ArrayBuffer(FOOTER_START_BYTES));
    footerStart.setUint8(0, Opcode.FOOTER);
    footerStart.setBigUint64(1, FOOTER_CONTENT_BYTES, true);
    footerStart.setBigUint64(9, summaryStart, true);
    footerStart.setBigUint64(17, summaryOffsetStart, true);
    const summaryCrc = crc32Final(
      crc32Update(crc32Update(crc32Init(), b.buffer), new Uint8Array(footerStart.buffer)),
    );
    b.writeFooter({ summaryStart, summaryOffsetStart, summaryCrc });
    b.writeMagic();
    await this.#flush();
  }

  /** Writes what the record builder holds, counted into the data section's CRC. */
  async #flushData(): Promise<void> {
    await this.#flush(true);
  }

  async #flush(dataSection = false): Promise<void> {
    if (this.#records.length === 0) return;
    const bytes = this.#records.buffer; // a copy
    if (dataSection) this.#dataCrc = crc32Update(this.#dataCrc, bytes);
    this.#records.reset();
    await this.#writable.write(bytes);
  }
}
