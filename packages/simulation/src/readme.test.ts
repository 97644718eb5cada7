import { describe, expect, it } from 'vitest';
import { SimulationHAL, World } from './index.js';

describe('the README example', () => {
  it('moves, senses, sees and bumps into the box ahead', async () => {
    const world = new World({ map: 'obstacles', seed: 1 });
    const hal = new SimulationHAL({ world });
    await hal.initialize();

    const moved = await hal.locomotion.moveForward(20);
    const pose = await hal.locomotion.getPose();
    const ranges = await hal.vision.getDistanceSensors();
    const frame = await hal.vision.captureFrame();
    const bump = await hal.locomotion.moveForward(60);
    await hal.cleanup();

    expect(moved.success).toBe(true);
    expect(pose.position.x).toBeCloseTo(-1.6, 3);
    expect(ranges.source).toBe('simulation');
    expect(ranges.front).toBeCloseTo(0.43, 2);
    expect(frame.startsWith('data:image/jpeg;base64,')).toBe(true);
    expect([bump.success, bump.code]).toEqual([false, 'COLLISION']);
  });
});
