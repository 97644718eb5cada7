import { SimulationHAL } from '@hal/simulation';
import { CAPABILITIES, HalError } from '@hal/types';
import type { HardwareAbstractionLayer } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { memorySink } from './file-sink.js';
import type { RecordingSink } from './file-sink.js';
import type { HalCallRecord, SafetyEvent } from './messages.js';
import { TOPICS } from './messages.js';
import { readRecording } from './read-recording.js';
import type { Recording } from './read-recording.js';
import { recordHal } from './record-hal.js';
import { McapRecorder } from './recorder.js';
import { expectWellFormed } from './testing/well-formed.js';

async function recorded(
  run: (hal: HardwareAbstractionLayer) => Promise<void>,
  hal: HardwareAbstractionLayer = new SimulationHAL({ deviceId: 'sim-rec' }),
): Promise<Recording> {
  const sink = memorySink();
  const recorder = await McapRecorder.create(sink);
  const wrapped = recordHal(hal, recorder, { posePeriodMs: 0, map: { name: 'empty' } });
  await run(wrapped);
  await wrapped.cleanup();
  await recorder.close();
  const recording = await readRecording(sink.bytes());
  expectWellFormed(recording);
  return recording;
}

const calls = (recording: Recording): HalCallRecord[] =>
  recording.messages.filter((m) => m.topic === TOPICS.calls).map((m) => m.value as HalCallRecord);

describe('recordHal', () => {
  it('is the HAL it wraps to its users: instanceof, getters, fields, a method replaced on the HAL', async () => {
    const sim = new SimulationHAL({ deviceId: 'sim-front' });
    const sink = memorySink();
    const recorder = await McapRecorder.create(sink);
    const hal = recordHal(sim, recorder, { posePeriodMs: 0 });
    expect(hal).toBeInstanceOf(SimulationHAL);
    expect(hal.mode).toBe('simulation');
    expect('locomotion' in hal).toBe(true);
    await hal.initialize();
    expect(hal.isReady()).toBe(true);
    expect(await hal.communication.setLED(1, 2, 3, 'solid')).toMatchObject({ success: true });
    // a method replaced on the HAL after it was first called through the recording
    const replaced: string[] = [];
    sim.communication.log = (message: string) => {
      replaced.push(message);
    };
    hal.communication.log('through the replacement');
    expect(replaced).toEqual(['through the replacement']);
    // a field assigned through the recording is the HAL's
    (hal as unknown as { note: string }).note = 'kept';
    expect((sim as unknown as { note?: string }).note).toBe('kept');
    // a method or subsystem assigned through the recording would record nothing: refused
    const original = sim.communication.log;
    expect(() => {
      hal.communication.log = () => undefined;
    }).toThrow(TypeError);
    expect(() => {
      (hal as unknown as { safety: unknown }).safety = {};
    }).toThrow(/assign it on the HAL itself/);
    expect(sim.communication.log).toBe(original);
    await hal.cleanup();
    await recorder.close();
    const recording = await readRecording(sink.bytes());
    expect(calls(recording).map((c) => c.call)).toEqual([
      'initialize',
      'isReady',
      'communication.setLED',
      'communication.log',
      'cleanup',
    ]);
  });

  it('records every call with its arguments, result, code and timing, and the pose after each motion', async () => {
    const recording = await recorded(async (hal) => {
      await hal.initialize();
      await hal.locomotion.moveForward(10);
      await hal.locomotion.rotate('left', 90);
      await hal.locomotion.moveForward(Number.NaN);
      await hal.locomotion.moveTo(0.1, 0.1, 0, undefined);
    });
    const list = calls(recording);
    expect(list.map((c) => c.call)).toEqual([
      'initialize',
      'locomotion.moveForward',
      'locomotion.rotate',
      'locomotion.moveForward',
      'locomotion.moveTo',
      'cleanup',
    ]);
    // an omitted optional argument is left out, so a replay calls it the same way
    expect(list[4]).toMatchObject({ args: [0.1, 0.1, 0], success: true });
    expect(list[1]).toMatchObject({ args: [10], outcome: 'resolved', success: true });
    expect(list[1]!.duration_ms).toBeGreaterThanOrEqual(0);
    expect(list[1]!.result).toMatchObject({ success: true, mode: 'simulation' });
    expect(list[3]).toMatchObject({ args: ['NaN'], success: false, code: 'INVALID_PARAMETER' });
    const poses = recording.messages.filter((m) => m.topic === TOPICS.halPose);
    const last = poses.at(-1)?.value as { position: { x: number; y: number } } | undefined;
    expect(last?.position.x).toBeCloseTo(0.1, 3);
    expect(last?.position.y).toBeCloseTo(0.1, 3);
    expect(recording.channels.get(TOPICS.pose)?.schemaName).toBe('foxglove.PoseInFrame');
    expect(recording.channels.get(TOPICS.tf)?.messageCount).toBe(poses.length);
    // after the left turn the base_link faces +y: yaw pi/2 is the quaternion (0, 0, sin 45, cos 45)
    const tf = recording.messages.filter((m) => m.topic === TOPICS.tf).at(-1)?.value as {
      rotation: { z: number; w: number };
    };
    expect(tf.rotation.z).toBeCloseTo(Math.SQRT1_2, 3);
    expect(recording.metadata.get('hal.robot')).toMatchObject({
      device_id: 'sim-rec',
      mode: 'simulation',
      map: '{"name":"empty"}',
      version: expect.stringMatching(/^\d+\.\d+\.\d+/),
    });
    expect(JSON.parse(recording.metadata.get('hal.robot')!['capabilities']!)).toContain(
      CAPABILITIES.camera,
    );
  });

  it('records the e-stop with its reason, the refused motion and the reset on /hal/safety', async () => {
    const recording = await recorded(async (hal) => {
      await hal.initialize();
      await hal.safety.emergencyStop('operator pressed the button');
      await hal.locomotion.moveForward(5);
      await hal.safety.resetEmergencyStop();
    });
    const events = recording.messages
      .filter((m) => m.topic === TOPICS.safety)
      .map((m) => m.value as SafetyEvent);
    expect(events).toEqual([
      {
        event: 'emergency_stop',
        reason: 'operator pressed the button',
        success: true,
        emergency_stopped: true,
      },
      { event: 'reset', success: true, emergency_stopped: false },
    ]);
    expect(calls(recording).find((c) => c.call === 'locomotion.moveForward')).toMatchObject({
      success: false,
      code: 'EMERGENCY_STOPPED',
    });
  });

  it('puts camera frames on /hal/camera as foxglove.CompressedImage and keeps the call record short', async () => {
    let frame = '';
    const recording = await recorded(async (hal) => {
      await hal.initialize();
      frame = await hal.vision.captureFrame();
    });
    const image = recording.messages.find((m) => m.topic === TOPICS.camera)?.value as {
      data: string;
      format: string;
    };
    expect(recording.channels.get(TOPICS.camera)?.schemaName).toBe('foxglove.CompressedImage');
    expect(image.format).toBe('jpeg');
    expect(`data:image/jpeg;base64,${image.data}`).toBe(frame);
    const record = calls(recording).find((c) => c.call === 'vision.captureFrame');
    expect(String(record?.result).length).toBeLessThan(200);
  });

  it('records a rejection with its code and passes the same error on, and keeps sync calls sync', async () => {
    let caught: unknown;
    let latched: unknown;
    const recording = await recorded(async (hal) => {
      caught = await hal.locomotion.getPose().catch((error: unknown) => error);
      latched = hal.safety.isEmergencyStopped();
      hal.communication.log('not ready yet', 'warn');
      await hal.initialize();
      hal.communication.log('hello from the robot', 'warn');
    });
    expect(caught).toBeInstanceOf(HalError);
    expect(latched).toBe(false);
    const list = calls(recording);
    expect(list[0]).toMatchObject({
      call: 'locomotion.getPose',
      outcome: 'rejected',
      success: false,
      code: 'NOT_READY',
    });
    expect(list[1]).toMatchObject({
      call: 'safety.isEmergencyStopped',
      outcome: 'returned',
      result: false,
    });
    const logs = recording.messages.filter((m) => m.topic === TOPICS.log).map((m) => m.value);
    expect(logs.at(-1)).toMatchObject({
      level: 3,
      message: 'hello from the robot',
      name: 'sim-rec',
    });
  });

  it('samples the pose at the set rate while ready, and sees a latch it did not cause', async () => {
    const sink = memorySink();
    const recorder = await McapRecorder.create(sink);
    const inner = new SimulationHAL({ clock: 'realtime', realtimeSpeed: 1 });
    const hal = recordHal(inner, recorder, { posePeriodMs: 20 });
    await hal.initialize();
    await new Promise((resolve) => setTimeout(resolve, 300));
    await inner.safety.emergencyStop('tripped behind the recorder');
    await new Promise((resolve) => setTimeout(resolve, 100));
    await hal.cleanup();
    await recorder.close();
    const recording = await readRecording(sink.bytes());
    expectWellFormed(recording);
    expect(recording.channels.get(TOPICS.pose)?.messageCount).toBeGreaterThan(5);
    const events = recording.messages.filter((m) => m.topic === TOPICS.safety).map((m) => m.value);
    expect(events).toEqual([{ event: 'latched', success: true, emergency_stopped: true }]);
  });

  it('waits at close for a pose sample still being read, so it is written, not dropped', async () => {
    const sink = memorySink();
    const recorder = await McapRecorder.create(sink);
    const inner = new SimulationHAL();
    const hal = recordHal(inner, recorder, { posePeriodMs: 0 });
    await hal.initialize();
    await recorder.drained();
    const before = recorder.stats().written;
    // a remote robot: a pose read takes a round trip
    const getPose = inner.locomotion.getPose.bind(inner.locomotion);
    inner.locomotion.getPose = async () => {
      await new Promise((resolve) => setTimeout(resolve, 50));
      return getPose();
    };
    // a motion's pose sample starts once its record is made; close right after that
    expect((await hal.communication.setLED(1, 2, 3, 'solid')).success).toBe(true);
    expect((await hal.locomotion.stop()).success).toBe(true);
    const stats = await recorder.close();
    expect(stats.written).toBeGreaterThan(before);
    const recording = await readRecording(sink.bytes());
    expectWellFormed(recording);
    // the pose initialize left and the sample as it became ready, the pose the stop left, and
    // the sample after the stop (started while the stop's record was made, during close)
    expect(recording.messages.filter((m) => m.topic === TOPICS.pose)).toHaveLength(4);
    // nothing came in after the file was closed, to be dropped there
    await new Promise((resolve) => setTimeout(resolve, 100));
    expect(recorder.stats().dropped).toBe(0);
    // a call after the close still answers its caller; its record is dropped and counted
    expect((await hal.communication.setLED(4, 5, 6, 'solid')).success).toBe(true);
    await expect.poll(() => recorder.stats().dropped, { timeout: 2000 }).toBe(1);
    await inner.cleanup();
  });

  it("records the step report a motion ended on, though the next motion's replaced it before the record was made", async () => {
    // a HAL that reports steps as PhysicalHAL does, its report set by the test
    const report = (steps: number) => ({
      leftSteps: steps,
      rightSteps: steps,
      leftStepsPerS: 0,
      rightStepsPerS: 0,
      robotUptimeMs: steps,
    });
    class ReportingSim extends SimulationHAL {
      current = report(0);
      reportedSteps(): ReturnType<typeof report> {
        return this.current;
      }
    }
    const inner = new ReportingSim({ deviceId: 'sim-steps' });
    const recording = await recorded(async (hal) => {
      await hal.initialize();
      inner.current = report(10);
      await hal.locomotion.moveForward(1);
      // the next motion's first reply lands before the record of the first is made
      inner.current = report(20);
      await hal.locomotion.moveForward(1);
    }, inner);
    const steps = recording.messages
      .filter((m) => m.topic === TOPICS.steps)
      .map((m) => (m.value as { left_steps: number }).left_steps);
    expect(steps).toEqual([10, 20]);
  });

  it('records calls answered out of order, and two robots sharing one recorder, each with its own', async () => {
    const one = new SimulationHAL({ deviceId: 'sim-a' });
    const two = new SimulationHAL({ deviceId: 'sim-b' });
    // setLED answers when the test says, with the red value it was given
    const answers: (() => void)[] = [];
    for (const sim of [one, two]) {
      sim.communication.setLED = (r: number) =>
        new Promise((resolve) => {
          answers[r] = () => resolve({ success: true, mode: 'simulation', r } as never);
        });
    }
    const sink = memorySink();
    const recorder = await McapRecorder.create(sink);
    const a = recordHal(one, recorder, { posePeriodMs: 0, namespace: 'a' });
    const b = recordHal(two, recorder, { posePeriodMs: 0, namespace: 'b' });
    const pending = [
      a.communication.setLED(1, 0, 0, 'solid'),
      b.communication.setLED(2, 0, 0, 'solid'),
      a.communication.setLED(3, 0, 0, 'solid'),
    ];
    // answered in the order 3, 2, 1
    for (const r of [3, 2, 1]) {
      answers[r]!();
      await pending[r - 1];
    }
    await recorder.close();
    const recording = await readRecording(sink.bytes());
    expectWellFormed(recording);
    const byTopic = (topic: string) =>
      recording.messages
        .filter((m) => m.topic === topic)
        .map((m) => m.value as HalCallRecord)
        .map((c) => [c.args[0], (c.result as { r?: number } | undefined)?.r]);
    // each record holds its own call's arguments and result, in the order the calls answered
    expect(byTopic('/a/hal/calls')).toEqual([
      [3, 3],
      [1, 1],
    ]);
    expect(byTopic('/b/hal/calls')).toEqual([[2, 2]]);
  });

  it('leaves the wrapped HAL untouched: the same results and its own properties', async () => {
    const inner = new SimulationHAL({ deviceId: 'same' });
    const hal = recordHal(inner, await McapRecorder.create(memorySink()), { posePeriodMs: 0 });
    expect(hal.mode).toBe('simulation');
    expect(hal.getDeviceInfo()).toEqual(inner.getDeviceInfo());
    expect(hal.robotConfig).toBe(inner.robotConfig);
    expect(hal.locomotion).toBe(hal.locomotion);
    await hal.initialize();
    expect(inner.isReady()).toBe(true);
    expect(await hal.locomotion.getPose()).toEqual(await inner.locomotion.getPose());
    await hal.cleanup();
  });

  it('keeps the robot moving and stopping as asked when the disk refuses every write, and counts the loss', async () => {
    const refusing: RecordingSink = {
      position: () => 0n,
      write: () => Promise.reject(new Error('EIO: i/o error')),
      close: () => Promise.resolve(),
    };
    const warnings: string[] = [];
    const recorder = await McapRecorder.create(refusing, {
      logger: { log: (level, _namespace, message) => level === 'warn' && warnings.push(message) },
    });
    const hal = recordHal(new SimulationHAL(), recorder, { posePeriodMs: 0 });
    await hal.initialize();
    expect(await hal.locomotion.moveForward(10)).toMatchObject({ success: true });
    expect(await hal.safety.emergencyStop('disk test')).toMatchObject({ success: true });
    expect(await hal.locomotion.moveForward(10)).toMatchObject({ code: 'EMERGENCY_STOPPED' });
    expect((await hal.locomotion.getPose()).position.x).toBeCloseTo(0.1, 3);
    await hal.cleanup();
    const stats = await recorder.close();
    expect(stats.failure).toContain('EIO');
    expect(stats.written).toBe(0);
    expect(stats.dropped).toBeGreaterThan(5);
    expect(warnings.join('\n')).toContain('EIO');
  });
});
