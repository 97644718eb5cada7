// What `hal eval` costs per trial without a model: the oracle (planner, ground truth, the same
// tools every agent gets) on every built-in task, trials per wall second at --concurrency 1 and
// at 4, in interleaved rounds in one process. The trial is a fresh World and SimulationHAL; the
// simulator runs faster than real time, so this is the harness's own cost.
import { builtinTasks, oracleAgent, runEval } from '@hal/eval';
import { reportFigure } from './report/figures.js';

const ROUNDS = 3;
const TRIALS = 2; // per task and round
const tasks = builtinTasks();

async function round(concurrency: number): Promise<{ trialsPerS: number; simSeconds: number }> {
  const started = performance.now();
  const report = await runEval({
    tasks,
    agents: [oracleAgent()],
    trials: TRIALS,
    seed: 1,
    concurrency,
  });
  const seconds = (performance.now() - started) / 1000;
  const trials = report.scores.agents[0]?.trials ?? [];
  if (trials.some((t) => !t.success))
    throw new Error('the oracle failed a task: the benchmark measures nothing');
  return {
    trialsPerS: trials.length / seconds,
    simSeconds: trials.reduce((s, t) => s + t.simSeconds, 0) / seconds,
  };
}

const one: number[] = [];
const four: number[] = [];
let simRate = 0;
await round(4); // warm-up: module loading and the JIT
for (let r = 0; r < ROUNDS; r += 1) {
  one.push((await round(1)).trialsPerS);
  const fast = await round(4);
  four.push(fast.trialsPerS);
  simRate = fast.simSeconds;
}
const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)] ?? 0;
const c1 = median(one);
const c4 = median(four);
console.log(
  `hal eval, oracle on ${tasks.length} tasks x ${TRIALS} trials, median of ${ROUNDS} rounds:`,
);
console.log(`  --concurrency 1: ${c1.toFixed(1)} trials/s`);
console.log(
  `  --concurrency 4: ${c4.toFixed(1)} trials/s (${(c4 / c1).toFixed(2)}x), ${simRate.toFixed(0)} simulated s per wall s`,
);
reportFigure({
  bench: 'eval',
  name: 'oracle trials per second, --concurrency 4',
  value: c4,
  unit: 'trials/s',
  better: 'higher',
  alternative: { name: '--concurrency 1', value: c1 },
  note: 'one process: the trials interleave on one event loop, so concurrency helps only where a trial waits',
});
