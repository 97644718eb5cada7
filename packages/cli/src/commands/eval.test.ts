// `hal eval` in-process: the scripted agents on the built-in tasks, the reports, the refusals,
// and the real local model (SmolLM2-135M from hal model pull) on one task end to end.
import { mkdir, mkdtemp, readFile, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { EvalReport } from '@hal/eval';
import { captureIO } from '../testing/capture-io.js';
import { runHal } from '../program.js';

const MODEL_MS = 240_000; // a busy shared CPU can be slow; a quiet one takes seconds

let dir = '';
beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-eval-cli-'));
});
afterAll(async () => {
  await rm(dir, { recursive: true, force: true });
});

const oneTask = {
  version: 1,
  tasks: [
    {
      id: 'precision/forward-10cm',
      group: 'precision',
      instruction: 'Drive forward 10 cm.',
      world: { start: { x: 0, y: 0 } },
      budget: { toolCalls: 4, simSeconds: 30 },
      checks: [{ kind: 'displacement', forwardM: 0.1, toleranceM: 0.01 }],
    },
  ],
};

describe('hal eval', () => {
  it('prints the table before the reports, so a report that cannot be written loses no run', async () => {
    const out = join(dir, 'unwritable-reports');
    // eval.json is taken by a folder: the place passes its check with --overwrite, the write fails
    await mkdir(join(out, 'eval.json'), { recursive: true });
    const io = captureIO();
    const args = ['eval', '--agent', 'oracle', '--tasks', 'safety', '--trials', '1'];
    expect(await runHal([...args, '--out', out, '--overwrite'], io)).toBe(1);
    expect(io.stdout()).toContain('oracle');
    expect(io.stderr()).toContain(
      `hal: FAILED: "--out" ${out}: the reports could not be written (EISDIR)`,
    );
    // without --overwrite the folder that holds files is refused before any trial
    const refused = captureIO();
    expect(await runHal([...args, '--out', out], refused)).toBe(2);
    expect(refused.stderr()).toContain(`hal: USAGE: "--out" ${out}: is not empty`);
    expect(refused.stdout()).toBe('');
  });

  it('scores the oracle, the naive baseline and the claimer, and writes the reports', async () => {
    const io = captureIO();
    const out = join(dir, 'reports');
    const args = [
      '--agent',
      'oracle,naive,claimer',
      '--tasks',
      'precision,safety',
      '--trials',
      '2',
    ];
    const code = await runHal(['--json', 'eval', ...args, '--concurrency', '4', '--out', out], io);
    expect(code, io.stderr()).toBe(0);
    const [report] = io.jsonLines() as EvalReport[];
    const rates = report?.scores.agents.map((a) => [a.agent, a.overall.rate]);
    expect(rates?.[0]).toEqual(['oracle', 1]);
    expect(rates?.[2]).toEqual(['claimer', 0]);
    expect(report?.scores.agents[0]?.groups.map((g) => g.group)).toEqual(['precision', 'safety']);
    const written = JSON.parse(await readFile(join(out, 'eval.json'), 'utf8')) as EvalReport;
    expect(written.scores).toEqual(report?.scores);
    expect(await readFile(join(out, 'eval.md'), 'utf8')).toContain(
      '| precision/drive-30cm | 2/2 |',
    );
    expect(await readFile(join(out, 'eval.svg'), 'utf8')).toMatch(/^<svg /);
  });

  it('prints a table by group, with the progress of every trial on stderr', async () => {
    const io = captureIO();
    const code = await runHal(
      ['eval', '--agent', 'oracle', '--tasks', 'robustness', '--trials', '1'],
      io,
    );
    expect(code, io.stderr()).toBe(0);
    expect(io.stdout()).toMatch(/^agent\s+robustness\s+overall/);
    expect(io.stdout()).toMatch(/\noracle\s+100% 8\/8\s+100%/);
    expect(io.stderr()).toMatch(/\[#+\] 8\/8 oracle robustness\/lossy-link seed 1: pass/);
  });

  it('exits 1 when an agent scores below --min-success, naming it', async () => {
    const io = captureIO();
    const code = await runHal(
      ['eval', '--agent', 'naive', '--tasks', 'goals', '--trials', '1', '--min-success', '0.5'],
      io,
    );
    expect(code).toBe(1);
    expect(io.stderr()).toMatch(/below --min-success 0\.5: naive 0/);
  });

  it('runs a task file, and refuses one whose check names what the world lacks, with file and field', async () => {
    const good = join(dir, 'good.json');
    await writeFile(good, JSON.stringify(oneTask));
    const io = captureIO();
    expect(
      await runHal(
        ['--json', 'eval', '--agent', 'oracle', '--tasks-file', good, '--trials', '1'],
        io,
      ),
    ).toBe(0);
    expect((io.jsonLines()[0] as EvalReport).scores.tasks).toEqual(['precision/forward-10cm']);

    const bad = join(dir, 'bad.json');
    const task = {
      ...oneTask.tasks[0],
      checks: [{ kind: 'reach-object', object: 'red-box', withinM: 0.2 }],
    };
    await writeFile(bad, JSON.stringify({ version: 1, tasks: [task] }));
    const refused = captureIO();
    expect(await runHal(['eval', '--tasks-file', bad], refused)).toBe(1);
    expect(refused.stderr()).toContain(
      `TASK_INVALID: ${bad}: "tasks.0.checks.0.object" names "red-box", which the world lacks`,
    );
  });

  it('applies the reality knobs, the sensors and the leash to every trial', async () => {
    const io = captureIO();
    const args = [
      '--agent',
      'oracle',
      '--tasks',
      'precision',
      '--trials',
      '2',
      '--loss',
      '0.3',
      '--latency',
      '200',
    ];
    expect(
      await runHal(['--json', 'eval', ...args, '--sensors', 'none', '--max-distance', '0.1'], io),
      io.stderr(),
    ).toBe(0);
    const trials = (io.jsonLines()[0] as EvalReport).scores.agents[0]?.trials ?? [];
    expect(trials.reduce((s, t) => s + t.lostCalls, 0)).toBeGreaterThan(0);
    // the 0.1 m leash turns the oracle's moves into refusals: drive-30cm is not reached in one call
    expect(trials.find((t) => t.task === 'precision/drive-30cm')?.refusedCalls).toBeGreaterThan(0);
  });

  it('moves the body otherwise than its odometry with the wheel knobs, the same on every run', async () => {
    const file = join(dir, 'wheels.json');
    await writeFile(file, JSON.stringify(oneTask));
    const run = async (knobs: string[]) => {
      const io = captureIO();
      const args = ['--agent', 'naive', '--tasks-file', file, '--trials', '3', ...knobs];
      expect(await runHal(['--json', 'eval', ...args], io), io.stderr()).toBe(0);
      return (io.jsonLines()[0] as EvalReport).scores.agents[0]?.trials ?? [];
    };
    const error = (trials: EvalReport['scores']['agents'][number]['trials']) =>
      trials.reduce((s, t) => s + (t.positionErrorM ?? 0), 0) / trials.length;
    const knobs = ['--wheel-diameter-error', '5', '--wheel-slip', '10', '--odometry-noise', '2'];
    const perfect = await run([]);
    const real = await run(knobs);
    expect(perfect.every((t) => t.success)).toBe(true);
    expect(error(real)).toBeGreaterThan(error(perfect) + 0.002);
    expect(await run(knobs)).toEqual(real);
  });

  it('offers every agent the profile --tools names: naive finds no move_forward among the skills', async () => {
    const run = async (tools: string[]) => {
      const io = captureIO();
      const args = ['--agent', 'naive', '--tasks', 'precision', '--trials', '1', ...tools];
      expect(await runHal(['--json', 'eval', ...args], io), io.stderr()).toBe(0);
      return (io.jsonLines()[0] as EvalReport).scores.agents[0];
    };
    const own = await run([]);
    const primitives = await run(['--tools', 'primitives']);
    const skills = await run(['--tools', 'skills']);
    // naive's own profile is the HAL tools: naming it changes nothing
    expect(own?.overall.rate).toBeGreaterThan(0);
    expect(primitives?.trials).toEqual(own?.trials);
    // its move_forward is no tool of the skills profile (UNKNOWN_TOOL): it never moves
    expect(skills?.overall.rate).toBe(0);
    expect(skills?.trials.length).toBe(own?.trials.length);
    for (const trial of skills?.trials ?? []) {
      expect(trial.toolCalls).toBeGreaterThan(0);
      expect(trial.pathLengthM).toBe(0);
    }
  }, 120_000);

  it('still narrows the HAL tools to the names --tools lists', async () => {
    const io = captureIO();
    const args = ['--agent', 'naive', '--tasks-file', join(dir, 'names.json'), '--trials', '1'];
    await writeFile(join(dir, 'names.json'), JSON.stringify(oneTask));
    expect(await runHal(['--json', 'eval', ...args, '--tools', 'get_pose'], io), io.stderr()).toBe(
      0,
    );
    const [trial] = (io.jsonLines()[0] as EvalReport).scores.agents[0]?.trials ?? [];
    // move_forward is not offered: the drive fails
    expect(trial).toMatchObject({ success: false, pathLengthM: 0 });
  }, 60_000);

  it.each([
    [
      ['--tools', 'skills,move_forward'],
      /"--tools": "skills" is a profile: give a profile alone \(skills, primitives, all\) or tool names, not both/,
    ],
    [['--wheel-slip', '60'], /"--wheel-slip" must be a number in 0\.\.50 %, got "60"/],
    [['--time-scale', '10'], /"--time-scale" needs a robot/],
    [['--on', 'sim', '--key', 'abcd'], /"--key" needs a robot --on udp/],
    [['--sensors', 'sonar'], /unknown sensor "sonar"/],
    [['--loss', '1'], /--loss/],
    [['--agent', 'gpt'], /unknown agent "gpt"/],
    [['--tasks', 'speed'], /unknown group "speed"/],
    [['--trials', '0'], /--trials/],
    [['--min-success', '2'], /--min-success/],
  ])('refuses %j as a usage error', async (args, message) => {
    const io = captureIO();
    expect(await runHal(['eval', ...args], io)).toBe(2);
    expect(io.stderr()).toMatch(message);
  });

  it(
    'scores the local model on one task end to end (what it chose is not asserted)',
    async () => {
      const file = join(dir, 'one.json');
      await writeFile(file, JSON.stringify(oneTask));
      const io = captureIO();
      const args = ['--agent', 'local', '--tasks-file', file, '--trials', '1', '--threads', '1'];
      const code = await runHal(['--json', 'eval', ...args], io);
      expect(code, io.stderr()).toBe(0);
      const report = io.jsonLines()[0] as EvalReport;
      const [trial] = report.scores.agents[0]?.trials ?? [];
      expect(report.scores.agents[0]?.agent).toMatch(/^local:SmolLM2/);
      expect(trial).toMatchObject({
        task: 'precision/forward-10cm',
        seed: 1,
        success: expect.any(Boolean),
      });
      expect(trial?.tokensIn).toBeGreaterThan(0);
      expect(trial?.tokensOut).toBeGreaterThan(0);
      expect(report.timing.agents[0]?.modelMs).toBeGreaterThan(0);
    },
    MODEL_MS,
  );
});
