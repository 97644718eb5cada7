import { SimulationHAL, World } from '@hal/simulation';
import { HalError } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { memorySink } from './file-sink.js';
import type { HalCallRecord } from './messages.js';
import { robotNamespace } from './namespace.js';
import { readRecording } from './read-recording.js';
import { recordHal } from './record-hal.js';
import { McapRecorder } from './recorder.js';
import { summarizeRecording } from './summary.js';
import { expectWellFormed } from './testing/well-formed.js';

describe('robotNamespace', () => {
  it('leaves the topics of one robot as they are, and puts a namespaced robot under /<namespace>', () => {
    expect(robotNamespace().topics.calls).toBe('/hal/calls');
    expect(robotNamespace().frame('base_link')).toBe('base_link');
    const space = robotNamespace('sim-2');
    expect(space.topics).toMatchObject({ calls: '/sim-2/hal/calls', tf: '/sim-2/tf' });
    expect(space.frame('base_link')).toBe('sim-2/base_link');
    expect(space.metadataName).toBe('hal.robot/sim-2');
  });

  it('refuses a namespace that would not make a topic name, naming the parameter', () => {
    expect(() => robotNamespace('a/b')).toThrow(HalError);
    expect(() => robotNamespace('')).toThrow(/"namespace" must be 1-64 letters/);
  });
});

describe('recordHal options', () => {
  it('refuses a bad namespace or sampling period with INVALID_PARAMETER, naming it', async () => {
    const recorder = await McapRecorder.create(memorySink());
    const sim = new SimulationHAL();
    expect(() => recordHal(sim, recorder, { namespace: 'no spaces' })).toThrow(/"namespace"/);
    expect(() => recordHal(sim, recorder, { posePeriodMs: Number.NaN })).toThrow(
      /"posePeriodMs" must be a finite number/,
    );
    expect(() => recordHal(sim, recorder, { linkPeriodMs: -5 })).toThrow(
      expect.objectContaining({
        code: 'INVALID_PARAMETER',
        details: { parameter: 'linkPeriodMs' },
      }),
    );
    expect(recorder.stats().written).toBe(0);
    await recorder.close();
  });
});

describe('recordHal with a namespace', () => {
  it('records two robots into one file, each on its own channels and frames, summed up per robot', async () => {
    const sink = memorySink();
    const recorder = await McapRecorder.create(sink);
    const world = new World();
    const robots = ['sim-1', 'sim-2'].map((id, i) =>
      recordHal(
        new SimulationHAL({ world, deviceId: id, start: { x: 0, y: i * 0.5, yaw: 0 } }),
        recorder,
        { namespace: id, posePeriodMs: 0 },
      ),
    );
    const [one, two] = robots as [SimulationHAL, SimulationHAL];
    await Promise.all(robots.map((hal) => hal.initialize()));
    await Promise.all([one.locomotion.moveForward(10), two.locomotion.moveForward(5)]);
    await two.locomotion.moveForward(Number.NaN);
    await two.safety.emergencyStop('only this one');
    await Promise.all(robots.map((hal) => hal.cleanup()));
    await recorder.close();

    const recording = await readRecording(sink.bytes());
    expectWellFormed(recording);
    const callsOf = (topic: string) =>
      recording.messages.filter((m) => m.topic === topic).map((m) => m.value as HalCallRecord);
    expect(callsOf('/sim-1/hal/calls').map((c) => c.call)).toEqual([
      'initialize',
      'locomotion.moveForward',
      'cleanup',
    ]);
    expect(callsOf('/sim-2/hal/calls')).toHaveLength(5);
    expect(recording.channels.has('/hal/calls')).toBe(false);
    const lastTf = (topic: string) =>
      recording.messages.filter((m) => m.topic === topic).at(-1)?.value as {
        parent_frame_id: string;
        child_frame_id: string;
        translation: { x: number; y: number };
      };
    expect(lastTf('/sim-1/tf')).toMatchObject({
      parent_frame_id: 'world',
      child_frame_id: 'sim-1/base_link',
    });
    expect(lastTf('/sim-1/tf').translation.x).toBeCloseTo(0.1, 3);
    expect(lastTf('/sim-2/tf').translation.x).toBeCloseTo(0.05, 3);
    expect(lastTf('/sim-2/tf').translation.y).toBeCloseTo(0.5, 3);
    expect(recording.metadata.get('hal.robot/sim-2')).toMatchObject({ device_id: 'sim-2' });

    const summary = summarizeRecording(recording);
    expect(summary).toMatchObject({ calls: 8, errors: 1, emergencyStops: 1 });
    expect(summary.robots).toEqual({
      'sim-1': { calls: 3, errors: 0, emergencyStops: 0, trips: 0, messages: expect.any(Number) },
      'sim-2': { calls: 5, errors: 1, emergencyStops: 1, trips: 0, messages: expect.any(Number) },
    });
    expect(summary.robots?.['sim-1']?.messages).toBeGreaterThan(3);
  });
});
