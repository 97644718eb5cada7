// `hal record` says how many messages it wrote, and the file holds exactly that many: the
// recorder's own /recorder/loss message is counted too.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { runHal } from '@hal/cli';
import { readRecordingFile } from '@hal/recorder';
import { afterAll, describe, expect, it } from 'vitest';
import { captureIO } from '../cli/capture-io.js';

const dir = mkdtempSync(join(tmpdir(), 'hal-record-count-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

describe('hal record', () => {
  it('reports as many messages as the file holds', async () => {
    const file = join(dir, 'run.mcap');
    const io = captureIO();
    const code = await runHal(
      ['record', '-o', file, '--sim', '--time-scale', '20', 'forward 0.05', 'turn 90'],
      io,
    );
    expect(code, io.stderr()).toBe(0);
    const said = /recorded (\d+) messages to /.exec(io.stdout());
    expect(said, io.stdout()).not.toBeNull();
    const recording = await readRecordingFile(file);
    expect(recording.complete).toBe(true);
    expect(Number(said![1])).toBe(recording.messages.length);
    expect(recording.metadata.get('recorder.loss')?.['written']).toBe(said![1]);
  }, 60_000);
});
