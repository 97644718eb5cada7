import { describe, expect, it } from 'vitest';
import { SimulationHAL } from '@hal/simulation';
import { parseFleetCommand, runFleetCommand } from './commands.js';

describe('fleet commands', () => {
  it('accepts each command kind and runs it through the HAL', async () => {
    const hal = new SimulationHAL();
    await hal.initialize();
    const forward = await runFleetCommand(
      hal,
      parseFleetCommand({ kind: 'moveForward', distanceCm: 2 }),
    );
    expect(forward.success).toBe(true);
    expect((await hal.locomotion.getPose()).position.x).toBeCloseTo(0.02, 3);
    const to = await runFleetCommand(hal, parseFleetCommand({ kind: 'moveTo', x: 0.05, y: 0 }));
    expect(to.success).toBe(true);
    expect((await hal.locomotion.getPose()).position.x).toBeCloseTo(0.05, 3);
    expect((await runFleetCommand(hal, { kind: 'setLED', r: 1, g: 2, b: 3 })).success).toBe(true);
    expect(hal.robot.led).toMatchObject({ r: 1, g: 2, b: 3 });
  });

  it('refuses a malformed command with INVALID_PARAMETER naming the field', () => {
    expect(() => parseFleetCommand({ kind: 'rotate', direction: 'up', degrees: 10 })).toThrow(
      /direction/,
    );
    expect(() => parseFleetCommand({ kind: 'moveForward', distanceCm: Infinity })).toThrow(
      /distanceCm/,
    );
    expect(() => parseFleetCommand('stop')).toThrow(/not a fleet command/);
  });
});
