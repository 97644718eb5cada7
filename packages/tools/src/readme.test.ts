import { SimulationHAL } from '@hal/simulation';
import { expect, it } from 'vitest';
import { createToolExecutor, halTools, toOpenAITools } from './index.js';

it('README: an LLM is given the tools, moves the robot, and is held back by the leash', async () => {
  const hal = new SimulationHAL();
  await hal.initialize();

  const tools = toOpenAITools(halTools(hal));
  const executor = createToolExecutor(hal, {
    leash: { maxDistanceM: 0.5, geofence: { minX: -1, maxX: 1, minY: -1, maxY: 1 } },
  });

  const result = await executor.execute({ name: 'move_forward', arguments: '{"distanceCm": 20}' });
  expect(tools.map((t) => t.function.name)).toContain('move_forward');
  expect(result).toMatchObject({ isError: false, content: [{ type: 'text' }] });
  expect(result.structured).toMatchObject({ success: true });

  const refused = await executor.execute({ name: 'move_forward', arguments: '{"distanceCm": 90}' });
  expect(refused).toMatchObject({ isError: true, code: 'LEASH_DISTANCE' });
  expect(refused.content[0]).toMatchObject({
    text: expect.stringContaining('would travel 0.9 m; the leash allows at most 0.5 m per call'),
  });
  expect((await hal.locomotion.getPose()).position.x).toBeCloseTo(0.2, 2);
});
