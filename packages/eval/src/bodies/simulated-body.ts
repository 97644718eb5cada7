import type { SimulationHAL } from '@hal/simulation';
import type { TrialBody } from './trial-body.js';

/** The simulator's ground truth: where the world has the robot, whatever its odometry says. */
export function simulatedBody(hal: SimulationHAL): TrialBody {
  const robot = () => hal.robot;
  const steps = () => robot().leftSteps + robot().rightSteps;
  return {
    source: 'truth',
    pose: () => ({ x: robot().x, y: robot().y, yaw: robot().yaw }),
    around: async (run) => {
      const before = steps();
      const result = await run();
      // from the wheels' steps: a turn on the spot moves the centre nowhere
      return { result, pathM: (Math.abs(steps() - before) / 2) * robot().stepLengthM };
    },
    nowUs: () => hal.world.nowUs,
    delay: (ms) => {
      hal.world.advance(ms * 1000);
      return Promise.resolve();
    },
    emergencyStopped: () => robot().emergencyStopped,
  };
}
