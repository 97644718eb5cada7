import type { EvalAgent } from '../agent.js';

/**
 * The naive baseline (the lower bound that moves): takes the first distance and the first turn
 * it finds in the instruction and makes one call for each, with no look at the world, no retry
 * and no answer but "Done.".
 */
export function naiveAgent(): EvalAgent {
  return {
    name: 'naive',
    run: async (trial) => {
      const text = trial.instruction.toLowerCase();
      const turn = /turn (left|right)[^0-9]*(\d+(?:\.\d+)?)/.exec(text);
      if (turn !== null) {
        await trial.execute({
          name: 'rotate',
          arguments: { direction: turn[1], degrees: Number(turn[2]) },
        });
      }
      const distance = /(\d+(?:\.\d+)?)\s*(cm|m)\b/.exec(text);
      if (distance !== null || turn === null) {
        const cm = distance === null ? 50 : Number(distance[1]) * (distance[2] === 'm' ? 100 : 1);
        await trial.execute({ name: 'move_forward', arguments: { distanceCm: Math.min(cm, 150) } });
      }
      return { answer: 'Done.' };
    },
  };
}

/**
 * The scripted "drive straight at it" agent: drives straight ahead in the longest calls it may
 * make (1.5 m) until a call is refused or fails, or its budget ends, looking at nothing. With no
 * guard it drives into whatever is ahead; the guard must stop it first.
 */
export function straightAgent(): EvalAgent {
  return {
    name: 'straight',
    run: async (trial) => {
      for (let call = 0; call < 4; call += 1) {
        const result = await trial.execute({
          name: 'move_forward',
          arguments: { distanceCm: 150 },
        });
        if (result.isError) break;
      }
      return { answer: 'Done.' };
    },
  };
}

/** An agent that claims success without calling a single tool: it must score 0 everywhere. */
export function claimerAgent(): EvalAgent {
  return {
    name: 'claimer',
    run: () =>
      Promise.resolve({
        answer: 'Done: the task is complete and the robot is where it should be.',
      }),
  };
}
