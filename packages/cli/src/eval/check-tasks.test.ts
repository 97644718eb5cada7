// `hal eval --check-tasks` in-process: the oracle over every seed of a task file, naming the task
// and seeds it cannot solve.
import { mkdtemp, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { captureIO } from '../testing/capture-io.js';
import { runHal } from '../program.js';

let dir = '';
beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-check-tasks-'));
});
afterAll(async () => {
  await rm(dir, { recursive: true, force: true });
});

const solvable = {
  id: 'precision/forward-10cm',
  group: 'precision',
  instruction: 'Drive forward 10 cm.',
  world: { start: { x: 0, y: 0 } },
  budget: { toolCalls: 4, simSeconds: 30 },
  checks: [{ kind: 'displacement', forwardM: 0.1, toleranceM: 0.01 }],
};
// loads (every place is fine) but no agent can pass it: 1 m in one call of at most 0.2 m
const unsolvable = {
  id: 'precision/forward-1m-leashed',
  group: 'precision',
  instruction: 'Drive forward 1 m.',
  world: { start: { x: 0, y: 0 } },
  budget: { toolCalls: 1, simSeconds: 30 },
  leash: { maxDistanceM: 0.2 },
  checks: [{ kind: 'displacement', forwardM: 1, toleranceM: 0.01 }],
};

async function check(tasks: unknown[], name: string) {
  const path = join(dir, name);
  await writeFile(path, JSON.stringify({ version: 1, tasks }));
  const io = captureIO();
  const code = await runHal(['eval', '--check-tasks', '--tasks-file', path, '--trials', '2'], io);
  return { code, out: io.stdout(), err: io.stderr() };
}

describe('hal eval --check-tasks', () => {
  it('passes a file the oracle solves on every seed', async () => {
    const { code, out } = await check([solvable], 'good.json');
    expect(out).toBe('the oracle solved all 1 task(s) on 2 seed(s) each\n');
    expect(code).toBe(0);
  }, 60_000);

  it('names each task and seed the oracle cannot solve, and exits 1', async () => {
    const { code, out, err } = await check([solvable, unsolvable], 'bad.json');
    expect(code).toBe(1);
    const lines = out.trim().split('\n');
    expect(lines).toHaveLength(3);
    expect(lines[0]).toMatch(/^precision\/forward-1m-leashed seed 1: the oracle failed: /);
    expect(lines[1]).toMatch(/^precision\/forward-1m-leashed seed 2: the oracle failed: /);
    expect(lines[2]).toBe('the oracle could not solve 1 of 2 task(s) (2 of 4 trial(s))');
    expect(out).not.toContain('forward-10cm');
    expect(err).toContain('hal: FAILED: the oracle could not solve 2 trial(s)');
  }, 60_000);
});
