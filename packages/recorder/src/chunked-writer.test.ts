import { crc32 } from '@foxglove/crc';
import { McapIndexedReader, McapStreamReader } from '@mcap/core';
import type { McapTypes } from '@mcap/core';
import { describe, expect, it } from 'vitest';
import { ChunkedMcapWriter } from './chunked-writer.js';
import { memorySink } from './file-sink.js';

const text = new TextEncoder();

async function writerWithChannel(chunkSize = 1 << 20) {
  const sink = memorySink();
  const writer = new ChunkedMcapWriter({ writable: sink, chunkSize });
  await writer.start({ profile: '', library: 'test' });
  const schemaId = await writer.registerSchema({
    name: 'n',
    encoding: 'jsonschema',
    data: text.encode('{}'),
  });
  const channelId = await writer.registerChannel({
    topic: '/t',
    schemaId,
    messageEncoding: 'json',
    metadata: new Map(),
  });
  const message = (n: number): McapTypes.Message => ({
    channelId,
    sequence: n,
    logTime: BigInt(n),
    publishTime: BigInt(n),
    data: text.encode(JSON.stringify({ n })),
  });
  return { sink, writer, message };
}

/** Every top-level record of a file, read by @mcap/core's stream reader up to where it ends. */
function streamed(bytes: Uint8Array): McapTypes.TypedMcapRecord[] {
  const reader = new McapStreamReader({ includeChunks: true });
  reader.append(bytes);
  const out: McapTypes.TypedMcapRecord[] = [];
  for (let r = reader.nextRecord(); r !== undefined; r = reader.nextRecord()) out.push(r);
  return out;
}

describe('ChunkedMcapWriter', () => {
  it("writes a file @mcap/core's indexed reader reads, its data and summary CRCs right", async () => {
    const { sink, writer, message } = await writerWithChannel(64);
    for (let n = 0; n < 10; n += 1) await writer.addMessage(message(n));
    await writer.addMetadata({ name: 'm', metadata: new Map([['k', 'v']]) });
    await writer.end();
    const bytes = sink.bytes();
    const reader = await McapIndexedReader.Initialize({
      readable: {
        size: () => Promise.resolve(BigInt(bytes.byteLength)),
        read: (offset, length) =>
          Promise.resolve(bytes.subarray(Number(offset), Number(offset + length))),
      },
    });
    const read = [];
    for await (const m of reader.readMessages()) read.push(Number(m.logTime));
    expect(read).toEqual([0, 1, 2, 3, 4, 5, 6, 7, 8, 9]);
    expect(reader.chunkIndexes.length).toBeGreaterThan(1); // closed by size
    expect(reader.statistics?.messageCount).toBe(10n);
    // the CRCs the reader leaves to whoever checks them, checked here
    const records = streamed(bytes);
    const dataEnd = records.find((r) => r.type === 'DataEnd');
    expect(reader.dataEndOffset).toBeGreaterThan(0n);
    expect(dataEnd).toEqual({
      type: 'DataEnd',
      dataSectionCrc: crc32(bytes.subarray(0, Number(reader.dataEndOffset))),
    });
    expect(reader.footer.summaryCrc).not.toBe(0);
    const footerAt = bytes.byteLength - 8 - (1 + 8 + 20);
    expect(reader.footer.summaryCrc).toBe(
      crc32(bytes.subarray(Number(reader.footer.summaryStart), footerAt + 1 + 8 + 16)),
    );
  });

  it('closeChunk writes the open chunk at once, and nothing when none is open', async () => {
    const { sink, writer, message } = await writerWithChannel();
    await writer.addMessage(message(1));
    await writer.addMessage(message(2));
    expect(writer.openChunkMessages).toBe(2);
    const before = sink.bytes().byteLength;
    await writer.closeChunk();
    expect(writer.openChunkMessages).toBe(0);
    expect(writer.chunksWritten).toBe(1);
    expect(sink.bytes().byteLength).toBeGreaterThan(before);
    const messages = streamed(sink.bytes()).filter((r) => r.type === 'Message');
    expect(messages.map((m) => m.logTime)).toEqual([1n, 2n]);
    const after = sink.bytes().byteLength;
    await writer.closeChunk();
    expect(sink.bytes().byteLength).toBe(after);
    expect(writer.chunksWritten).toBe(1);
  });
});
