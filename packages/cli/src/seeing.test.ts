import { SimulationHAL, World } from '@hal/simulation';
import { afterEach, describe, expect, it } from 'vitest';
import { seeingFrom } from './seeing.js';

let hal: SimulationHAL | undefined;
afterEach(async () => {
  await hal?.cleanup();
  hal = undefined;
});

async function robot(camera: boolean): Promise<SimulationHAL> {
  const world = new World({
    map: {
      name: 'one box',
      obstacles: [
        { kind: 'box', x: 0.9, y: 0, width: 0.3, depth: 0.3, height: 0.3, color: '#7b2cbf' },
      ],
    },
  });
  hal = new SimulationHAL({ world, features: { camera } });
  await hal.initialize();
  return hal;
}

describe('seeingFrom', () => {
  it("answers scan with the range sensors and the camera's look, for a robot with a camera", async () => {
    const sim = await robot(true);
    const { hal: seeing, perception } = seeingFrom(sim, sim, undefined, { kind: 'sim' });
    expect(perception).toBeDefined();
    const scan = await seeing.vision.scan();
    expect(scan.objects.filter((o) => o.sensor === 'camera').map((o) => o.id)).toEqual([
      'purple box 1',
    ]);
    expect(scan.objects.some((o) => o.sensor === 'range')).toBe(true);
  });

  it('leaves a robot without a camera, and one served elsewhere, as they are', async () => {
    const blind = await robot(false);
    expect(seeingFrom(blind, blind, undefined).hal).toBe(blind);
    await blind.cleanup();
    const sim = await robot(true);
    expect(seeingFrom(sim, sim, undefined, { kind: 'ws' }).hal).toBe(sim);
  });
});
