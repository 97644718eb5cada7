// A recording survives a crash up to about its last second: `hal record` (against the emulated
// cube over UDP) and `hal agent --record` (on the simulator, its model behind the fake
// OpenAI-compatible endpoint) are run through the launcher users run (`node scripts/hal.js`) and
// killed with SIGKILL in the middle of a motion. The file is then read with @mcap/core's own
// stream reader, as any MCAP tool would read it: every call that had answered more than a second
// before the kill is in it. (The recorder closes a chunk once it is 500 ms old; what it may lose
// is written down in docs/recording.md.)
import { spawn } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import * as zstd from '@foxglove/wasm-zstd';
import { McapStreamReader } from '@mcap/core';
import { afterAll, describe, expect, it } from 'vitest';
import { startFakeOpenAIServer } from '../helpers/fake-openai-server.js';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';

const LAUNCHER = fileURLToPath(new URL('../../scripts/hal.js', import.meta.url));
const dir = mkdtempSync(join(tmpdir(), 'hal-crash-loss-'));
afterAll(async () => {
  await stopAllEmulators();
  rmSync(dir, { recursive: true, force: true });
});

/** Past this, a call must be in the file (ms before the kill). */
const KEPT_AFTER_MS = 1000;

interface CallRecord {
  call: string;
  args: unknown[];
  success: boolean;
}

/**
 * The `/hal/calls` records of a file as @mcap/core's stream reader gives them, record by record,
 * up to where the file stops (a killed process leaves no summary: the reader ends there).
 */
async function callsReadByMcapCore(file: string): Promise<CallRecord[]> {
  await zstd.isLoaded;
  const reader = new McapStreamReader({
    decompressHandlers: { zstd: (data, size) => zstd.decompress(data, Number(size)) },
  });
  reader.append(new Uint8Array(readFileSync(file)));
  const topics = new Map<number, string>();
  const calls: CallRecord[] = [];
  const decoder = new TextDecoder();
  try {
    for (let record = reader.nextRecord(); record; record = reader.nextRecord()) {
      if (record.type === 'Channel') topics.set(record.id, record.topic);
      if (record.type === 'Message' && topics.get(record.channelId) === '/hal/calls') {
        calls.push(JSON.parse(decoder.decode(record.data)) as CallRecord);
      }
    }
  } catch (error) {
    // the record the kill cut through; everything before it has been read
    expect(String(error)).not.toMatch(/CRC|decompress/i);
  }
  expect(reader.done()).toBe(false); // no footer: the process never finished the file
  return calls;
}

/** Starts `node scripts/hal.js ARGS`, its output collected; resolves its exit signal. */
function launch(args: string[]) {
  const child = spawn(process.execPath, [LAUNCHER, ...args], { stdio: ['ignore', 'pipe', 'pipe'] });
  let output = '';
  child.stdout.on('data', (chunk: Buffer) => (output += chunk.toString()));
  child.stderr.on('data', (chunk: Buffer) => (output += chunk.toString()));
  const exited = new Promise<NodeJS.Signals | null>((resolve) =>
    child.once('exit', (_code, signal) => resolve(signal)),
  );
  return { child, exited, output: () => output };
}

const sleep = (ms: number) => new Promise((resolve) => setTimeout(resolve, ms));

async function waitUntil(check: () => boolean, timeoutMs: number, what: string): Promise<void> {
  const deadline = Date.now() + timeoutMs;
  while (!check()) {
    if (Date.now() > deadline) throw new Error(`waited ${timeoutMs} ms for ${what}`);
    await sleep(20);
  }
}

describe('a recording killed with SIGKILL mid-motion', () => {
  it('hal record against the emulated cube keeps every call answered more than a second before the kill', async () => {
    const emulator = await startEmulator();
    const file = join(dir, 'record.mcap');
    const steps = ['forward 0.05', 'turn 90', 'forward 0.05', 'turn 90', 'forward 0.05', 'turn 90'];
    const run = launch(['record', '-o', file, '--udp', `127.0.0.1:${emulator.udpPort}`, ...steps]);
    const finishedAt: number[] = [];
    let killedAt: number;
    try {
      // three motions done, as the robot says (when this process saw it: never earlier)
      for (let k = 1; k <= 3; k += 1) {
        await emulator.waitForCount((e) => e.event === 'move_finished', k, 60_000);
        finishedAt.push(Date.now());
      }
      // the fourth under way (each takes about 3 s at the cube's speed), then the kill
      await emulator.waitForCount((e) => e.event === 'move_started', 4, 30_000);
      await sleep(1200);
      expect(emulator.events.filter((e) => e.event === 'move_finished')).toHaveLength(3);
    } finally {
      killedAt = Date.now();
      run.child.kill('SIGKILL');
    }
    expect(await run.exited, run.output()).toBe('SIGKILL');

    const motions = (await callsReadByMcapCore(file)).filter((c) =>
      c.call.startsWith('locomotion.'),
    );
    const due = finishedAt.filter((at) => at < killedAt - KEPT_AFTER_MS).length;
    expect(due).toBe(3);
    expect(motions.length).toBeGreaterThanOrEqual(due);
    expect(motions.slice(0, 3)).toEqual([
      expect.objectContaining({ call: 'locomotion.moveForward', args: [5], success: true }),
      expect.objectContaining({ call: 'locomotion.rotate', args: ['left', 90], success: true }),
      expect.objectContaining({ call: 'locomotion.moveForward', args: [5], success: true }),
    ]);
  }, 120_000);

  it('hal agent --record keeps every tool call answered more than a second before the kill', async () => {
    // every turn, the model asks for 10 cm more (the last reply repeats): about 4 s a motion
    const server = await startFakeOpenAIServer([
      {
        content: null,
        toolCalls: [{ name: 'move_forward', arguments: JSON.stringify({ distanceCm: 10 }) }],
      },
    ]);
    const file = join(dir, 'agent.mcap');
    const run = launch([
      'agent',
      '--sim',
      '--base-url',
      server.baseUrl,
      '--model',
      'fake',
      '--max-steps',
      '50',
      '--record',
      file,
      'drive forward, 10 cm at a time',
    ]);
    let killedAt: number;
    try {
      // a request to the model comes after each tool call has answered: 4 requests, 3 answers
      await waitUntil(
        () => server.requests.length >= 4 || run.child.exitCode !== null,
        90_000,
        `the agent's 4th model request (output so far: ${run.output()})`,
      );
      expect(run.child.exitCode, run.output()).toBeNull();
      await sleep(1200); // the 4th move under way
    } finally {
      killedAt = Date.now();
      run.child.kill('SIGKILL');
      await server.close();
    }
    expect(await run.exited, run.output()).toBe('SIGKILL');

    // request i+1 came once tool call i had answered (and the agent had taken its result)
    const answeredAt = server.requests.slice(1).map((r) => r.at);
    const due = answeredAt.filter((at) => at < killedAt - KEPT_AFTER_MS).length;
    expect(due).toBeGreaterThanOrEqual(3);
    const moves = (await callsReadByMcapCore(file)).filter(
      (c) => c.call === 'locomotion.moveForward',
    );
    expect(moves.length).toBeGreaterThanOrEqual(due);
    for (const move of moves.slice(0, due)) {
      expect(move).toMatchObject({ args: [10], success: true });
    }
  }, 150_000);
});
