// A recording process killed with SIGKILL leaves a file MCAP's recovery reads up to its last
// complete chunk: every message there decodes against its channel's schema, in time order.
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { readRecordingFile } from '@hal/recorder';
import type { HalCallRecord } from '@hal/recorder';
import { Ajv2020 } from 'ajv/dist/2020.js';
import { afterAll, describe, expect, it } from 'vitest';

const CHILD = fileURLToPath(new URL('./recording-child.ts', import.meta.url));
const dir = mkdtempSync(join(tmpdir(), 'hal-recorder-kill-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

async function until(check: () => boolean, timeoutMs: number, what: string): Promise<void> {
  const deadline = Date.now() + timeoutMs;
  while (!check()) {
    if (Date.now() > deadline)
      throw new Error(`timed out after ${timeoutMs} ms waiting for ${what}`);
    await new Promise((resolve) => setTimeout(resolve, 50));
  }
}

describe('a recording killed with SIGKILL', () => {
  it('is read back by MCAP recovery up to its last complete chunk, every message valid', async () => {
    const file = join(dir, 'killed.mcap');
    const child = spawn(
      process.execPath,
      ['--conditions=@hal/source', '--import', 'tsx', CHILD, file],
      { stdio: ['ignore', 'pipe', 'pipe'] },
    );
    let stderr = '';
    child.stderr.on('data', (chunk: Buffer) => (stderr += chunk.toString()));
    const exited = new Promise<NodeJS.Signals | null>((resolve) =>
      child.once('exit', (_code, signal) => resolve(signal)),
    );
    try {
      const size = () => {
        try {
          return statSync(file).size;
        } catch {
          return 0;
        }
      };
      // several chunks on disk, then the kill lands mid-run
      await until(() => size() > 24 * 1024 || child.exitCode !== null, 30_000, 'chunks on disk');
      expect(child.exitCode, stderr).toBeNull();
    } finally {
      child.kill('SIGKILL');
    }
    expect(await exited).toBe('SIGKILL');

    const recording = await readRecordingFile(file);
    expect(recording.complete).toBe(false);
    expect(recording.truncation).toEqual(expect.any(String));
    const calls = recording.messages.filter((m) => m.topic === '/hal/calls');
    expect(calls.length).toBeGreaterThan(5);
    expect(recording.channels.get('/hal/pose')?.messageCount).toBeGreaterThan(10);
    expect(recording.metadata.get('hal.robot')).toMatchObject({ device_id: 'sim-killed' });

    const ajv = new Ajv2020({ strict: false });
    let last = 0n;
    for (const message of recording.messages) {
      const validate = ajv.compile(recording.channels.get(message.topic)!.schema as object);
      expect(validate(message.value), `${message.topic}: ${ajv.errorsText(validate.errors)}`).toBe(
        true,
      );
      expect(message.logTime >= last).toBe(true);
      last = message.logTime;
    }
    // the calls are the run's first ones, none missing in between: a prefix of what was made
    const starts = calls.map((m) => BigInt((m.value as HalCallRecord).start_ns));
    expect([...starts].sort((a, b) => (a < b ? -1 : a > b ? 1 : 0))).toEqual(starts);
    expect((calls[0]!.value as HalCallRecord).call).toBe('initialize');
  }, 60_000);
});
