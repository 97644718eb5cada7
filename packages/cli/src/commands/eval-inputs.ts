// What `hal eval` reads from its options: the tasks, the sensors, the reality gap, the model
// settings, and the checks made before anything is loaded or run.
import { builtinTasks, EvalError, loadTaskFile, TASK_GROUPS } from '@hal/eval';
import type { RealityInput, Task, TaskGroup } from '@hal/eval';
import { CliError } from '../cli-error.js';
import type { EvalAgentOptions } from '../eval/eval-agents.js';
import type { EvalPlace } from '../eval/eval-robots.js';
import { checkOutputPlace } from '../output-place.js';
import type { EvalCliOptions } from './eval-options.js';

/** `--tasks a,b`: the task groups named (none: every group); USAGE on an unknown one. */
function groupList(text: string | undefined): TaskGroup[] {
  if (text === undefined) return [];
  const groups = text
    .split(',')
    .map((g) => g.trim())
    .filter((g) => g !== '');
  for (const g of groups) {
    if (!(TASK_GROUPS as readonly string[]).includes(g))
      throw new CliError('USAGE', `"--tasks": unknown group "${g}" (${TASK_GROUPS.join(', ')})`);
  }
  return groups as TaskGroup[];
}

const SENSORS = { camera: 'camera', range: 'rangeSensors', imu: 'imu' } as const;

/** `--sensors camera,range`: the sensors every task's robot has (the others are off). */
export function sensorSet(text: string): { camera: boolean; rangeSensors: boolean; imu: boolean } {
  const names = text
    .split(',')
    .map((n) => n.trim())
    .filter((n) => n !== '' && n !== 'none');
  for (const n of names) {
    if (!(n in SENSORS))
      throw new CliError(
        'USAGE',
        `"--sensors": unknown sensor "${n}" (camera, range, imu, or none)`,
      );
  }
  return {
    camera: names.includes('camera'),
    rangeSensors: names.includes('range'),
    imu: names.includes('imu'),
  };
}

/** The tasks of the run: built-in or `--tasks-file`, of the `--tasks` groups; USAGE when none. */
export async function chooseTasks(options: EvalCliOptions): Promise<Task[]> {
  const groups = groupList(options.tasks);
  let tasks: Task[];
  try {
    tasks =
      options.tasksFile === undefined ? builtinTasks() : await loadTaskFile(options.tasksFile);
  } catch (error) {
    if (error instanceof EvalError) throw new CliError('FAILED', `${error.code}: ${error.message}`);
    throw error;
  }
  const chosen = groups.length === 0 ? tasks : tasks.filter((t) => groups.includes(t.group));
  if (chosen.length === 0)
    throw new CliError('USAGE', `no task in the groups ${groups.join(', ')}`);
  return chosen;
}

/**
 * Refuses options that need a robot the run has none of, and a `--out` or `--record` folder
 * that cannot be written: before any model is loaded or trial run.
 */
export async function checkEvalPlaces(
  options: EvalCliOptions,
  places: readonly EvalPlace[],
): Promise<void> {
  const robotNamed = places.some((p) => p.kind !== 'sim');
  if (!robotNamed && options.timeScale !== undefined)
    throw new CliError('USAGE', '"--time-scale" needs a robot: --on emulator or udp://...');
  if (!places.some((p) => p.kind === 'udp') && options.key !== undefined)
    throw new CliError('USAGE', '"--key" needs a robot --on udp://...');
  // the folders written to are checked before any model is loaded or trial run
  const overwrite = options.overwrite === true;
  if (options.out !== undefined)
    await checkOutputPlace({ option: '--out', path: options.out, kind: 'folder', overwrite });
  if (options.record !== undefined)
    await checkOutputPlace({
      option: '--record',
      path: options.record,
      kind: 'folder',
      overwrite,
    });
}

/** The simulator's reality gap, from the options given (none: an empty object). */
export function realityOf(options: EvalCliOptions): RealityInput {
  return {
    ...(options.latency === undefined ? {} : { latencyMs: options.latency }),
    ...(options.loss === undefined ? {} : { lossRate: options.loss }),
    ...(options.rangeNoise === undefined ? {} : { rangeNoiseM: options.rangeNoise }),
    ...(options.wheelDiameterError === undefined
      ? {}
      : { wheelDiameterErrorPct: options.wheelDiameterError }),
    ...(options.wheelSlip === undefined ? {} : { wheelSlipPct: options.wheelSlip }),
    ...(options.odometryNoise === undefined ? {} : { odometryNoisePct: options.odometryNoise }),
  };
}

/** The model agents' settings, from the options given. */
export function agentSettingsOf(options: EvalCliOptions): EvalAgentOptions {
  return {
    ...(options.modelFile === undefined ? {} : { modelFile: options.modelFile }),
    ...(options.baseUrl === undefined ? {} : { baseUrl: options.baseUrl }),
    ...(options.systemPrompt === undefined ? {} : { systemPrompt: options.systemPrompt }),
    ...(options.temperature === undefined ? {} : { temperature: options.temperature }),
    ...(options.maxSteps === undefined ? {} : { maxSteps: options.maxSteps }),
    ...(options.threads === undefined ? {} : { threads: options.threads }),
  };
}
