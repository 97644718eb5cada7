import { runFleetCommand } from '@hal/fleet';
import { SimulationHAL } from '@hal/simulation';
import { describe, expect, it } from 'vitest';
import { describeCommand, panelCommand } from './panel-commands.js';

async function afterCommand(name: Parameters<typeof panelCommand>[0], amount: number) {
  const hal = new SimulationHAL();
  await hal.initialize();
  try {
    const result = await runFleetCommand(hal, panelCommand(name, amount));
    const pose = await hal.locomotion.getPose();
    return { result, x: pose.position.x, yaw: pose.rotation.yaw };
  } finally {
    await hal.cleanup();
  }
}

describe('the Fleet card commands', () => {
  it('drive a robot forward and backward by the amount in cm', async () => {
    const ahead = await afterCommand('forward', 20);
    expect(ahead.result.success).toBe(true);
    expect(ahead.x).toBeCloseTo(0.2, 2);
    const back = await afterCommand('backward', 20);
    expect(back.result.success).toBe(true);
    expect(back.x).toBeCloseTo(-0.2, 2);
  });

  it('turn a robot left and right by the amount in degrees', async () => {
    expect((await afterCommand('left', 90)).yaw).toBeCloseTo(Math.PI / 2, 2);
    expect((await afterCommand('right', 90)).yaw).toBeCloseTo(-Math.PI / 2, 2);
  });

  it('describe a command with its label, amount and unit', () => {
    expect(describeCommand('backward', 20)).toBe('Backward 20 cm');
  });
});
