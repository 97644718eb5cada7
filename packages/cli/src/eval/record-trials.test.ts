// `hal eval --record DIR`: every trial kept as an MCAP file, opened here with @mcap/core itself
// (not the recorder's own reader), which must hold the calls the trial made.
import { mkdtemp, readFile, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import * as zstd from '@foxglove/wasm-zstd';
import { McapIndexedReader } from '@mcap/core';
import type { McapTypes } from '@mcap/core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { EvalReport } from '@hal/eval';
import { captureIO } from '../testing/capture-io.js';
import { runHal } from '../program.js';

let dir = '';
beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-eval-record-'));
  await zstd.isLoaded;
});
afterAll(async () => {
  await rm(dir, { recursive: true, force: true });
});

function readable(bytes: Uint8Array): McapTypes.IReadable {
  return {
    size: () => Promise.resolve(BigInt(bytes.byteLength)),
    read: (offset, length) =>
      Promise.resolve(bytes.subarray(Number(offset), Number(offset + length))),
  };
}

/** The `/hal/calls` records of an MCAP file, as @mcap/core reads them. */
async function callsIn(file: string): Promise<{ call: string; args: unknown[] }[]> {
  const reader = await McapIndexedReader.Initialize({
    readable: readable(new Uint8Array(await readFile(file))),
    decompressHandlers: {
      zstd: (buffer, size) => zstd.decompress(buffer, Number(size)),
    },
  });
  const topics = new Map([...reader.channelsById].map(([id, c]) => [id, c.topic]));
  const calls: { call: string; args: unknown[] }[] = [];
  const decoder = new TextDecoder();
  for await (const message of reader.readMessages()) {
    if (topics.get(message.channelId) !== '/hal/calls') continue;
    calls.push(JSON.parse(decoder.decode(message.data)) as { call: string; args: unknown[] });
  }
  return calls;
}

describe('hal eval --record', () => {
  it("keeps each trial as an MCAP recording named by agent, task, seed and trial, with the trial's calls", async () => {
    const tasks = join(dir, 'tasks.json');
    await writeFile(
      tasks,
      JSON.stringify({
        version: 1,
        tasks: [
          {
            id: 'precision/forward-12cm',
            group: 'precision',
            instruction: 'Drive forward 12 cm.',
            world: { start: { x: 0, y: 0 } },
            checks: [{ kind: 'displacement', forwardM: 0.12, toleranceM: 0.01 }],
          },
        ],
      }),
    );
    const out = join(dir, 'recordings');
    const io = captureIO();
    const args = ['--agent', 'oracle,naive', '--tasks-file', tasks, '--trials', '2', '--seed', '5'];
    expect(await runHal(['--json', 'eval', ...args, '--record', out], io), io.stderr()).toBe(0);
    const report = io.jsonLines()[0] as EvalReport;
    for (const agent of ['oracle', 'naive']) {
      for (const [trial, seed] of [
        [0, 5],
        [1, 6],
      ] as const) {
        const file = join(
          out,
          agent,
          'precision',
          'forward-12cm',
          `seed-${seed}-trial-${trial}.mcap`,
        );
        const calls = await callsIn(file);
        // the leash's look at the pose and the tools' at the device come before the agent's own
        const own = calls
          .map((c) => c.call)
          .filter(
            (c) => !['initialize', 'cleanup', 'getDeviceInfo', 'locomotion.getPose'].includes(c),
          );
        expect(own, `${agent} seed ${seed}`).toEqual(
          agent === 'oracle'
            ? ['locomotion.moveForward', 'safety.isEmergencyStopped']
            : ['locomotion.moveForward'],
        );
        expect(calls.find((c) => c.call === 'locomotion.moveForward')?.args).toEqual([12]);
        const scored = report.scores.agents
          .find((a) => a.agent === agent)
          ?.trials.find((t) => t.seed === seed);
        expect(own.length).toBe(scored?.toolCalls);
      }
    }
  }, 60_000);
});
