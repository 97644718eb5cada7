// `hal eval`: scores agents on the seeded tasks of @hal/eval in the simulator: the oracle, the
// baselines, the local model, any OpenAI-compatible endpoint. Progress on stderr, the table (or
// with --json the report) on stdout, the reports in --out, and --min-success fails a CI run.
import { STOP_TOOL } from '@hal/tools';
import { Command } from 'commander';
import { toolsChoice } from '../tools-option.js';
import { addGuardOptions, guardSettingsFromOptions } from '../guard-options.js';
import { addLeashOptions, leashFromOptions } from '../leash-options.js';
import { agentNames, buildAgents } from '../eval/eval-agents.js';
import { parsePlaces } from '../eval/eval-robots.js';
import { recordTrials } from '../eval/record-trials.js';
import { progress } from '../io.js';
import { cliLogger } from '../logger.js';
import type { RegisterCommand } from './context.js';
import {
  agentSettingsOf,
  checkEvalPlaces,
  chooseTasks,
  realityOf,
  sensorSet,
} from './eval-inputs.js';
import { addEvalOptions } from './eval-options.js';
import type { EvalCliOptions } from './eval-options.js';
import { checkTasksRun, reportRun, runAgents } from './eval-run.js';
import type { AgentRun, EvalOutput } from './eval-run.js';

export const registerEval: RegisterCommand = (program, { io, global }) => {
  const command = addGuardOptions(addLeashOptions(new Command('eval'))).description(
    'score agents on seeded tasks in the simulator, from its ground truth, and on a robot from its reports (oracle, naive, claimer, straight, parser, nav, nav-camera, the local model, openai:MODEL)',
  );
  program.addCommand(
    addEvalOptions(command).action(async (options: EvalCliOptions) => {
      await evalAction({ io, g: global() }, options);
    }),
  );
};

/**
 * `hal eval`: reads and checks the options (before any model is loaded), then either checks the
 * tasks with the oracle, or builds the agents, runs them and reports the run.
 */
async function evalAction(output: EvalOutput, options: EvalCliOptions): Promise<void> {
  const { io, g } = output;
  const names = agentNames(options.agent);
  const places = parsePlaces(options.on);
  const chosen = toolsChoice(options.tools);
  const profile = chosen !== undefined && 'profile' in chosen ? chosen.profile : undefined;
  const tools = chosen !== undefined && 'names' in chosen ? [...chosen.names] : undefined;
  await checkEvalPlaces(options, places);
  const tasks = await chooseTasks(options);
  if (options.checkTasks === true) {
    await checkTasksRun(output, tasks, options);
    return;
  }
  const sensors = options.sensors === undefined ? undefined : sensorSet(options.sensors);
  const leash = leashFromOptions(options);
  const guard = guardSettingsFromOptions(options) ?? false;
  const reality = realityOf(options);
  const settings: AgentRun['settings'] = {
    ...(tools === undefined ? {} : { tools: [...new Set([...tools, STOP_TOOL])] }),
    ...(profile === undefined ? {} : { profile }),
    ...(sensors === undefined ? {} : { sensors }),
    ...(Object.keys(leash).length === 0 ? {} : { leash }),
    guard,
    ...(Object.keys(reality).length === 0 ? {} : { reality }),
  };
  if (names.includes('local')) progress(io, g, 'loading the local model...');
  const built = await buildAgents(names, agentSettingsOf(options), io.env, cliLogger(io, g.json));
  const recording = options.record === undefined ? undefined : recordTrials(options.record);
  const report = await runAgents(
    output,
    { names, tasks, places, built, recording, settings },
    options,
  );
  await reportRun(output, report, recording, options);
}
