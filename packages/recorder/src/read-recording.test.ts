import { describe, expect, it } from 'vitest';
import { memorySink } from './file-sink.js';
import { LOG } from './foxglove-schemas.js';
import { CALL_RECORD, TOPICS } from './messages.js';
import { readRecording } from './read-recording.js';
import { McapRecorder } from './recorder.js';
import { RecordingReadError } from './recording-read-error.js';

const MAGIC = [0x89, 0x4d, 0x43, 0x41, 0x50, 0x30, 0x0d, 0x0a];
const CHUNK = 0x06;
const DATA_END = 0x0f;

function call(n: number): Record<string, unknown> {
  return {
    call: 'locomotion.moveForward',
    args: [n],
    outcome: 'resolved',
    success: true,
    start_ns: String(n),
    duration_ms: 1,
  };
}

/** A log line of 2,000 hex digits that do not compress: its chunk is larger than 400 bytes. */
function log(n: number): Record<string, unknown> {
  let x = 0x9e3779b9 + n;
  let text = '';
  while (text.length < 2000) {
    x ^= x << 13;
    x ^= x >>> 17;
    x ^= x << 5;
    text += (x >>> 0).toString(16).padStart(8, '0');
  }
  return { timestamp: { sec: n, nsec: 0 }, level: 2, message: text, name: 't', file: '', line: 0 };
}

/**
 * A recording of 7 calls, each in a chunk of its own, with a log line between them (in a chunk
 * of its own too): a small chunk size closes a chunk after every message.
 */
async function sevenCalls(): Promise<Uint8Array> {
  const sink = memorySink();
  const recorder = await McapRecorder.create(sink, { chunkSize: 64 });
  recorder.channel(TOPICS.calls, CALL_RECORD);
  recorder.channel(TOPICS.log, LOG);
  for (let n = 0; n < 7; n += 1) {
    recorder.write(TOPICS.calls, call(n), BigInt(2 * n + 1));
    recorder.write(TOPICS.log, log(n), BigInt(2 * n + 2));
  }
  await recorder.close();
  return sink.bytes();
}

/** The file's top-level records: opcode, where each starts, and its whole length. */
function records(bytes: Uint8Array): { opcode: number; offset: number; length: number }[] {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const out = [];
  for (let at = MAGIC.length; at + 9 <= bytes.byteLength - MAGIC.length;) {
    const length = 9 + Number(view.getBigUint64(at + 1, true));
    out.push({ opcode: bytes[at]!, offset: at, length });
    at += length;
  }
  return out;
}

/** `bytes` with `count` bytes from `from` overwritten by others (a fixed pseudo-random run). */
function garbled(bytes: Uint8Array, from: number, count: number): Uint8Array {
  const out = bytes.slice();
  let x = 0x2545f491;
  for (let i = from; i < from + count && i < out.byteLength; i += 1) {
    x ^= x << 13;
    x ^= x >>> 17;
    x ^= x << 5;
    out[i] = (out[i]! ^ (x & 0xff || 1)) & 0xff;
  }
  return out;
}

const callsOf = (recording: { messages: { topic: string; value: unknown }[] }) =>
  recording.messages
    .filter((m) => m.topic === TOPICS.calls)
    .map((m) => (m.value as { args: number[] }).args[0]);

async function refusal(bytes: Uint8Array): Promise<RecordingReadError> {
  const error = await readRecording(bytes, { name: 'x.mcap' }).then(
    () => undefined,
    (e: unknown) => e,
  );
  expect(error).toBeInstanceOf(RecordingReadError);
  return error as RecordingReadError;
}

describe('readRecording', () => {
  describe('refuses what is not a recording, naming the file and why', () => {
    it('an empty file', async () => {
      const error = await refusal(new Uint8Array(0));
      expect(error.code).toBe('EMPTY');
      expect(error.message).toBe('x.mcap is empty (0 bytes): not an MCAP recording');
    });

    it('a text file', async () => {
      const error = await refusal(new TextEncoder().encode('hello, these are notes\n'));
      expect(error.code).toBe('NOT_MCAP');
      expect(error.message).toContain(
        "x.mcap is not an MCAP file: it does not start with MCAP's magic bytes",
      );
      expect(error.message).toContain('"hello, t"');
    });

    it("MCAP's magic alone, or cut inside it", async () => {
      const magic = await refusal(new Uint8Array(MAGIC));
      expect(magic.code).toBe('NO_HEADER');
      expect(magic.message).toBe(
        'x.mcap holds no recording: it ends after 8 bytes, before its header record is complete',
      );
      expect((await refusal(new Uint8Array(MAGIC.slice(0, 5)))).code).toBe('NO_HEADER');
    });

    it("400 bytes of garbage after MCAP's magic", async () => {
      const bytes = garbled(new Uint8Array([...MAGIC, ...new Array<number>(400).fill(0)]), 8, 400);
      const error = await refusal(bytes);
      expect(error.code).toBe('NO_HEADER');
      expect(error.message).toContain('its first record (at byte 8) is not a readable header');
    });

    it('a recording whose one chunk is garbled: damaged, with not one message to read', async () => {
      const sink = memorySink();
      const recorder = await McapRecorder.create(sink);
      recorder.channel(TOPICS.calls, CALL_RECORD);
      for (let n = 0; n < 7; n += 1) recorder.write(TOPICS.calls, call(n));
      await recorder.close();
      const chunk = records(sink.bytes()).find((r) => r.opcode === CHUNK)!;
      const error = await refusal(garbled(sink.bytes(), chunk.offset + 60, 400));
      expect(error.code).toBe('DAMAGED');
      expect(error.offset).toBe(chunk.offset);
      expect(error.message).toMatch(
        new RegExp(
          `^x\\.mcap is damaged: not one message could be read \\(damaged at byte ${chunk.offset} of \\d+ \\(.+\\)`,
        ),
      );
    });
  });

  it('reads a complete recording whole, with no gaps', async () => {
    const recording = await readRecording(await sevenCalls());
    expect(recording.complete).toBe(true);
    expect(recording.gaps).toEqual([]);
    expect(recording.truncation).toBeUndefined();
    expect(callsOf(recording)).toEqual([0, 1, 2, 3, 4, 5, 6]);
  });

  it('reads a file cut short up to its last complete record, and says where it stopped', async () => {
    const bytes = await sevenCalls();
    const chunks = records(bytes).filter((r) => r.opcode === CHUNK);
    const last = chunks[9]!; // the 5th log line's: calls 0-4 come before it
    const cut = bytes.subarray(0, last.offset + 20);
    const recording = await readRecording(cut);
    expect(recording.complete).toBe(false);
    expect(callsOf(recording)).toEqual([0, 1, 2, 3, 4]);
    expect(recording.gaps).toEqual([
      {
        kind: 'cut-short',
        offset: last.offset,
        reason: `the file ends at byte ${cut.byteLength}, inside the record that starts at byte ${last.offset}`,
      },
    ]);
    expect(recording.truncation).toMatch(
      new RegExp(
        `^cut short at byte ${last.offset} of ${cut.byteLength} \\(.+\\); \\d+ records read$`,
      ),
    );
  });

  it('reads on past a garbled chunk: every call of the other chunks, and the damage named', async () => {
    const bytes = await sevenCalls();
    const chunks = records(bytes).filter((r) => r.opcode === CHUNK);
    const logChunk = chunks[3]!; // the 2nd log line's
    expect(logChunk.length).toBeGreaterThan(40 + 400);
    const recording = await readRecording(garbled(bytes, logChunk.offset + 40, 400));
    expect(recording.complete).toBe(false);
    expect(callsOf(recording)).toEqual([0, 1, 2, 3, 4, 5, 6]);
    expect(recording.gaps).toEqual([
      {
        kind: 'damaged',
        offset: logChunk.offset,
        resumedAt: chunks[4]!.offset,
        reason: expect.any(String) as unknown,
      },
    ]);
    expect(recording.truncation).toContain(`damaged at byte ${logChunk.offset}`);
    expect(recording.truncation).toContain(`read on from byte ${chunks[4]!.offset}`);
    // the garbled chunk's log line is the one lost
    expect(recording.messages.filter((m) => m.topic === TOPICS.log)).toHaveLength(6);
  });

  it('reads on past a garbled chunk of a file that was also cut short (no summary to help)', async () => {
    const bytes = await sevenCalls();
    const all = records(bytes);
    const chunks = all.filter((r) => r.opcode === CHUNK);
    const dataEnd = all.find((r) => r.opcode === DATA_END)!;
    const cut = garbled(bytes.subarray(0, dataEnd.offset - 3), chunks[4]!.offset + 30, 10);
    const recording = await readRecording(cut);
    // the 3rd call's chunk is lost, the rest read
    expect(callsOf(recording)).toEqual([0, 1, 3, 4, 5, 6]);
    expect(recording.gaps.map((g) => g.kind)).toEqual(['damaged', 'cut-short']);
    expect(recording.gaps[0]).toMatchObject({
      offset: chunks[4]!.offset,
      resumedAt: chunks[5]!.offset,
    });
  });
});
