// The options of `hal eval`, in the order its help lists them.
import { Option } from 'commander';
import type { Command } from 'commander';
import { TASK_GROUPS } from '@hal/eval';
import type { GuardCliOptions } from '../guard-options.js';
import type { LeashCliOptions } from '../leash-options.js';
import { distanceArg, hexKeyArg, integerArg, numberArg, positiveArg, urlArg } from '../values.js';

/** The options of `hal eval`, as commander parses them. */
export interface EvalCliOptions extends LeashCliOptions, GuardCliOptions {
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

/** Adds every option of `hal eval` to `command` (the leash and guard options are added apart). */
export function addEvalOptions(command: Command): Command {
  addTrialOptions(command);
  addOutputOptions(command);
  addModelOptions(command);
  addRunOptions(command);
  return addRealityOptions(command);
}

/** Which agents, on which tasks, how many trials from which seed, how many at once, and where. */
function addTrialOptions(command: Command): Command {
  return command
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
    );
}

/** Where the reports and recordings go, and the success rate below which the run fails. */
function addOutputOptions(command: Command): Command {
  return command
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
    );
}

/** The tools the agents are offered, and the settings of the model agents. */
function addModelOptions(command: Command): Command {
  return command
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
    );
}

/** The robot's sensors in every task, and the oracle's check of the tasks instead of a run. */
function addRunOptions(command: Command): Command {
  return command
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
    );
}

/** The simulator's reality gap: latency, loss, sensor noise, wheel errors and slip. */
function addRealityOptions(command: Command): Command {
  return command
    .addOption(
      new Option('--latency <ms>', 'reality: simulated latency added to every call, ms').argParser(
        numberArg('--latency', { min: 0, max: 10_000 }, 'ms'),
      ),
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
    );
}
