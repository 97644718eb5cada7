// `hal agent "<goal>"`: a model drives one robot through the HAL tools until it says it is done
// or a cap is reached. The local GGUF model by default (no key, no server), or an
// OpenAI-compatible endpoint with --base-url. Tool calls and results are printed as they happen
// and the model's reply streams as it is generated; Ctrl-C stops the generation and the robot.
import { Command, Option } from 'commander';
import { runAgent } from '@hal/agent';
import type { AgentOutcome, ChatProvider, RunAgentOptions } from '@hal/agent';
import {
  createLocalChatProvider,
  LOCAL_SYSTEM_PROMPT,
  LocalModelError,
  SKILL_EXAMPLES,
  SKILLS_SYSTEM_PROMPT,
} from '@hal/agent-local';
import type { LocalChatProvider } from '@hal/agent-local';
import {
  addGuardOptions,
  guardFromOptions,
  guardReport,
  guardText,
  recordGuard,
} from '../guard-options.js';
import { seeingFrom } from '../seeing.js';
import type { GuardCliOptions } from '../guard-options.js';
import { addFoxgloveOptions, foxglovePlan, startLiveView } from '../foxglove/live-view.js';
import type { FoxgloveCliOptions, LiveView } from '../foxglove/live-view.js';
import { addLeashOptions, leashFromOptions } from '../leash-options.js';
import type { LeashCliOptions } from '../leash-options.js';
import { AGENT_EVENT, recordHal, TOPICS } from '@hal/recorder';
import { integerArg, positiveArg, urlArg } from '../values.js';
import { createToolExecutor, halTools, STOP_TOOL, toOpenAITools } from '@hal/tools';
import type { Logger, Pose } from '@hal/types';
import { DEFAULT_SMALL_MODEL_STEPS, DEFAULT_STEPS, modelChoice } from '../agent/model-choice.js';
import { offeredTools } from '../mcp/offered-tools.js';
import { openWorldSimulator, readLookWorld } from '../look/look-world.js';
import type { LookWorld } from '../look/look-world.js';
import type { ModelChoice, ModelCliOptions } from '../agent/model-choice.js';
import { eventPrinter } from '../agent/print.js';
import { CliError } from '../cli-error.js';
import { emit, progress } from '../io.js';
import { cliLogger } from '../logger.js';
import { addOverwriteOption, checkOutputPlace, openRecordingFile } from '../output-place.js';
import { poseText } from '../pose-text.js';
import { addTargetOptions, namesTarget, resolveTarget } from '../target.js';
import type { Target, TargetCliOptions } from '../target.js';
import { withTarget } from '../target-hal.js';
import type { OpenedHal } from '../target-hal.js';
import type { CliIO } from '../io.js';
import type { RegisterCommand } from './context.js';

interface AgentCliOptions
  extends TargetCliOptions, ModelCliOptions, LeashCliOptions, GuardCliOptions, FoxgloveCliOptions {
  maxTime?: number;
  world?: string;
  record?: string;
  overwrite?: boolean;
  timeout?: number;
}

/** Loads the local model, its errors as the CLI reports them. */
async function loadLocal(
  choice: Extract<ModelChoice, { kind: 'local' }>,
  logger: Logger,
): Promise<LocalChatProvider> {
  try {
    return await createLocalChatProvider({
      ...(choice.modelFile === undefined ? {} : { modelFile: choice.modelFile }),
      ...(choice.offerTools === undefined ? {} : { offerTools: choice.offerTools }),
      // the default model offered the skills: shown worked runs, and made to act before answering
      ...(choice.profile !== 'primitives' && choice.modelFile === undefined
        ? { examples: SKILL_EXAMPLES, callFirst: true }
        : {}),
      ...(choice.threads === undefined ? {} : { threads: choice.threads }),
      ...(choice.contextSize === undefined ? {} : { contextSize: choice.contextSize }),
      logger,
    });
  } catch (error) {
    throw asCliError(error);
  }
}

function asCliError(error: unknown): unknown {
  return error instanceof LocalModelError
    ? new CliError('FAILED', `${error.code}: ${error.message}`)
    : error;
}

/** Runs `use` on the simulator started in `world`, and closes it. */
async function inWorld<T>(
  world: LookWorld,
  target: Extract<Target, { kind: 'sim' }>,
  io: CliIO,
  use: (opened: OpenedHal) => Promise<T>,
): Promise<T> {
  const opened = await openWorldSimulator(world, io, {
    speed: target.speed,
    ...(target.calibration === undefined ? {} : { calibration: target.calibration }),
  });
  try {
    return await use(opened);
  } finally {
    await opened.close();
  }
}

export const registerAgent: RegisterCommand = (program, { io, global }) => {
  const command = new Command('agent')
    .description(
      'let a model drive a robot toward a goal in words: a local GGUF model by default, or an OpenAI-compatible endpoint (--base-url)',
    )
    .argument('<goal...>', 'what the robot should do, e.g. "drive forward 10 cm"')
    .addOption(
      new Option(
        '--model-file <path>',
        'a GGUF model to run in this process (default: SmolLM2-135M, fetched by hal model pull)',
      ),
    )
    .addOption(
      new Option(
        '--base-url <url>',
        'an OpenAI-compatible endpoint instead, up to /v1 (key from $OPENAI_API_KEY)',
      ).argParser(urlArg('--base-url', ['http:', 'https:'])),
    )
    .addOption(new Option('--model <name>', "the endpoint's model (default $OPENAI_MODEL)"))
    .addOption(
      new Option(
        '--tools <profile>',
        'what the model is offered: skills, primitives (the HAL tools), all, or HAL tool names, comma-separated (default: skills for the default model, else primitives)',
      ),
    )
    .addOption(
      new Option(
        '--max-steps <n>',
        `most model requests (default ${DEFAULT_SMALL_MODEL_STEPS} with the default model, else ${DEFAULT_STEPS})`,
      ).argParser(integerArg('--max-steps', 1, 200)),
    )
    .addOption(
      new Option(
        '--world <file>',
        "with the simulator: start it in this world (a task file's world: map, start, coloured objects; see docs/eval.md)",
      ),
    )
    .addOption(
      new Option('--max-time <s>', 'most time for the whole run, seconds (default 300)').argParser(
        positiveArg('--max-time'),
      ),
    )
    .addOption(
      new Option('--timeout <ms>', 'time one tool call may take (motions get more)').argParser(
        integerArg('--timeout', 100, 600_000),
      ),
    )
    .addOption(
      new Option(
        '--threads <n>',
        'CPU threads of the local model (default: one fewer than the cores, 1 to 4)',
      ).argParser(integerArg('--threads', 1, 256)),
    )
    .addOption(
      new Option(
        '--record <file>',
        "record the run into this MCAP file: the robot's calls and pose, and the agent's events",
      ),
    )
    .addOption(
      new Option(
        '--context <tokens>',
        'context window of the local model (default 2048)',
      ).argParser(integerArg('--context', 256, 131_072)),
    );
  addOverwriteOption(command, 'the --record file');
  addLeashOptions(command);
  addGuardOptions(command);
  addFoxgloveOptions(command);
  addTargetOptions(command).action(async (words: string[], options: AgentCliOptions) => {
    const json = global().json;
    const goal = words.join(' ').trim();
    if (goal === '') throw new CliError('USAGE', 'the goal must not be empty');
    const choice = modelChoice(options, io.env);
    // the embedded simulator when no robot is named, as in hal mcp
    const target = resolveTarget(
      namesTarget(options) ? options : { ...options, sim: true },
      io.env,
    );
    if (options.world !== undefined && target.kind !== 'sim')
      throw new CliError('USAGE', '--world starts the simulator in a world: it needs --sim');
    // a world file that cannot be used is refused before the model loads
    const world = options.world === undefined ? undefined : await readLookWorld(options.world);
    const leash = leashFromOptions(options);
    const foxglove = foxglovePlan(options, io.env);
    const logger = cliLogger(io, json);

    // the --record file is checked before the model loads (which may take minutes), opened after
    const recordPlace =
      options.record === undefined
        ? undefined
        : { option: '--record', path: options.record, overwrite: options.overwrite === true };
    if (recordPlace !== undefined) await checkOutputPlace({ ...recordPlace, kind: 'file' });
    // the model first: a bad model file is an error before any robot is touched
    let local: LocalChatProvider | undefined;
    if (choice.kind === 'local') {
      progress(io, global(), 'loading the model...');
      local = await loadLocal(choice, logger);
      progress(
        io,
        global(),
        `model ${local.modelFile} (${local.gpu === false ? 'CPU' : local.gpu})`,
      );
    }
    // a file that cannot be written is refused before any robot is touched
    const recorder =
      recordPlace === undefined
        ? undefined
        : await openRecordingFile(recordPlace, { logger }).catch(async (error: unknown) => {
            await local?.dispose().catch(() => undefined);
            throw error;
          });
    recorder?.channel(TOPICS.agent, AGENT_EVENT);
    const sampling = new AbortController();
    let live: LiveView | undefined;
    try {
      const connect =
        options.connectTimeout === undefined ? {} : { connectTimeoutMs: options.connectTimeout };
      const open =
        world !== undefined && target.kind === 'sim'
          ? <T>(use: (opened: OpenedHal) => Promise<T>) => inWorld(world, target, io, use)
          : <T>(use: (opened: OpenedHal) => Promise<T>) =>
              withTarget(target, io, { ...connect, json, role: 'control' }, use);
      const { outcome, pose, guard } = await open(async ({ hal: robot, deviceId }) => {
        // the guard sits between the leash (the executor) and the robot
        const { hal: guarded, guard } = guardFromOptions(robot, options, io, json, target);
        recordGuard(guard, recorder);
        // scan answers from the range sensors and the camera, as the robot can know
        const { hal: opened, perception } = seeingFrom(guarded, robot, recorder, target);
        const recorded = recorder
          ? recordHal(opened, recorder, { signal: sampling.signal, deviceId })
          : opened;
        // a viewer watches the run and may drive under the same leash
        live = await startLiveView(
          recorded,
          foxglove,
          { io, global },
          { deviceId, leash, ...(perception === undefined ? {} : { perception }) },
        );
        const hal = live.hal;
        const timeout = options.timeout === undefined ? {} : { timeoutMs: options.timeout };
        const executor =
          choice.profile === 'primitives'
            ? createToolExecutor(hal, {
                tools:
                  choice.kind === 'endpoint' && choice.tools !== undefined
                    ? // the loop stops the robot with `stop` at the end of a run: always keep it
                      halTools(hal, { include: [...new Set([...choice.tools, STOP_TOOL])] })
                    : halTools(hal),
                leash,
                ...timeout,
              })
            : // the skills drive through the same executor: the leash and the guard hold inside them
              offeredTools(hal, { profile: choice.profile, leash, ...timeout });
        if (local !== undefined)
          await local.prepare(toOpenAITools(executor.tools)).catch((e) => {
            throw asCliError(e);
          });
        const model: Pick<RunAgentOptions, 'provider' | 'endpoint' | 'systemPrompt'> =
          local !== undefined
            ? {
                provider: local satisfies ChatProvider,
                ...(choice.kind === 'local' && choice.modelFile === undefined
                  ? {
                      systemPrompt:
                        choice.profile === 'primitives'
                          ? LOCAL_SYSTEM_PROMPT
                          : SKILLS_SYSTEM_PROMPT,
                    }
                  : {}),
              }
            : { endpoint: (choice as Extract<ModelChoice, { kind: 'endpoint' }>).endpoint };
        const print = eventPrinter((text) => io.out(text));
        const run: AgentOutcome = await runAgent({
          goal,
          executor,
          ...model,
          caps: {
            maxSteps:
              options.maxSteps ??
              (choice.kind === 'local' && choice.modelFile === undefined
                ? DEFAULT_SMALL_MODEL_STEPS
                : DEFAULT_STEPS),
            ...(options.maxTime === undefined ? {} : { maxMs: options.maxTime * 1000 }),
          },
          signal: io.signal,
          onEvent: (event) => {
            recorder?.write(TOPICS.agent, event);
            if (json) io.out(`${JSON.stringify(event)}\n`);
            else print(event);
          },
          logger,
        });
        let pose: Pose | undefined;
        try {
          pose = await hal.locomotion.getPose();
        } catch {
          pose = undefined;
        }
        return { outcome: run, pose, guard: guardReport(guard) };
      });
      await live?.close();
      sampling.abort();
      const recorded = await recorder?.close();
      const summary = {
        type: 'outcome',
        reason: outcome.reason,
        steps: outcome.steps,
        elapsedMs: outcome.elapsedMs,
        text: outcome.text,
        ...(pose === undefined ? {} : { pose }),
        guard,
        ...(recorded === undefined ? {} : { recording: { file: options.record, ...recorded } }),
        ...(outcome.error === undefined
          ? {}
          : { error: { code: outcome.error.code, message: outcome.error.message } }),
      };
      emit(io, global(), summary, () =>
        [
          ...(pose === undefined ? [] : [`pose ${poseText(pose)}`]),
          ...(outcome.text === '' ? [] : [`model: ${outcome.text}`]),
          ...[guardText(guard)].filter((line) => line !== undefined),
        ].join('\n'),
      );
      if (outcome.reason === 'error' && outcome.error !== undefined) {
        const cause = outcome.error.cause;
        throw new CliError(
          'FAILED',
          cause instanceof LocalModelError
            ? `${cause.code}: ${cause.message}`
            : `${outcome.error.code}: ${outcome.error.message}`,
        );
      }
    } finally {
      await live?.close().catch(() => undefined);
      sampling.abort();
      await recorder?.close().catch(() => undefined);
      await local?.dispose().catch(() => undefined);
    }
  });
  program.addCommand(command);
};
