import { PhysicalHAL } from '@hal/physical';
import { MockRobot } from '@hal/physical/testing';
import { SimulationHAL } from '@hal/simulation';
import { HalBoundary, V1_ROBOT } from '@hal/types';
import type { CallName, HardwareAbstractionLayer, RobotConfig } from '@hal/types';
import { Ajv2020 } from 'ajv/dist/2020.js';
import { describe, expect, it } from 'vitest';
import { TOOL_CATALOG } from './catalog.js';
import { robotConfigOf } from './robot-config.js';
import { halTools } from './tools.js';

/**
 * JSON-representable samples per call, valid and invalid; each side decides which is which. The
 * type asks for every call of the table.
 */
const SAMPLES: Record<CallName, unknown[]> = {
  moveForward: [
    { distanceCm: 10 },
    { distanceCm: 188.4 },
    { distanceCm: 188.5 },
    { distanceCm: 0 },
    { distanceCm: -5 },
    { distanceCm: '10' },
    {},
    { distanceCm: 10, extra: true },
    null,
    [],
  ],
  moveBackward: [
    { distanceCm: 0.01 },
    { distanceCm: 500 },
    { distanceCm: 0 },
    { distanceCm: true },
    {},
  ],
  rotate: [
    { direction: 'left', degrees: 90 },
    { direction: 'right', degrees: 1078 },
    { direction: 'right', degrees: 1079.5 },
    { direction: 'up', degrees: 90 },
    { direction: 'left', degrees: 0 },
    { direction: 'left' },
    { degrees: 90 },
  ],
  moveTo: [
    { x: 1, y: 2, z: 0 },
    { x: 1, y: 2, z: 0, speed: 0.02 },
    { x: 1, y: 2, z: 0, speed: 1 },
    { x: 1, y: 2, z: 0, speed: 0.001 },
    { x: 51, y: 0, z: 0 },
    { x: -50, y: 50, z: 3 },
    { x: 1, y: 2 },
    { x: '1', y: 2, z: 0 },
  ],
  drive: [
    { left: 100, right: -100 },
    { left: 255, right: 255, durationMs: 1000 },
    { left: 256, right: 0 },
    { left: 0, right: 0, durationMs: 0 },
    { left: 0, right: 0, durationMs: 60_000 },
    { left: 0, right: 0, durationMs: 60_001 },
    { left: 0 },
  ],
  stop: [{}, { extra: 1 }, null, 'stop'],
  emergencyStop: [
    {},
    { reason: 'obstacle' },
    { reason: 'x'.repeat(200) },
    { reason: 'x'.repeat(201) },
    { reason: 5 },
    { reason: '\u0000\r\n' },
    { reason: null },
  ],
  resetEmergencyStop: [{}, 7],
  getPose: [{}, []],
  captureFrame: [{}, 'frame'],
  getDistanceSensors: [{}, 1],
  scan: [
    {},
    { mode: 'full' },
    { mode: 'targeted' },
    { mode: 'quick' },
    { mode: 'bogus' },
    { mode: 1 },
  ],
  getLineSensors: [{}, false],
  getIMU: [{}, null],
  getSafetyStatus: [{}, 'x'],
  isEmergencyStopped: [{}, 0],
  setLED: [
    { r: 0, g: 128, b: 255 },
    { r: 0, g: 0, b: 0, pattern: 'blink' },
    { r: 256, g: 0, b: 0 },
    { r: 1.5, g: 0, b: 0 },
    { r: -1, g: 0, b: 0 },
    { r: 0, g: 0, b: 0, pattern: 'disco' },
    { r: 0, g: 0 },
  ],
  speak: [
    { text: 'hello' },
    { text: 'hi', urgency: 'alert' },
    { text: '' },
    { text: 'x'.repeat(501) },
    { text: 'hi', urgency: 'shout' },
    {},
  ],
  playSound: [{ soundId: 'beep' }, { soundId: '' }, { soundId: 'x'.repeat(101) }, { soundId: 3 }],
  log: [
    { message: 'hello' },
    { message: 'x', level: 'warn' },
    { message: 'x'.repeat(2001) },
    { message: 'x', level: 'loud' },
    {},
  ],
};

function halAccepts(config: RobotConfig, call: CallName, args: unknown): boolean {
  const boundary = new HalBoundary({
    mode: 'simulation',
    config: () => config,
    isEmergencyStopped: () => false,
    isReady: () => true,
  });
  try {
    boundary.validate(call, args);
    return true;
  } catch {
    return false;
  }
}

function checkParity(hal: HardwareAbstractionLayer) {
  const ajv = new Ajv2020({ strict: false });
  const config = robotConfigOf(hal);
  for (const tool of halTools(hal)) {
    const samples = SAMPLES[tool.call];
    expect(samples, `samples for ${tool.call}`).toBeDefined();
    const check = ajv.compile(tool.inputSchema);
    const verdicts = (samples ?? []).map((sample) => {
      const hal = halAccepts(config, tool.call as CallName, sample);
      const what = `${tool.name} ${JSON.stringify(sample)?.slice(0, 60)}`;
      if (tool.safety === 'estop') {
        // the HAL takes any e-stop; the schema only guides the model (a text reason)
        expect(hal, `${what}: the HAL refused an e-stop`).toBe(true);
        if (check(sample)) expect(hal, what).toBe(true);
      } else {
        expect(check(sample), `${what}: the tool schema and the HAL disagree`).toBe(hal);
      }
      return hal;
    });
    expect(verdicts, `${tool.name}: the samples include an accepted one`).toContain(true);
    // the e-stop is never refused for its argument: every sample must be accepted, on both sides
    if (tool.safety === 'estop') expect(verdicts, tool.name).not.toContain(false);
    else expect(verdicts, `${tool.name}: the samples include a refused one`).toContain(false);
  }
}

describe('tool schemas against the HAL validation', () => {
  it('has samples for every call in the catalog', () => {
    for (const entry of TOOL_CATALOG) expect(Object.keys(SAMPLES)).toContain(entry.call);
  });

  it('accepts exactly what the HAL accepts, for every tool of a simulated robot with every feature', async () => {
    const hal = new SimulationHAL({ features: { speaker: true } });
    await hal.initialize();
    expect(halTools(hal)).toHaveLength(TOOL_CATALOG.length - 1); // no line sensors in the simulator
    checkParity(hal);
    await hal.cleanup();
  });

  it('accepts exactly what the HAL accepts for a robot with other limits', async () => {
    const hal = new SimulationHAL({
      robot: { maxStepsPerCommand: 20_000, maxDriveDurationMs: 90_000 },
    });
    await hal.initialize();
    expect(robotConfigOf(hal)).not.toEqual(V1_ROBOT);
    checkParity(hal);
    await hal.cleanup();
  });

  it('accepts exactly what a PhysicalHAL accepts, with the limits the robot reported', async () => {
    const robot = new MockRobot({ timeScale: 50, hostTimeoutMs: 10_000 });
    const hal = new PhysicalHAL(
      { mode: 'physical', deviceId: 'cube-1' },
      { transport: robot.transport(), timeScale: 50 },
    );
    await hal.initialize();
    checkParity(hal);
    // the HAL's own answer agrees with its boundary for a refused and an accepted sample
    expect((await hal.locomotion.moveForward(500)).code).toBe('RANGE_EXCEEDED');
    expect((await hal.locomotion.moveForward(1)).success).toBe(true);
    await hal.cleanup();
  });
});
