import { z } from 'zod';

/** Which world a HAL drives: a simulated robot, the physical robot, or both at once. */
export const HALModeSchema = z
  .enum(['simulation', 'physical', 'hybrid'])
  .describe(
    'simulation: the simulated robot; physical: the real robot; hybrid: both, physical is the truth',
  );

/** Which world a HAL drives. */
export type HALMode = z.infer<typeof HALModeSchema>;
