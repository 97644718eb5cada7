import { mkdtemp, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { GuardEventSchema } from '@hal/perception';
import { readRecordingFile } from '@hal/recorder';
import { SimulationHAL, World } from '@hal/simulation';
import { Command } from 'commander';
import { afterEach, describe, expect, it } from 'vitest';
import { captureIO } from './testing/capture-io.js';
import {
  addGuardOptions,
  GUARD_TOPIC,
  guardFromOptions,
  guardReport,
  guardSettingsFromOptions,
  guardText,
  recordGuard,
} from './guard-options.js';
import { openRecordingFile } from './output-place.js';

function parse(args: string[]) {
  const command = addGuardOptions(
    new Command('x').exitOverride().configureOutput({ writeErr: () => undefined }),
  );
  command.parse(args, { from: 'user' });
  return command.opts<{ guard?: boolean; guardStandoff?: number }>();
}

let dir: string | undefined;
afterEach(async () => {
  if (dir !== undefined) await rm(dir, { recursive: true, force: true });
  dir = undefined;
});

describe('guard options', () => {
  it('guards by default, with the stand-off in any distance unit, and not with --no-guard', () => {
    expect(guardSettingsFromOptions(parse([]))).toEqual({});
    expect(guardSettingsFromOptions(parse(['--guard-standoff', '15cm']))).toEqual({
      standoffM: 0.15,
    });
    expect(guardSettingsFromOptions(parse(['--no-guard']))).toBeUndefined();
    expect(() => parse(['--guard-standoff', '0'])).toThrow(/--guard-standoff/);
  });

  it('leaves a robot reached over the network to the guard where it is served', () => {
    const sim = new SimulationHAL();
    const io = captureIO();
    expect(guardFromOptions(sim, {}, io, false, { kind: 'ws' }).guard).toBeUndefined();
    expect(guardFromOptions(sim, {}, io, false, { kind: 'nats' }).guard).toBeUndefined();
    expect(guardFromOptions(sim, {}, io, false, { kind: 'udp' }).guard).toBeDefined();
    expect(guardFromOptions(sim, { guard: false }, io, false, { kind: 'sim' }).hal).toBe(sim);
  });

  it('records the guard stopping a motion on /hal/guard, beside the calls', async () => {
    dir = await mkdtemp(join(tmpdir(), 'hal-guard-record-'));
    const file = join(dir, 'run.mcap');
    const world = new World({
      map: { name: 'wall', walls: [{ from: [0.625, -1], to: [0.625, 1] }] },
    });
    const sim = new SimulationHAL({ world, features: { rangeSensors: false } });
    const io = captureIO();
    const { hal, guard } = guardFromOptions(sim, {}, io, false);
    const recorder = await openRecordingFile({ option: '--record', path: file, overwrite: false });
    recordGuard(guard, recorder);
    await hal.initialize();
    const result = await hal.locomotion.moveForward(100);
    await hal.cleanup();
    await recorder.close();
    expect(result.code).toBe('OBSTACLE_AHEAD');
    const recording = await readRecordingFile(file);
    const events = recording.messages.filter((m) => m.topic === GUARD_TOPIC);
    expect(events).toHaveLength(1);
    const event = GuardEventSchema.parse(events[0]?.value);
    expect(event).toMatchObject({
      type: 'obstacle',
      stop: { motion: 'moveForward', source: 'camera' },
    });
    expect(guardReport(guard)).toMatchObject({ stops: 1, sees: 'camera' });
    expect(guardReport(undefined)).toEqual({ off: true });
    expect(guardText(guardReport(guard))).toMatch(
      /^guard: 1 motion\(s\) stopped or refused before an obstacle; the last 0\.\d+ m ahead \(camera\)$/,
    );
    expect(guardText({ off: true })).toBeUndefined();
  });
});
