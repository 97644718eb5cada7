// `hal inspect` and `hal replay` check a file before they trust it: what is not a recording (a
// text file, an empty file, MCAP's magic alone, garbage after it, a recording whose one chunk is
// garbled) is `hal: FAILED: FILE ...` with the reason, exit 1; a recording cut short or damaged in
// part is read as far as it goes, and both commands say where reading stopped and what they read.
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { runHal } from '@hal/cli';
import { McapRecorder, readRecordingFile, recordHal } from '@hal/recorder';
import type { RecordingSummary } from '@hal/recorder';
import { SimulationHAL } from '@hal/simulation';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { captureIO } from '../cli/capture-io.js';
import { runHalProcess } from '../helpers/hal-process.js';

const dir = mkdtempSync(join(tmpdir(), 'hal-bad-files-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

const MAGIC = [0x89, 0x4d, 0x43, 0x41, 0x50, 0x30, 0x0d, 0x0a];

/** The file's top-level chunk records: where each starts and its whole length. */
function chunks(bytes: Uint8Array): { offset: number; length: number }[] {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const out = [];
  for (let at = MAGIC.length; at + 9 <= bytes.byteLength - MAGIC.length;) {
    const length = 9 + Number(view.getBigUint64(at + 1, true));
    if (bytes[at] === 0x06) out.push({ offset: at, length });
    at += length;
  }
  return out;
}

/** How many messages the chunk at `offset` holds: the entries of its message indexes. */
function messagesIn(bytes: Uint8Array, offset: number): number {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  let at = offset + 9 + Number(view.getBigUint64(offset + 1, true));
  let count = 0;
  while (bytes[at] === 0x07) {
    const length = Number(view.getBigUint64(at + 1, true));
    count += view.getUint32(at + 9 + 2, true) / 16;
    at += 9 + length;
  }
  return count;
}

/** `bytes` with `count` bytes from `from` changed (a fixed pseudo-random run). */
function garbled(bytes: Uint8Array, from: number, count: number): Uint8Array {
  const out = bytes.slice();
  let x = 0x1234567;
  for (let i = from; i < from + count; i += 1) {
    x ^= x << 13;
    x ^= x >>> 17;
    x ^= x << 5;
    out[i] = (out[i]! ^ (x & 0xff || 1)) & 0xff;
  }
  return out;
}

async function inspect(file: string) {
  const io = captureIO();
  const code = await runHal(['inspect', file], io);
  return { code, stdout: io.stdout(), stderr: io.stderr() };
}

async function replay(file: string) {
  const io = captureIO();
  const code = await runHal(['replay', file], io);
  return { code, stdout: io.stdout(), stderr: io.stderr() };
}

let recorded: Uint8Array;

beforeAll(async () => {
  // a short recorded drive, small chunks (1 KiB): its calls spread over many chunks
  const file = join(dir, 'run.mcap');
  const recorder = await McapRecorder.toFile(file, { chunkSize: 1024 });
  const hal = recordHal(new SimulationHAL({ deviceId: 'sim-bad' }), recorder, { posePeriodMs: 0 });
  await hal.initialize();
  for (let i = 0; i < 6; i += 1) {
    await hal.locomotion.moveForward(2);
    await hal.locomotion.rotate('left', 15);
  }
  await hal.cleanup();
  await recorder.close();
  recorded = new Uint8Array(readFileSync(file));
});

describe('hal inspect and hal replay, given what is not a recording', () => {
  const cases: [string, () => Uint8Array, RegExp][] = [
    [
      'notes.txt',
      () => new TextEncoder().encode('shopping: bread, milk\n'),
      /is not an MCAP file: it does not start with MCAP's magic bytes \(it starts with 73 68 6f 70 70 69 6e 67 "shopping"\)$/,
    ],
    ['empty.mcap', () => new Uint8Array(0), /is empty \(0 bytes\): not an MCAP recording$/],
    [
      'magic.mcap',
      () => new Uint8Array(MAGIC),
      /holds no recording: it ends after 8 bytes, before its header record is complete$/,
    ],
    [
      'garbage.mcap',
      () => garbled(new Uint8Array([...MAGIC, ...new Array<number>(400).fill(0)]), 8, 400),
      /holds no recording: its first record \(at byte 8\) is not a readable header: /,
    ],
    [
      'one-chunk-garbled.mcap',
      () => {
        const only = chunks(recorded)[0]!;
        // every chunk but the first cut away, and the first garbled
        const bytes = garbled(
          recorded.subarray(0, only.offset + only.length),
          only.offset + 40,
          400,
        );
        return bytes;
      },
      /is damaged: not one message could be read \(damaged at byte \d+ of \d+ \(.+\)/,
    ],
  ];

  for (const [name, bytes, reason] of cases) {
    it(`${name}: FAILED, exit 1, the file named with the reason`, async () => {
      const file = join(dir, name);
      writeFileSync(file, bytes());
      for (const run of [await inspect(file), await replay(file)]) {
        expect(run.code, run.stderr).toBe(1);
        expect(run.stdout).toBe('');
        const line = run.stderr.trim();
        expect(line.startsWith(`hal: FAILED: ${file} `), line).toBe(true);
        expect(line).toMatch(reason);
      }
    });
  }

  it('as a process: notes.txt exits 1 with one FAILED line', async () => {
    const file = join(dir, 'notes-process.txt');
    writeFileSync(file, 'not a recording\n');
    const run = await runHalProcess(['inspect', file], 60_000);
    expect(run.code, run.stderr).toBe(1);
    expect(run.stdout).toBe('');
    expect(run.stderr).toMatch(new RegExp(`^hal: FAILED: ${file} is not an MCAP file: `));
  }, 90_000);
});

describe('hal inspect and hal replay, given a recording not whole', () => {
  it('a file cut short: read to its last complete record, where it stopped said', async () => {
    const all = chunks(recorded);
    const cutAt = all[4]!.offset + 30;
    const file = join(dir, 'cut.mcap');
    writeFileSync(file, recorded.subarray(0, cutAt));
    const expected = await readRecordingFile(file);
    const calls = expected.messages.filter((m) => m.topic === '/hal/calls').length;
    expect(calls).toBeGreaterThan(0);

    const inspected = await inspect(file);
    expect(inspected.code, inspected.stderr).toBe(0);
    expect(inspected.stdout).toContain(
      `not read whole: cut short at byte ${all[4]!.offset} of ${cutAt} (the file ends at byte ${cutAt}, inside the record that starts at byte ${all[4]!.offset});`,
    );
    expect(inspected.stdout).toContain(`calls ${calls}, `);

    const replayed = await replay(file);
    expect(replayed.code, replayed.stderr).toBe(0);
    expect(replayed.stdout).toContain(`not read whole: cut short at byte ${all[4]!.offset}`);
  });

  it('a file garbled in the middle: every chunk but the damaged one read, the damage named', async () => {
    const all = chunks(recorded);
    const intact = await inspect(join(dir, 'run.mcap'));
    const before = Number(/calls (\d+),/.exec(intact.stdout)?.[1]);
    expect(before).toBeGreaterThanOrEqual(14); // initialize, 12 motions, cleanup

    // a chunk longer than the 400 bytes garbled in it, so they stay inside it
    const damaged = all.find((c, i) => i > 0 && c.length > 420 + 20)!;
    const file = join(dir, 'garbled.mcap');
    writeFileSync(file, garbled(recorded, damaged.offset + 20, 400));
    const io = captureIO();
    expect(await runHal(['--json', 'inspect', file], io)).toBe(0);
    const summary = io.jsonLines().at(-1) as RecordingSummary;
    expect(summary.complete).toBe(false);
    expect(summary.gaps).toEqual([
      {
        kind: 'damaged',
        offset: damaged.offset,
        resumedAt: all[all.indexOf(damaged) + 1]!.offset,
        reason: expect.any(String) as unknown,
      },
    ]);
    // only the damaged chunk's messages are lost: every other chunk is read
    const lost = messagesIn(recorded, damaged.offset);
    const count = (s: { channels: Record<string, { messages: number }> }) =>
      Object.values(s.channels).reduce((n, c) => n + c.messages, 0);
    const intactIo = captureIO();
    expect(await runHal(['--json', 'inspect', join(dir, 'run.mcap')], intactIo)).toBe(0);
    const whole = intactIo.jsonLines().at(-1) as RecordingSummary;
    expect(lost).toBeGreaterThan(0);
    expect(count(summary)).toBe(count(whole) - lost);
    expect(summary.calls).toBeGreaterThanOrEqual(before - lost);

    const text = await inspect(file);
    expect(text.stdout).toContain(
      `not read whole: damaged at byte ${damaged.offset} of ${recorded.byteLength} (`,
    );
    expect(text.stdout).toContain(`read on from byte ${summary.gaps[0]!.resumedAt}`);
  });
});
