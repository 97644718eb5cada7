// The steps of `hal eval` once its options are read: the oracle's check of the tasks, the run
// of the agents on the places named, and what is reported after it.
import { EvalError, runEval, summaryTable } from '@hal/eval';
import type { EvalOptions, EvalReport, Task } from '@hal/eval';
import { CliError } from '../cli-error.js';
import { checkTasks, checkTasksText } from '../eval/check-tasks.js';
import type { EvalAgents } from '../eval/eval-agents.js';
import { openPlaces } from '../eval/eval-robots.js';
import type { EvalPlace } from '../eval/eval-robots.js';
import { modelFailureError, trialVerdict } from '../eval/model-failures.js';
import type { recordTrials } from '../eval/record-trials.js';
import { writeReports } from '../eval/write-reports.js';
import { emit, progress } from '../io.js';
import type { CliIO, GlobalOptions } from '../io.js';
import type { EvalCliOptions } from './eval-options.js';

/** Where `hal eval` writes: its streams, and the shared options as parsed. */
export interface EvalOutput {
  io: CliIO;
  g: GlobalOptions;
}

/** The trials' recording, when `--record` is given. */
export type TrialRecording = ReturnType<typeof recordTrials>;

/** A bar of `width` characters, `done` of `total` filled. */
function bar(done: number, total: number, width = 20): string {
  const filled = Math.round((done / total) * width);
  return `[${'#'.repeat(filled)}${'.'.repeat(width - filled)}]`;
}

/**
 * `--check-tasks`: runs the oracle over `--trials` seeds of every task and lists what it cannot
 * solve; FAILED when there is any (a task the oracle cannot solve scores every agent 0).
 */
export async function checkTasksRun(
  { io, g }: EvalOutput,
  tasks: Task[],
  options: EvalCliOptions,
): Promise<void> {
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
}

/** What a run of the agents needs besides the options: the run's settings, already read. */
export interface AgentRun {
  names: string[];
  tasks: Task[];
  places: EvalPlace[];
  built: EvalAgents;
  recording: TrialRecording | undefined;
  /** The settings of `runEval` read from the options (tools, profile, sensors, leash, guard, reality). */
  settings: Pick<EvalOptions, 'tools' | 'profile' | 'sensors' | 'leash' | 'guard' | 'reality'>;
}

/**
 * Opens the places (starting an emulator if one is named), runs every agent's trials on them
 * with progress on stderr, and frees the places and agents whatever happens. An EvalError
 * becomes a FAILED CliError.
 */
export async function runAgents(
  { io, g }: EvalOutput,
  run: AgentRun,
  options: EvalCliOptions,
): Promise<EvalReport> {
  const { names, tasks, places, built, recording } = run;
  let opened: Awaited<ReturnType<typeof openPlaces>> | undefined;
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
    return await runEval({
      tasks,
      agents: built.agents,
      trials: options.trials,
      seed: options.seed,
      concurrency,
      simulator: opened.simulator,
      ...(recording === undefined ? {} : { instrument: recording.instrument }),
      robots: opened.robots,
      ...run.settings,
      onTrial: ({ agent, score, done, total }) =>
        progress(
          io,
          g,
          `${bar(done, total)} ${done}/${total} ${agent} ${score.task} seed ${score.seed}: ${trialVerdict(score)}`,
        ),
    });
  } catch (error) {
    if (error instanceof EvalError) throw new CliError('FAILED', `${error.code}: ${error.message}`);
    throw error;
  } finally {
    await opened?.dispose();
    await built.dispose();
  }
}

/**
 * Reports a finished run: the recordings kept, the table (or the JSON report), the report files
 * of `--out`; then fails the run when a model never answered or an agent is below `--min-success`.
 */
export async function reportRun(
  { io, g }: EvalOutput,
  report: EvalReport,
  recording: TrialRecording | undefined,
  options: EvalCliOptions,
): Promise<void> {
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
    const below = report.scores.agents.filter((a) => a.overall.rate < (options.minSuccess ?? 0));
    if (below.length > 0)
      throw new CliError(
        'FAILED',
        `below --min-success ${options.minSuccess}: ${below.map((a) => `${a.agent} ${a.overall.rate}`).join(', ')}`,
      );
  }
}
