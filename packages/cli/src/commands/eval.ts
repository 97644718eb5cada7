// `hal eval`: scores agents on the seeded tasks of @hal/eval in the simulator: the oracle, the
// baselines, the local model, any OpenAI-compatible endpoint. Progress on stderr, the table (or
// with --json the report) on stdout, the reports in --out, and --min-success fails a CI run.
import { Command, Option } from 'commander';
import {
  builtinTasks,
  EvalError,
  loadTaskFile,
  runEval,
  summaryTable,
  TASK_GROUPS,
} from '@hal/eval';
import type { EvalReport, Task, TaskGroup } from '@hal/eval';
import { toolsChoice } from '../tools-option.js';
import { addGuardOptions, guardSettingsFromOptions } from '../guard-options.js';
import type { GuardCliOptions } from '../guard-options.js';
import { addLeashOptions, leashFromOptions } from '../leash-options.js';
import type { LeashCliOptions } from '../leash-options.js';
import { distanceArg, hexKeyArg, integerArg, numberArg, positiveArg, urlArg } from '../values.js';
import { CliError } from '../cli-error.js';
import { agentNames, buildAgents } from '../eval/eval-agents.js';
import { checkTasks, checkTasksText } from '../eval/check-tasks.js';
import { openPlaces, parsePlaces } from '../eval/eval-robots.js';
import { recordTrials } from '../eval/record-trials.js';
import { writeReports } from '../eval/write-reports.js';
import { emit, progress } from '../io.js';
import { cliLogger } from '../logger.js';
import { modelFailureError, trialVerdict } from '../eval/model-failures.js';
import { checkOutputPlace } from '../output-place.js';
import type { RegisterCommand } from './context.js';

interface EvalCliOptions extends LeashCliOptions, GuardCliOptions {
  on: string;
  record?: string;
  timeScale?: number;
  key?: string;
  latency?: number;
  loss?: number;
  rangeNoise?: number;
  wheelDiameterError?: number;
  wheelSlip?: number;
  odometryNoise?: number;
  sensors?: string;
  agent: string;
  tasks?: string;
  tasksFile?: string;
  trials: number;
  seed: number;
  concurrency: number;
  out?: string;
  overwrite?: boolean;
  minSuccess?: number;
  tools?: string;
  systemPrompt?: string;
  modelFile?: string;
  baseUrl?: string;
  temperature?: number;
  maxSteps?: number;
  threads?: number;
  checkTasks?: boolean;
}

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
function sensorSet(text: string): { camera: boolean; rangeSensors: boolean; imu: boolean } {
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

async function chooseTasks(options: EvalCliOptions): Promise<Task[]> {
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

/** A bar of `width` characters, `done` of `total` filled. */
function bar(done: number, total: number, width = 20): string {
  const filled = Math.round((done / total) * width);
  return `[${'#'.repeat(filled)}${'.'.repeat(width - filled)}]`;
}

export const registerEval: RegisterCommand = (program, { io, global }) => {
  program.addCommand(
    addGuardOptions(addLeashOptions(new Command('eval')))
      .description(
        'score agents on seeded tasks in the simulator, from its ground truth, and on a robot from its reports (oracle, naive, claimer, straight, parser, nav, nav-camera, the local model, openai:MODEL)',
      )
      .addOption(
        new Option(
          '--agent <names>',
          'agents, comma-separated: oracle, naive, claimer, straight, parser, nav, nav-camera, local, openai:MODEL',
        ).default('oracle,naive'),
      )
      .addOption(
        new Option(
          '--tasks <groups>',
          `task groups, comma-separated (default all: ${TASK_GROUPS.join(', ')})`,
        ),
      )
      .addOption(
        new Option(
          '--tasks-file <path>',
          'a task file (JSON, see docs/eval.md) instead of the built-in tasks',
        ),
      )
      .addOption(
        new Option('--trials <k>', 'trials per task, seeds seed..seed+k-1')
          .default(5)
          .argParser(integerArg('--trials', 1, 1000)),
      )
      .addOption(
        new Option('--seed <n>', 'the first seed')
          .default(1)
          .argParser(integerArg('--seed', 0, 2 ** 31 - 1)),
      )
      .addOption(
        new Option('--concurrency <n>', 'trials at once (the local model runs one at a time)')
          .default(1)
          .argParser(integerArg('--concurrency', 1, 64)),
      )
      .addOption(
        new Option(
          '--on <places>',
          "where to run, comma-separated: sim, emulator (a cube-emulator started for the run, put into each task's world with its camera: every task), udp://HOST[:PORT] (the tasks judged from its reports: precision)",
        ).default('sim'),
      )
      .addOption(
        new Option(
          '--time-scale <x>',
          "the robot's clock speed-up: the emulator is started with it, a udp:// emulator runs at it",
        ).argParser(positiveArg('--time-scale')),
      )
      .addOption(
        new Option('--key <hex>', "a udp:// robot's pre-shared key").argParser(hexKeyArg('--key')),
      )
      .addOption(
        new Option(
          '--out <dir>',
          'write eval.json, eval.md and eval.svg into this folder (new or empty, unless --overwrite)',
        ),
      )
      .addOption(
        new Option(
          '--record <dir>',
          'keep every trial as an MCAP recording: DIR/AGENT/GROUP/TASK/seed-S-trial-I.mcap (DIR new or empty, unless --overwrite)',
        ),
      )
      .addOption(
        new Option(
          '--overwrite',
          'write into a --out or --record folder that is not empty, replacing its files',
        ),
      )
      .addOption(
        new Option(
          '--min-success <rate>',
          'exit 1 when an agent succeeds on less than this fraction of trials (0..1)',
        ).argParser(numberArg('--min-success', { min: 0, max: 1 })),
      )
      .addOption(
        new Option(
          '--tools <profile|names>',
          "the tools every agent is offered: a profile, skills, primitives or all (default each agent's own: parser and local skills, the others primitives), or only these HAL tools, comma-separated",
        ),
      )
      .addOption(new Option('--system-prompt <text>', "replaces the model agents' system prompt"))
      .addOption(
        new Option(
          '--model-file <path>',
          'the GGUF file of the local agent (default: SmolLM2-135M, fetched by hal model pull)',
        ),
      )
      .addOption(
        new Option(
          '--base-url <url>',
          "the openai: agents' endpoint, up to /v1 (default $OPENAI_BASE_URL, else OpenAI; key from $OPENAI_API_KEY)",
        ).argParser(urlArg('--base-url', ['http:', 'https:'])),
      )
      .addOption(
        new Option('--temperature <t>', 'sampling temperature of the model agents').argParser(
          numberArg('--temperature', { min: 0, max: 2 }),
        ),
      )
      .addOption(
        new Option('--max-steps <n>', 'most model requests per trial').argParser(
          integerArg('--max-steps', 1, 200),
        ),
      )
      .addOption(
        new Option('--threads <n>', 'CPU threads of the local model').argParser(
          integerArg('--threads', 1, 256),
        ),
      )
      .addOption(
        new Option(
          '--sensors <names>',
          "the robot's sensors in every task: camera, range, imu, comma-separated, or none (default: each task's)",
        ),
      )
      .addOption(
        new Option(
          '--check-tasks',
          'run only the oracle, in the simulator, over --trials seeds of every task, and list the tasks and seeds it cannot solve (exit 1 if any)',
        ),
      )
      .addOption(
        new Option(
          '--latency <ms>',
          'reality: simulated latency added to every call, ms',
        ).argParser(numberArg('--latency', { min: 0, max: 10_000 }, 'ms')),
      )
      .addOption(
        new Option(
          '--loss <rate>',
          'reality: chance a call is lost (answers TIMEOUT), 0..0.9, seeded',
        ).argParser(numberArg('--loss', { min: 0, max: 0.9 })),
      )
      .addOption(
        new Option(
          '--range-noise <distance>',
          'reality: range sensor noise, standard deviation (metres, or 2cm)',
        ).argParser(distanceArg('--range-noise', { min: 0, max: 1 })),
      )
      .addOption(
        new Option(
          '--wheel-diameter-error <pct>',
          "reality: each wheel's true diameter off the nominal, standard deviation in percent, seeded",
        ).argParser(numberArg('--wheel-diameter-error', { min: 0, max: 20 }, '%')),
      )
      .addOption(
        new Option(
          '--wheel-slip <pct>',
          'reality: most travel a wheel loses to slip per motion, percent, seeded',
        ).argParser(numberArg('--wheel-slip', { min: 0, max: 50 }, '%')),
      )
      .addOption(
        new Option(
          '--odometry-noise <pct>',
          "reality: the odometry's error on each wheel's travel per motion, standard deviation in percent, seeded",
        ).argParser(numberArg('--odometry-noise', { min: 0, max: 20 }, '%')),
      )
      .action(async (options: EvalCliOptions) => {
        const g = global();
        const names = agentNames(options.agent);
        const places = parsePlaces(options.on);
        const chosen = toolsChoice(options.tools);
        const profile = chosen !== undefined && 'profile' in chosen ? chosen.profile : undefined;
        const tools = chosen !== undefined && 'names' in chosen ? [...chosen.names] : undefined;
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
        const tasks = await chooseTasks(options);
        if (options.checkTasks === true) {
          progress(
            io,
            g,
            `checking ${tasks.length} task(s) with the oracle on ${options.trials} seed(s) each, from seed ${options.seed}`,
          );
          const unsolved = await checkTasks(tasks, {
            trials: options.trials,
            seed: options.seed,
            concurrency: options.concurrency,
            onTrial: (score, done, total) =>
              progress(
                io,
                g,
                `${bar(done, total)} ${done}/${total} ${score.task} seed ${score.seed}: ${trialVerdict(score)}`,
              ),
          });
          emit(io, g, { unsolved }, () => checkTasksText(unsolved, tasks.length, options.trials));
          if (unsolved.length > 0)
            throw new CliError(
              'FAILED',
              `the oracle could not solve ${unsolved.length} trial(s): fix those tasks (a task the oracle cannot solve scores every agent 0 for no fault of its own)`,
            );
          return;
        }
        const sensors = options.sensors === undefined ? undefined : sensorSet(options.sensors);
        const leash = leashFromOptions(options);
        const guard = guardSettingsFromOptions(options) ?? false;
        const reality = {
          ...(options.latency === undefined ? {} : { latencyMs: options.latency }),
          ...(options.loss === undefined ? {} : { lossRate: options.loss }),
          ...(options.rangeNoise === undefined ? {} : { rangeNoiseM: options.rangeNoise }),
          ...(options.wheelDiameterError === undefined
            ? {}
            : { wheelDiameterErrorPct: options.wheelDiameterError }),
          ...(options.wheelSlip === undefined ? {} : { wheelSlipPct: options.wheelSlip }),
          ...(options.odometryNoise === undefined
            ? {}
            : { odometryNoisePct: options.odometryNoise }),
        };
        if (names.includes('local')) progress(io, g, 'loading the local model...');
        const built = await buildAgents(
          names,
          {
            ...(options.modelFile === undefined ? {} : { modelFile: options.modelFile }),
            ...(options.baseUrl === undefined ? {} : { baseUrl: options.baseUrl }),
            ...(options.systemPrompt === undefined ? {} : { systemPrompt: options.systemPrompt }),
            ...(options.temperature === undefined ? {} : { temperature: options.temperature }),
            ...(options.maxSteps === undefined ? {} : { maxSteps: options.maxSteps }),
            ...(options.threads === undefined ? {} : { threads: options.threads }),
          },
          io.env,
          cliLogger(io, g.json),
        );
        let report: EvalReport;
        let opened: Awaited<ReturnType<typeof openPlaces>> | undefined;
        const recording = options.record === undefined ? undefined : recordTrials(options.record);
        try {
          opened = await openPlaces(places, {
            ...(options.timeScale === undefined ? {} : { timeScale: options.timeScale }),
            ...(options.key === undefined ? {} : { key: options.key }),
            env: io.env,
            signal: io.signal,
            onBuild: (dir) => progress(io, g, `building cube-emulator in ${dir} (if needed)...`),
          });
          const concurrency = built.local ? 1 : options.concurrency;
          progress(
            io,
            g,
            `${names.join(', ')}: ${tasks.length} task(s) x ${options.trials} trial(s), seed ${options.seed}, ${concurrency} at a time, on ${places.map((p) => (p.kind === 'udp' ? `udp://${p.host}:${p.port}` : p.kind)).join(', ')}`,
          );
          report = await runEval({
            tasks,
            agents: built.agents,
            trials: options.trials,
            seed: options.seed,
            concurrency,
            simulator: opened.simulator,
            ...(recording === undefined ? {} : { instrument: recording.instrument }),
            robots: opened.robots,
            ...(tools === undefined ? {} : { tools: [...new Set([...tools, 'stop'])] }),
            ...(profile === undefined ? {} : { profile }),
            ...(sensors === undefined ? {} : { sensors }),
            ...(Object.keys(leash).length === 0 ? {} : { leash }),
            guard,
            ...(Object.keys(reality).length === 0 ? {} : { reality }),
            onTrial: ({ agent, score, done, total }) =>
              progress(
                io,
                g,
                `${bar(done, total)} ${done}/${total} ${agent} ${score.task} seed ${score.seed}: ${trialVerdict(score)}`,
              ),
          });
        } catch (error) {
          if (error instanceof EvalError)
            throw new CliError('FAILED', `${error.code}: ${error.message}`);
          throw error;
        } finally {
          await opened?.dispose();
          await built.dispose();
        }
        if (recording !== undefined) {
          const { files, dropped } = recording.recorded;
          progress(
            io,
            g,
            `recorded ${files.length} trial(s) in ${options.record ?? ''}` +
              (dropped > 0 ? ` (${dropped} message(s) dropped: the disk was too slow)` : ''),
          );
        }
        // the table first: a report that cannot be written at the end loses nothing of the run
        emit(io, g, report, () => summaryTable(report));
        if (options.out !== undefined) {
          const out = options.out;
          const files = await writeReports(out, report).catch((error: unknown) => {
            throw new CliError(
              'FAILED',
              `"--out" ${out}: the reports could not be written (${(error as NodeJS.ErrnoException).code ?? String(error)})`,
            );
          });
          progress(io, g, `wrote ${files.json}, ${files.markdown}, ${files.svg}`);
        }
        // a model that never answered is a failed run, named once per agent, not a score
        const unreached = modelFailureError(report);
        if (unreached !== undefined) throw unreached;
        if (options.minSuccess !== undefined) {
          const below = report.scores.agents.filter(
            (a) => a.overall.rate < (options.minSuccess ?? 0),
          );
          if (below.length > 0)
            throw new CliError(
              'FAILED',
              `below --min-success ${options.minSuccess}: ${below.map((a) => `${a.agent} ${a.overall.rate}`).join(', ')}`,
            );
        }
      }),
  );
};
