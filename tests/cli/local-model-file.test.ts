// `--model-file` as a user gives it, in a child process (llama.cpp writes its grammar errors
// straight to the process's stderr, which only a child shows): any GGUF is offered every tool and
// runs (that the default file given by its path runs as the default is modelChoice's unit test,
// packages/cli/src/agent/model-choice.test.ts). The model is the SmolLM2-135M
// file `hal model pull` (or bash scripts/setup.sh) caches; a link to it elsewhere is "another
// GGUF" to hal.
import { mkdtemp, rm, symlink, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { defaultModelFile } from '@hal/agent-local';
import type { EvalReport } from '@hal/eval';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { runHalProcess } from '../helpers/hal-process.js';

const MODEL_MS = 240_000; // a busy shared CPU can be slow; a quiet one takes seconds

let dir = '';
let other = '';
beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-model-file-'));
  other = join(dir, 'my-model.gguf');
  await symlink(defaultModelFile(), other);
});
afterAll(async () => {
  await rm(dir, { recursive: true, force: true });
});

type Line = { type: string; [key: string]: unknown };
const lines = (stdout: string) =>
  stdout
    .split('\n')
    .filter((l) => l.startsWith('{'))
    .map((l) => JSON.parse(l) as Line);
const fast = ['--sim', '--time-scale', '20', '--threads', '1'];

/** No grammar text (llama.cpp's rules, "name ::= ...") and no grammar failure on stderr. */
function expectNoGrammar(stderr: string): void {
  expect(stderr).not.toContain('::=');
  expect(stderr).not.toContain('parse grammar');
}

describe('--model-file', () => {
  it(
    'hal agent runs another GGUF with every tool offered',
    async () => {
      const run = await runHalProcess(
        [
          '--json',
          'agent',
          ...fast,
          '--max-steps',
          '1',
          '--model-file',
          other,
          'drive forward 10 cm',
        ],
        MODEL_MS,
      );
      expect(run.code, run.stderr).toBe(0);
      expectNoGrammar(run.stderr);
      const outcome = lines(run.stdout).at(-1);
      expect(outcome).toMatchObject({ type: 'outcome', steps: 1 });
    },
    MODEL_MS,
  );

  it(
    'hal eval --agent local runs another GGUF on a task and scores it, its grammar built',
    async () => {
      const tasks = join(dir, 'one.json');
      await writeFile(
        tasks,
        JSON.stringify({
          version: 1,
          tasks: [
            {
              id: 'precision/forward-10cm',
              group: 'precision',
              instruction: 'Drive forward 10 cm.',
              world: { start: { x: 0, y: 0 } },
              budget: { toolCalls: 2, simSeconds: 30 },
              checks: [{ kind: 'displacement', forwardM: 0.1, toleranceM: 0.01 }],
            },
          ],
        }),
      );
      const args = ['--agent', 'local', '--model-file', other, '--tasks-file', tasks];
      const run = await runHalProcess(
        ['--json', 'eval', ...args, '--trials', '1', '--threads', '1', '--max-steps', '1'],
        MODEL_MS,
      );
      expect(run.code, run.stderr).toBe(0);
      expectNoGrammar(run.stderr);
      const report = JSON.parse(run.stdout) as EvalReport;
      const [agent] = report.scores.agents;
      expect(agent?.agent).toBe('local:my-model');
      expect(agent?.modelFailure).toBeNull();
      expect(agent?.trials[0]?.tokensOut).toBeGreaterThan(0);
    },
    MODEL_MS,
  );
});
